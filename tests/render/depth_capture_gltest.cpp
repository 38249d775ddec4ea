// SPDX-License-Identifier: GPL-3.0-or-later
// Layer capture on a headless EGL context (llvmpipe on CI): analytic scenes, the layer property,
// a CPU rasterizer as reference, and node buffer growth.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <span>
#include <vector>

#include <gtest/gtest.h>

#include "tests/render/gl_test.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/mat4x4.hpp>

#include "core/depth/cpu_capture.h"
#include "core/depth/depth_stack.h"
#include "core/model/builtin_models.h"
#include "core/model/camera.h"
#include "render/depth_capture.h"
#include "render/gl_context.h"
#include "render/offscreen_target.h"

namespace layer_capture_gltest {

class DepthCaptureGlTest : public render_test::GlTest {
protected:
    void SetUp() override {
        ASSERT_TRUE(s_context);
        const core::Status status = m_capture.initialize();
        ASSERT_TRUE(status) << status.error();
    }
    void TearDown() override { m_capture.release(); }

    core::DepthStack capture(const core::View& view, bool cullBackFaces = true,
                             render::DepthCapture::Timings* timings = nullptr,
                             std::span<const std::uint32_t> shownBackFaces = {}) {
        render::DepthCapture::Options options;
        options.cullBackFaces = cullBackFaces;
        options.shownBackFaces = shownBackFaces;
        auto result = m_capture.capture(view, options, timings);
        EXPECT_TRUE(result) << result.error();
        return result ? std::move(result).value() : core::DepthStack{};
    }

    render::DepthCapture m_capture;
};

/** A parallelogram: corners o, o + u, o + u + v, o + v; front-facing where u × v faces the eye. */
struct Quad {
    glm::vec3 o, u, v;
};

/** Quad q becomes triangles 2q = (o, o+u, o+u+v) and 2q + 1 = (o, o+u+v, o+v). */
core::Mesh quadMesh(const std::vector<Quad>& quads) {
    core::Mesh mesh;
    for (const Quad& q : quads) {
        const auto base = std::uint32_t(mesh.positions.size());
        mesh.positions.insert(mesh.positions.end(), {q.o, q.o + q.u, q.o + q.u + q.v, q.o + q.v});
        mesh.indices.insert(mesh.indices.end(),
                            {base, base + 1, base + 2, base, base + 2, base + 3});
    }
    mesh.normals.assign(mesh.positions.size(), glm::vec3(0.0f, 0.0f, 1.0f));
    mesh.materials.push_back({});
    mesh.triangleMaterial.assign(mesh.triangleCount(), 0);
    return mesh;
}

/** The world ray through a pixel centre (x right, y down), in double precision. */
struct Ray {
    glm::dvec3 origin, direction;
};
Ray pixelRay(const core::View& view, int x, int y) {
    const glm::dmat4 inverse = glm::inverse(glm::dmat4(view.proj) * glm::dmat4(view.view));
    const double nx = (x + 0.5) / view.width * 2.0 - 1.0, ny = 1.0 - (y + 0.5) / view.height * 2.0;
    glm::dvec4 a = inverse * glm::dvec4(nx, ny, -1.0, 1.0),
               b = inverse * glm::dvec4(nx, ny, 1.0, 1.0);
    const glm::dvec3 pa = glm::dvec3(a) / a.w, pb = glm::dvec3(b) / b.w;
    return {pa, pb - pa};
}

double viewDepth(const core::View& view, const glm::dvec3& world) {
    return -(glm::dmat4(view.view) * glm::dvec4(world, 1.0)).z;
}

struct Expected {
    double depth;
    std::uint32_t triangle;
    bool eitherHalf; // on the quad's diagonal: triangle or triangle + 1
};

/**
 * Ray-casts the quads at a pixel centre. Returns false if the pixel is too close to a quad's
 * boundary for coverage to be decided (rasterization snaps vertices to sub-pixel positions).
 */
bool castQuads(const std::vector<Quad>& quads, const std::vector<bool>& front,
               const core::View& view, int x, int y, bool cull, std::vector<Expected>& hits) {
    hits.clear();
    const Ray ray = pixelRay(view, x, y);
    constexpr double kMargin = 2e-3; // in quad parameters: a few hundredths of a pixel here
    for (std::size_t q = 0; q < quads.size(); ++q) {
        const glm::dvec3 o(quads[q].o), u(quads[q].u), v(quads[q].v);
        // o + s u + t v = origin + l direction
        const glm::dmat3 m(u, v, -ray.direction);
        const glm::dvec3 stl = glm::inverse(m) * (ray.origin - o);
        // l runs from the near plane (0) to the far plane (1).
        const double s = stl.x, t = stl.y, l = stl.z;
        const bool inside = s > kMargin && s < 1 - kMargin && t > kMargin && t < 1 - kMargin &&
                            l > kMargin && l < 1 - kMargin;
        const bool outside = s < -kMargin || s > 1 + kMargin || t < -kMargin || t > 1 + kMargin ||
                             l < -kMargin || l > 1 + kMargin;
        if (!inside && !outside)
            return false;
        if (outside || (cull && !front[q]))
            continue;
        const double depth = viewDepth(view, o + s * u + t * v);
        hits.push_back({depth, std::uint32_t(2 * q + (t > s ? 1 : 0)), std::abs(s - t) < kMargin});
    }
    std::sort(hits.begin(), hits.end(),
              [](const Expected& a, const Expected& b) { return a.depth < b.depth; });
    return true;
}

/** Three frontal quads at different depths, a back-facing one, and a sloped one in front. */
std::vector<Quad> stackedQuads() {
    return {
        {{-1.0f, -0.5f, 1.0f}, {1.5f, 0.0f, 0.0f}, {0.0f, 1.5f, 0.0f}},  // depth 4
        {{-0.5f, -1.0f, 0.0f}, {1.5f, 0.0f, 0.0f}, {0.0f, 1.5f, 0.0f}},  // depth 5
        {{-1.2f, -1.2f, -1.0f}, {2.4f, 0.0f, 0.0f}, {0.0f, 2.4f, 0.0f}}, // depth 6
        {{-0.3f, -0.3f, 0.5f}, {0.0f, 1.1f, 0.0f}, {0.6f, 0.0f, 0.0f}},  // back face, depth 4.5
        {{-0.9f, 0.2f, 1.5f}, {0.8f, 0.0f, 1.0f}, {0.0f, 0.7f, 0.0f}},   // sloped, depth 2.5..3.5
    };
}

core::View quadView(bool orthographic) {
    core::View view;
    view.width = 64;
    view.height = 48;
    view.view = glm::lookAt(glm::vec3(0.1f, 0.15f, 5.0f), glm::vec3(0.1f, 0.15f, 0.0f),
                            glm::vec3(0.0f, 1.0f, 0.0f));
    view.proj = orthographic ? glm::ortho(-1.6f, 1.6f, -1.2f, 1.2f, 0.5f, 20.0f)
                             : glm::perspective(glm::radians(40.0f), 64.0f / 48.0f, 1.0f, 20.0f);
    return view;
}

/** Compares a capture of the quads with ray casting; returns pixels by their layer count. */
std::map<std::size_t, int> expectAnalytic(const core::DepthStack& stack, const core::View& view,
                                          const std::vector<Quad>& quads,
                                          const std::vector<bool>& front, bool cull) {
    std::map<std::size_t, int> pixelsByLayers;
    EXPECT_EQ(stack.width, view.width);
    EXPECT_EQ(stack.height, view.height);
    if (stack.offsets.size() != stack.pixelCount() + 1 || stack.width != view.width ||
        stack.height != view.height) {
        ADD_FAILURE() << "malformed stack";
        return pixelsByLayers;
    }
    std::vector<Expected> hits;
    int decided = 0, wrong = 0;
    for (int y = 0; y < view.height; ++y)
        for (int x = 0; x < view.width; ++x) {
            if (!castQuads(quads, front, view, x, y, cull, hits))
                continue;
            ++decided;
            const std::size_t pixel = std::size_t(y) * view.width + x;
            ++pixelsByLayers[hits.size()];
            if (stack.layerCount(pixel) != hits.size()) {
                EXPECT_EQ(stack.layerCount(pixel), hits.size()) << "pixel " << x << "," << y;
                if (++wrong > 10)
                    return pixelsByLayers;
                continue;
            }
            for (std::uint32_t k = 0; k < hits.size(); ++k) {
                const std::uint32_t f = stack.fragment(pixel, k + 1);
                EXPECT_NEAR(stack.depth[f], hits[k].depth, 1e-4 * hits[k].depth)
                    << "pixel " << x << "," << y << " layer " << k + 1;
                const std::uint32_t t = stack.triangle[f];
                if (hits[k].eitherHalf)
                    EXPECT_TRUE(t / 2 == hits[k].triangle / 2) << "pixel " << x << "," << y;
                else
                    EXPECT_EQ(t, hits[k].triangle) << "pixel " << x << "," << y;
            }
        }
    // Nearly every pixel is decidable.
    EXPECT_GT(decided, view.width * view.height * 9 / 10);
    return pixelsByLayers;
}

void expectStackedQuads(const core::DepthStack& stack, const core::View& view, bool cull) {
    auto pixelsByLayers =
        expectAnalytic(stack, view, stackedQuads(), {true, true, true, false, true}, cull);
    // The scene has pixels with 1 to 4 layers (5 with the back face).
    for (std::size_t layers = 1; layers <= 4; ++layers)
        EXPECT_GT(pixelsByLayers[layers], 10) << layers << " layers";
}

TEST_F(DepthCaptureGlTest, StackedQuadsPerspective) {
    m_capture.setMesh(quadMesh(stackedQuads()));
    const core::View view = quadView(false);
    expectStackedQuads(capture(view), view, true);
}

TEST_F(DepthCaptureGlTest, StackedQuadsOrthographic) {
    m_capture.setMesh(quadMesh(stackedQuads()));
    const core::View view = quadView(true);
    expectStackedQuads(capture(view), view, true);
}

TEST_F(DepthCaptureGlTest, TwoSidedCapturesBackFaces) {
    m_capture.setMesh(quadMesh(stackedQuads()));
    for (bool orthographic : {false, true}) {
        const core::View view = quadView(orthographic);
        expectStackedQuads(capture(view, false), view, false);
    }
}

TEST_F(DepthCaptureGlTest, ShownBackFacesAreCapturedWhileTheOthersAreCulled) {
    m_capture.setMesh(quadMesh(stackedQuads()));
    const std::vector<std::uint32_t> backQuad = {6, 7}; // quad 3, the back-facing one
    for (bool orthographic : {false, true}) {
        const core::View view = quadView(orthographic);
        expectAnalytic(capture(view, true, nullptr, backQuad), view, stackedQuads(),
                       {true, true, true, true, true}, true);
        // The element buffer of shown faces is dropped when the list empties.
        expectStackedQuads(capture(view), view, true);
        // Shown back faces change nothing two-sided.
        expectStackedQuads(capture(view, false, nullptr, backQuad), view, false);
    }
}

TEST_F(DepthCaptureGlTest, ClippedTrianglesKeepIdsAndDepthPrecision) {
    // A floor from behind the eye to beyond the far plane: both clip planes cut its triangles.
    // With near/far at 1:10000 the z-buffer resolves little in the distance; view depth must not
    // care.
    const std::vector<Quad> quads = {
        {{-50.0f, -1.0f, 10.0f}, {100.0f, 0.0f, 0.0f}, {0.0f, 0.0f, -1000.0f}},
        {{-20.0f, -30.0f, -300.0f}, {40.0f, 0.0f, 0.0f}, {0.0f, 60.0f, 0.0f}}, // a far wall
    };
    m_capture.setMesh(quadMesh(quads));
    core::View view;
    view.width = 96;
    view.height = 64;
    view.view = glm::lookAt(glm::vec3(0.0f), glm::vec3(0.0f, 0.0f, -1.0f), glm::vec3(0, 1, 0));
    view.proj = glm::perspective(glm::radians(50.0f), 1.5f, 0.05f, 500.0f);
    auto pixelsByLayers = expectAnalytic(capture(view), view, quads, {true, true}, true);
    EXPECT_GT(pixelsByLayers[1], view.width * view.height / 3);
    EXPECT_GT(pixelsByLayers[2], 20); // the wall's foot, behind the floor
}

TEST_F(DepthCaptureGlTest, TopRowIsFirst) {
    // One quad covering only the upper half of the view.
    m_capture.setMesh(quadMesh({{{-2.0f, 0.0f, 0.0f}, {4.0f, 0.0f, 0.0f}, {0.0f, 2.0f, 0.0f}}}));
    core::View view;
    view.width = 8;
    view.height = 8;
    view.view = glm::lookAt(glm::vec3(0, 0, 2), glm::vec3(0.0f), glm::vec3(0, 1, 0));
    view.proj = glm::ortho(-1.0f, 1.0f, -1.0f, 1.0f, 0.1f, 10.0f);
    const core::DepthStack stack = capture(view);
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x)
            EXPECT_EQ(stack.layerCount(std::size_t(y) * 8 + x), y < 4 ? 1u : 0u) << x << "," << y;
}

core::View trefoilView(const core::Mesh& mesh, int width, int height, bool orthographic = false) {
    core::Camera camera;
    camera.frame(mesh.bounds());
    camera.orbit(20.0f, 15.0f);
    camera.orthographic = orthographic;
    return camera.view(width, height);
}

/** Checks the CSR layout, the front-to-back order and the per-layer counts. */
void expectWellFormed(const core::DepthStack& stack, std::size_t triangleCount,
                      const render::DepthCapture::Timings& timings) {
    ASSERT_EQ(stack.offsets.size(), stack.pixelCount() + 1);
    ASSERT_EQ(stack.offsets.front(), 0u);
    ASSERT_EQ(stack.offsets.back(), stack.fragmentCount());
    ASSERT_EQ(stack.triangle.size(), stack.depth.size());
    EXPECT_EQ(timings.fragments, stack.fragmentCount());
    std::vector<std::uint32_t> perLayer;
    for (std::size_t p = 0; p < stack.pixelCount(); ++p) {
        ASSERT_LE(stack.offsets[p], stack.offsets[p + 1]);
        const std::uint32_t n = stack.layerCount(p);
        if (perLayer.size() < n)
            perLayer.resize(n, 0);
        for (std::uint32_t k = 1; k <= n; ++k) {
            ++perLayer[k - 1];
            const std::uint32_t f = stack.fragment(p, k);
            ASSERT_TRUE(std::isfinite(stack.depth[f]) && stack.depth[f] > 0.0f);
            ASSERT_LT(stack.triangle[f], triangleCount);
            if (k > 1) {
                // Front to back; equal depths by triangle id.
                const std::uint32_t g = f - 1;
                ASSERT_TRUE(
                    stack.depth[g] < stack.depth[f] ||
                    (stack.depth[g] == stack.depth[f] && stack.triangle[g] < stack.triangle[f]));
            }
        }
    }
    EXPECT_EQ(perLayer, timings.fragmentsPerLayer);
    EXPECT_EQ(stack.fragmentsPerLayer(), timings.fragmentsPerLayer);
    // The layer property: a fragment on layer j implies one on every layer above it.
    for (std::size_t k = 1; k < perLayer.size(); ++k)
        EXPECT_LE(perLayer[k], perLayer[k - 1]);
}

TEST_F(DepthCaptureGlTest, TrefoilLayersAreOrderedAndComplete) {
    const core::Mesh mesh = core::makeTrefoil();
    m_capture.setMesh(mesh);
    render::DepthCapture::Timings timings;
    const core::DepthStack stack = capture(trefoilView(mesh, 320, 240), true, &timings);
    expectWellFormed(stack, mesh.triangleCount(), timings);
    // The knot's crossings put a second front face behind the first.
    ASSERT_GE(timings.fragmentsPerLayer.size(), 2u);
    EXPECT_GT(timings.fragmentsPerLayer[1], timings.fragmentsPerLayer[0] / 20);

    // Two-sided, every tube wall behind the first counts as well.
    render::DepthCapture::Timings twoSided;
    const core::DepthStack all = capture(trefoilView(mesh, 320, 240), false, &twoSided);
    expectWellFormed(all, mesh.triangleCount(), twoSided);
    EXPECT_GE(twoSided.fragmentsPerLayer.size(), 4u);
}

/**
 * The CPU reference: every fragment at each pixel centre, exact view depth from the triangle's
 * plane. A fragment is "sure" when the centre is clearly inside; "possible" when it lies within
 * a small distance of an edge (where the GL's snapping and tie rules decide) or the triangle is
 * too thin to tell its facing.
 */
struct CpuFragment {
    double depth;
    std::uint32_t triangle;
    bool sure;
};
std::vector<std::vector<CpuFragment>> cpuFragments(const core::Mesh& mesh, const core::View& view,
                                                   bool cull) {
    std::vector<std::vector<CpuFragment>> pixels(std::size_t(view.width) * view.height);
    const glm::dmat4 viewMatrix(view.view), clipMatrix = glm::dmat4(view.proj) * viewMatrix;
    const glm::dmat4 inverseProj = glm::inverse(glm::dmat4(view.proj));
    constexpr double kEdge = 0.02; // pixels
    std::vector<glm::dvec3> window(mesh.vertexCount()), eye(mesh.vertexCount());
    for (std::size_t i = 0; i < mesh.vertexCount(); ++i) {
        const glm::dvec4 p(glm::dvec3(mesh.positions[i]), 1.0);
        const glm::dvec4 clip = clipMatrix * p;
        // GL window coordinates: y up.
        window[i] = {(clip.x / clip.w + 1.0) * 0.5 * view.width,
                     (clip.y / clip.w + 1.0) * 0.5 * view.height, clip.w};
        eye[i] = glm::dvec3(viewMatrix * p);
    }
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        const std::uint32_t i0 = mesh.indices[3 * t], i1 = mesh.indices[3 * t + 1],
                            i2 = mesh.indices[3 * t + 2];
        const glm::dvec3 a = window[i0], b = window[i1], c = window[i2];
        const double area = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
        const bool thin = std::abs(area) < 1e-3;
        if (cull && area < 0.0 && !thin)
            continue;
        const double sign = area < 0.0 ? -1.0 : 1.0;
        const glm::dvec3 normal = glm::cross(eye[i1] - eye[i0], eye[i2] - eye[i0]);
        const int x0 = std::max(0, int(std::floor(std::min({a.x, b.x, c.x}) - 1)));
        const int x1 = std::min(view.width - 1, int(std::ceil(std::max({a.x, b.x, c.x}))));
        const int y0 = std::max(0, int(std::floor(std::min({a.y, b.y, c.y}) - 1)));
        const int y1 = std::min(view.height - 1, int(std::ceil(std::max({a.y, b.y, c.y}))));
        for (int gy = y0; gy <= y1; ++gy)
            for (int x = x0; x <= x1; ++x) {
                const double px = x + 0.5, py = gy + 0.5;
                double minDistance = 1e30;
                for (const auto& [p, q] : {std::pair{a, b}, std::pair{b, c}, std::pair{c, a}}) {
                    const double length = std::hypot(q.x - p.x, q.y - p.y);
                    const double e = ((q.x - p.x) * (py - p.y) - (px - p.x) * (q.y - p.y));
                    minDistance = std::min(minDistance, length > 0 ? sign * e / length : 0.0);
                }
                if (minDistance < -kEdge)
                    continue;
                // Depth where the pixel's view ray meets the triangle's plane.
                const double nx = px / view.width * 2.0 - 1.0, ny = py / view.height * 2.0 - 1.0;
                glm::dvec4 ra = inverseProj * glm::dvec4(nx, ny, -1.0, 1.0);
                glm::dvec4 rb = inverseProj * glm::dvec4(nx, ny, 1.0, 1.0);
                const glm::dvec3 pa = glm::dvec3(ra) / ra.w, pb = glm::dvec3(rb) / rb.w;
                const double denominator = glm::dot(normal, pb - pa);
                const double l =
                    denominator != 0.0 ? glm::dot(normal, eye[i0] - pa) / denominator : 0.0;
                const double depth = -(pa + l * (pb - pa)).z;
                const int y = view.height - 1 - gy;
                pixels[std::size_t(y) * view.width + x].push_back(
                    {depth, std::uint32_t(t), minDistance > kEdge && !thin});
            }
    }
    return pixels;
}

void expectMatchesCpu(const core::DepthStack& stack, const core::Mesh& mesh, const core::View& view,
                      bool cull) {
    const auto reference = cpuFragments(mesh, view, cull);
    std::size_t checked = 0, badPixels = 0, possibleTaken = 0;
    double worstRelative = 0.0;
    for (std::size_t p = 0; p < stack.pixelCount(); ++p) {
        const auto& expected = reference[p];
        bool bad = false;
        std::vector<std::uint32_t> seen;
        for (std::uint32_t f = stack.offsets[p]; f < stack.offsets[p + 1]; ++f) {
            const auto match = std::find_if(expected.begin(), expected.end(), [&](const auto& e) {
                return e.triangle == stack.triangle[f];
            });
            if (match == expected.end()) {
                bad = true;
                continue;
            }
            possibleTaken += !match->sure;
            seen.push_back(match->triangle);
            const double relative = std::abs(stack.depth[f] - match->depth) / match->depth;
            worstRelative = std::max(worstRelative, relative);
            bad |= relative > 1e-4;
        }
        for (const CpuFragment& e : expected)
            if (e.sure && std::find(seen.begin(), seen.end(), e.triangle) == seen.end())
                bad = true;
        checked += stack.layerCount(p);
        badPixels += bad;
    }
    EXPECT_EQ(badPixels, 0u);
    EXPECT_GT(checked, stack.pixelCount() / 8);
    std::printf("  %zu fragments checked, %zu on edges, worst relative depth error %.2g\n", checked,
                possibleTaken, worstRelative);
}

TEST_F(DepthCaptureGlTest, TrefoilMatchesCpuRasterizer) {
    const core::Mesh mesh = core::makeTrefoil();
    m_capture.setMesh(mesh);
    for (bool orthographic : {false, true}) {
        const core::View view = trefoilView(mesh, 320, 240, orthographic);
        expectMatchesCpu(capture(view), mesh, view, true);
    }
}

TEST_F(DepthCaptureGlTest, HexRingTwoSidedMatchesCpuRasterizer) {
    const core::Mesh mesh = core::makeHexRing();
    m_capture.setMesh(mesh);
    core::Camera camera;
    camera.frame(mesh.bounds());
    camera.orbit(-30.0f, 40.0f);
    const core::View view = camera.view(200, 150);
    expectMatchesCpu(capture(view, false), mesh, view, false);
}

/**
 * Against core::captureDepthLayersCpu, which rasterizes with GL's rules: the same fragments per
 * pixel and the same depths, but for a few pixels where llvmpipe's fixed-point edge arithmetic and
 * the reference's disagree about a centre on a shared edge.
 */
void expectMatchesCoreCapture(const core::DepthStack& gpu, const core::Mesh& mesh,
                              const core::View& view, bool cull) {
    core::CpuCaptureOptions options;
    options.cullBackFaces = cull;
    const core::DepthStack cpu = core::captureDepthLayersCpu(mesh, view, options);
    ASSERT_EQ(cpu.pixelCount(), gpu.pixelCount());
    std::size_t covered = 0, countDiffers = 0, fragmentDiffers = 0;
    double worstRelative = 0.0;
    for (std::size_t p = 0; p < gpu.pixelCount(); ++p) {
        covered += cpu.layerCount(p) > 0;
        if (gpu.layerCount(p) != cpu.layerCount(p)) {
            ++countDiffers;
            continue;
        }
        for (std::uint32_t k = 1; k <= gpu.layerCount(p); ++k) {
            const std::uint32_t g = gpu.fragment(p, k), c = cpu.fragment(p, k);
            const double relative = std::abs(double(gpu.depth[g]) - cpu.depth[c]) / cpu.depth[c];
            worstRelative = std::max(worstRelative, relative);
            fragmentDiffers += relative > 1e-4 || gpu.triangle[g] != cpu.triangle[c];
        }
    }
    EXPECT_GT(covered, gpu.pixelCount() / 8);
    EXPECT_LE(countDiffers, covered / 200) << "of " << covered << " covered pixels";
    EXPECT_LE(fragmentDiffers, gpu.fragmentCount() / 200);
    std::printf("  vs core capture: %zu of %zu pixels differ in count, %zu fragments differ, "
                "worst relative depth error %.2g\n",
                countDiffers, covered, fragmentDiffers, worstRelative);
}

TEST_F(DepthCaptureGlTest, TrefoilMatchesCoreCpuCapture) {
    const core::Mesh mesh = core::makeTrefoil();
    m_capture.setMesh(mesh);
    for (bool cull : {true, false}) {
        const core::View view = trefoilView(mesh, 320, 240);
        expectMatchesCoreCapture(capture(view, cull), mesh, view, cull);
    }
}

TEST_F(DepthCaptureGlTest, ClosedTubeTwoSidedDoublesEveryPixel) {
    // A ray through a closed surface leaves it as often as it enters.
    const core::Mesh mesh = core::makeTrefoil(60, 24);
    m_capture.setMesh(mesh);
    const core::View view = trefoilView(mesh, 160, 120);
    const core::DepthStack culled = capture(view, true), twoSided = capture(view, false);
    std::size_t covered = 0, doubled = 0;
    for (std::size_t p = 0; p < culled.pixelCount(); ++p) {
        covered += culled.layerCount(p) > 0;
        doubled += culled.layerCount(p) > 0 && twoSided.layerCount(p) == 2 * culled.layerCount(p);
    }
    EXPECT_GT(covered, culled.pixelCount() / 8);
    EXPECT_GE(doubled, covered * 99 / 100);
}

TEST_F(DepthCaptureGlTest, GrowsTinyNodeBufferAndMatchesNormalCapture) {
    const core::Mesh mesh = core::makeTrefoil();
    m_capture.setMesh(mesh);
    const core::View view = trefoilView(mesh, 320, 240);
    render::DepthCapture::Timings normalTimings;
    const core::DepthStack normal = capture(view, true, &normalTimings);

    m_capture.setNodeCapacity(16);
    render::DepthCapture::Timings grownTimings;
    const int before = m_capture.totalRecaptures();
    const core::DepthStack grown = capture(view, true, &grownTimings);
    EXPECT_EQ(grownTimings.recaptures, 1);
    EXPECT_EQ(m_capture.totalRecaptures(), before + 1);
    EXPECT_GE(m_capture.nodeCapacity(), grown.fragmentCount());
    EXPECT_EQ(grown.offsets, normal.offsets);
    EXPECT_EQ(grown.depth, normal.depth);
    EXPECT_EQ(grown.triangle, normal.triangle);
    EXPECT_EQ(grownTimings.fragmentsPerLayer, normalTimings.fragmentsPerLayer);

    // The grown capacity is kept: the same view needs no second draw.
    render::DepthCapture::Timings again;
    const core::DepthStack third = capture(view, true, &again);
    EXPECT_EQ(again.recaptures, 0);
    EXPECT_EQ(third.depth, normal.depth);
}

TEST_F(DepthCaptureGlTest, NodeRangesGiveTheSameStack) {
    const core::Mesh mesh = core::makeTrefoil();
    m_capture.setMesh(mesh);
    // 320 pixels are five 64-pixel columns: with 8 ranges, three get no fragment at all.
    const core::View view = trefoilView(mesh, 320, 240);
    m_capture.setNodeRanges(1);
    render::DepthCapture::Timings oneTimings;
    const core::DepthStack one = capture(view, true, &oneTimings);
    for (const std::size_t ranges : {2u, 4u, 8u}) {
        SCOPED_TRACE(ranges);
        m_capture.setNodeRanges(ranges);
        EXPECT_EQ(m_capture.nodeRanges(), ranges);
        m_capture.setNodeCapacity(16); // every range overflows; the second draw fits
        render::DepthCapture::Timings timings;
        const core::DepthStack split = capture(view, true, &timings);
        EXPECT_EQ(timings.recaptures, 1);
        EXPECT_EQ(split.offsets, one.offsets);
        EXPECT_EQ(split.depth, one.depth);
        EXPECT_EQ(split.triangle, one.triangle);
        EXPECT_EQ(timings.fragmentsPerLayer, oneTimings.fragmentsPerLayer);
        // The split the last draw needed is kept: the same view draws once.
        render::DepthCapture::Timings again;
        EXPECT_EQ(capture(view, true, &again).triangle, one.triangle);
        EXPECT_EQ(again.recaptures, 0);
    }
    m_capture.setNodeRanges(3);
    EXPECT_EQ(m_capture.nodeRanges(), 2u);
}

TEST_F(DepthCaptureGlTest, ChangingSizeKeepsListsClean) {
    const core::Mesh mesh = core::makeTrefoil(120, 30);
    m_capture.setMesh(mesh);
    const core::View large = trefoilView(mesh, 300, 200), small = trefoilView(mesh, 130, 90);
    const core::DepthStack first = capture(small);
    capture(large);
    const core::DepthStack second = capture(small);
    EXPECT_EQ(first.offsets, second.offsets);
    EXPECT_EQ(first.depth, second.depth);
    EXPECT_EQ(first.triangle, second.triangle);
}

TEST_F(DepthCaptureGlTest, TooManyFragmentsFailOrAreAllKept) {
    // 5 layers of 1536² pixels, 11.8 million fragments: more than llvmpipe's 128 MiB storage
    // blocks hold. Either every fragment arrives or the capture says why; none are dropped.
    std::vector<Quad> quads;
    for (int i = 0; i < 5; ++i)
        quads.push_back({{-2.0f, -2.0f, -float(i)}, {4.0f, 0.0f, 0.0f}, {0.0f, 4.0f, 0.0f}});
    m_capture.setMesh(quadMesh(quads));
    core::View view;
    view.width = view.height = 1536;
    view.view = glm::lookAt(glm::vec3(0, 0, 1), glm::vec3(0.0f), glm::vec3(0, 1, 0));
    view.proj = glm::ortho(-1.0f, 1.0f, -1.0f, 1.0f, 0.1f, 10.0f);
    auto result = m_capture.capture(view, {});
    if (result) {
        EXPECT_EQ(result->fragmentCount(), result->pixelCount() * 5);
    } else {
        EXPECT_NE(result.error().find("fragments"), std::string::npos) << result.error();
        std::printf("  %s\n", result.error().c_str());
    }
    // A smaller view still works afterwards.
    view.width = view.height = 64;
    auto small = m_capture.capture(view, {});
    ASSERT_TRUE(small) << small.error();
    EXPECT_EQ(small->fragmentCount(), small->pixelCount() * 5);
}

TEST_F(DepthCaptureGlTest, WithoutMeshTheStackIsEmpty) {
    const core::DepthStack stack = capture(quadView(false));
    EXPECT_EQ(stack.width, 64);
    EXPECT_EQ(stack.height, 48);
    EXPECT_EQ(stack.offsets.size(), stack.pixelCount() + 1);
    EXPECT_EQ(stack.fragmentCount(), 0u);
}

TEST_F(DepthCaptureGlTest, FailuresAreReported) {
    m_capture.setMesh(quadMesh(stackedQuads()));
    core::View huge = quadView(false);
    huge.width = 1 << 20;
    auto result = m_capture.capture(huge, {});
    ASSERT_FALSE(result);
    EXPECT_NE(result.error().find("not supported"), std::string::npos) << result.error();

    render::DepthCapture uninitialized;
    auto notReady = uninitialized.capture(quadView(false), {});
    ASSERT_FALSE(notReady);
    EXPECT_NE(notReady.error().find("not initialized"), std::string::npos);
}

} // namespace layer_capture_gltest
