// SPDX-License-Identifier: GPL-3.0-or-later
// A dab on the 2CylinderEngine (no UVs of its own) painted into a texture over the automatic UV
// layout: the texels it paints are those whose surface points the brush disc covers on screen,
// on a large flat face where vertex colours (few vertices far apart) smear the dab across it.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "tests/render/gl_test.h"

#include "core/depth/depth_layers.h"
#include "core/document/document.h"
#include "core/io/mesh_io.h"
#include "core/model/camera.h"
#include "core/paint/targets/paint_target.h"
#include "render/gl_depth_capturer.h"

namespace uv_footprint_gltest {

namespace fs = std::filesystem;
using core::kNone;

constexpr int kWidth = 640, kHeight = 480, kRadius = 12;

fs::path enginePath() {
    return fs::path(LAYERPAINT_ASSIMP_MODELS) /
           "glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb";
}

/** A triangle's plane: unit normal and offset (n · p = d). */
struct Plane {
    glm::dvec3 n{0.0};
    double d = 0.0;
    double area = 0.0;
};

Plane trianglePlane(const core::Mesh& mesh, std::uint32_t t) {
    const glm::dvec3 a(mesh.positions[mesh.indices[3 * t]]);
    const glm::dvec3 b(mesh.positions[mesh.indices[3 * t + 1]]);
    const glm::dvec3 c(mesh.positions[mesh.indices[3 * t + 2]]);
    const glm::dvec3 g = glm::cross(b - a, c - a);
    const double len = glm::length(g);
    Plane p;
    if (len > 0.0) {
        p.n = g / len;
        p.d = glm::dot(p.n, a);
        p.area = 0.5 * len;
    }
    return p;
}

class UvFootprintGlTest : public render_test::GlCaptureTest {
protected:
    void SetUp() override {
        ASSERT_TRUE(s_context);
        if (!fs::exists(enginePath()))
            GTEST_SKIP() << "assimp test models not installed: " << enginePath();
        ASSERT_NO_FATAL_FAILURE(GlCaptureTest::SetUp());
        if (!s_engine) {
            core::Result<core::Mesh> mesh = core::loadMesh(enginePath().string());
            ASSERT_TRUE(mesh.ok()) << mesh.error();
            ASSERT_FALSE(mesh->hasUvs());
            s_engine = std::make_shared<core::Mesh>(std::move(mesh).value());
        }
    }
    std::unique_ptr<core::Document> open(float yaw, float pitch) {
        auto doc = std::make_unique<core::Document>();
        doc->setMesh(*s_engine, "engine");
        core::Camera camera;
        camera.frame(s_engine->bounds());
        camera.orbit(yaw, pitch);
        doc->camera() = camera;
        m_capturer.setMesh(doc->mesh());
        m_view = camera.view(kWidth, kHeight);
        const core::Status status = doc->buildDepthLayers(m_capturer, m_view);
        EXPECT_TRUE(status) << status.error();
        doc->setLayerAware(false);
        return doc;
    }

    /**
     * A pixel whose front triangle is large and faces the camera, with every pixel within
     * kRadius + 6 on the same plane in front: the face of the largest such triangle.
     */
    std::optional<glm::ivec2> flatFace(const core::Document& doc, Plane& face) const {
        const core::DepthStack& stack = doc.depthLayers()->stack;
        const core::Mesh& mesh = doc.mesh();
        const auto front = [&](int x, int y) {
            if (x < 0 || y < 0 || x >= stack.width || y >= stack.height)
                return kNone;
            return stack.fragment(std::size_t(y) * std::size_t(stack.width) + std::size_t(x), 1);
        };
        const double side = double(mesh.bounds().longestSide());
        const glm::vec3 eye = glm::vec3(glm::inverse(m_view.view)[3]);
        std::optional<glm::ivec2> best;
        const int reach = kRadius + 6;
        for (int y = reach; y < stack.height - reach; y += 4)
            for (int x = reach; x < stack.width - reach; x += 4) {
                const std::uint32_t f = front(x, y);
                if (f == kNone)
                    continue;
                const Plane p = trianglePlane(mesh, stack.triangle[f]);
                if (p.area <= face.area)
                    continue;
                const glm::dvec3 at(m_view.unproject(glm::vec2(x, y) + 0.5f, stack.depth[f]));
                if (glm::dot(p.n, glm::normalize(glm::dvec3(eye) - at)) < 0.7)
                    continue; // seen too steeply
                bool flat = true;
                for (int dy = -reach; flat && dy <= reach; ++dy)
                    for (int dx = -reach; flat && dx <= reach; ++dx) {
                        const std::uint32_t g = front(x + dx, y + dy);
                        if (g == kNone) {
                            flat = false;
                            break;
                        }
                        const Plane q = trianglePlane(mesh, stack.triangle[g]);
                        flat = glm::dot(p.n, q.n) > 0.999 && std::fabs(q.d - p.d) < 1e-3 * side;
                    }
                if (flat) {
                    face = p;
                    best = glm::ivec2(x, y);
                }
            }
        return best;
    }

    void paintDab(core::Document& doc, glm::vec2 centre) {
        core::Brush& brush = doc.brush();
        brush.color = {1.0f, 0.0f, 0.0f, 1.0f};
        brush.radius = float(kRadius);
        brush.hardness = 1.0f;
        brush.opacity = 1.0f;
        brush.pressureRadius = false;
        core::PaintChanges changes;
        ASSERT_TRUE(doc.beginStroke({centre, 1.0f}, changes));
        doc.endStroke();
    }

    core::View m_view;
    inline static std::shared_ptr<core::Mesh> s_engine;
};

TEST_F(UvFootprintGlTest, DabOnTheCylinderHeadPaintsTheTexelsUnderTheBrushDisc) {
    // Views round the engine until one shows a large flat face (the cylinder heads' sides).
    std::unique_ptr<core::Document> doc;
    Plane face;
    std::optional<glm::ivec2> at;
    for (const glm::vec2 orbit : {glm::vec2(0, 0), glm::vec2(90, 0), glm::vec2(30, 20),
                                  glm::vec2(0, 80), glm::vec2(-90, 0), glm::vec2(180, 0)}) {
        doc = open(orbit.x, orbit.y);
        at = flatFace(*doc, face);
        if (at) {
            std::printf("[ view ] orbit %.0f, %.0f\n", orbit.x, orbit.y);
            break;
        }
    }
    ASSERT_TRUE(at.has_value()) << "no large flat face in the view";
    const glm::vec2 centre = glm::vec2(*at) + 0.5f;
    const double side = double(doc->mesh().bounds().longestSide());

    // Vertex colours first, where a dab on a large face smears: the same dab, then one on the
    // nearest corner of the face's triangle, where the colour of that vertex is spread over every
    // triangle around it.
    core::PaintTargetOptions options;
    options.kind = core::PaintTargetKind::VertexColors;
    ASSERT_TRUE(doc->setPaintTarget(options));
    {
        const core::Mesh& mesh = doc->paintTarget()->mesh();
        const auto* target = dynamic_cast<const core::VertexColorTarget*>(doc->paintTarget());
        ASSERT_NE(target, nullptr);
        const auto vertexDab = [&](glm::vec2 where, const char* what) {
            const std::vector<glm::vec4> before = target->colors();
            paintDab(*doc, where);
            std::size_t painted = 0;
            double reach = 0.0; // how far from the centre triangles with a painted corner go
            for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
                bool touched = false;
                for (int k = 0; k < 3; ++k) {
                    const std::uint32_t v = mesh.indices[3 * t + std::size_t(k)];
                    touched = touched || target->colors()[v] != before[v];
                }
                if (!touched)
                    continue;
                for (int k = 0; k < 3; ++k) {
                    const glm::vec3 s = m_view.project(mesh.positions[mesh.indices[3 * t + k]]);
                    reach = std::max(reach, double(glm::length(glm::vec2(s) - where)));
                }
            }
            for (std::size_t v = 0; v < mesh.vertexCount(); ++v)
                painted += target->colors()[v] != before[v];
            std::printf("[ vertex colours ] a %d px dab %s: %zu vertices painted, their "
                        "triangles (coloured by interpolation) reaching %.0f px from its centre\n",
                        kRadius, what, painted, reach);
        };
        vertexDab(centre, "in the middle of the face");
        const std::size_t pixel = std::size_t(at->y) * std::size_t(kWidth) + std::size_t(at->x);
        const core::DepthStack& stack = doc->depthLayers()->stack;
        const std::uint32_t t = stack.triangle[stack.fragment(pixel, 1)];
        glm::vec2 corner(0.0f);
        float nearest = 1e30f;
        for (int k = 0; k < 3; ++k) {
            const glm::vec2 s(m_view.project(mesh.positions[mesh.indices[3 * t + k]]));
            if (glm::length(s - centre) < nearest) {
                nearest = glm::length(s - centre);
                corner = s;
            }
        }
        if (corner.x > kRadius && corner.y > kRadius && corner.x < kWidth - kRadius &&
            corner.y < kHeight - kRadius)
            vertexDab(corner, "on a corner of the face's triangle");
    }
    std::printf("[ face ] the dab at (%d, %d), on a face whose triangle has %.2g of the model's "
                "side squared\n",
                at->x, at->y, face.area / (side * side));

    // A texture over the automatic layout.
    options.kind = core::PaintTargetKind::Texture;
    ASSERT_TRUE(doc->setPaintTarget(options));
    const auto* target = dynamic_cast<const core::TextureTarget*>(doc->paintTarget());
    ASSERT_NE(target, nullptr);
    const std::vector<std::uint8_t> before = target->page(0).rgba;
    paintDab(*doc, centre);
    const core::Mesh& mesh = target->mesh();
    ASSERT_TRUE(mesh.hasUvs());
    const core::Image& page = target->page(0);
    const int w = page.width, h = page.height;
    const auto red = [&](int x, int y) {
        const std::size_t i = 4 * (std::size_t(y) * std::size_t(w) + std::size_t(x));
        return page.rgba[i] > 200 && page.rgba[i + 1] < 60 &&
               (page.rgba[i] != before[i] || page.rgba[i + 1] != before[i + 1] ||
                page.rgba[i + 2] != before[i + 2]);
    };

    // Every texel whose centre a triangle covers: where it projects and whether it lies on the
    // face (only texels of the face are in front inside the disc).
    std::size_t painted = 0, paintedOutside = 0, inner = 0, innerPainted = 0;
    double worst = 0.0;
    std::vector<std::uint8_t> covered(std::size_t(w) * std::size_t(h), 0u);
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        glm::dvec2 uv[3];
        glm::dvec3 pos[3];
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t v = mesh.indices[3 * t + std::size_t(k)];
            uv[k] = glm::dvec2(mesh.uvs[v]) * glm::dvec2(w, h);
            pos[k] = glm::dvec3(mesh.positions[v]);
        }
        const double area =
            (uv[1].x - uv[0].x) * (uv[2].y - uv[0].y) - (uv[1].y - uv[0].y) * (uv[2].x - uv[0].x);
        if (area == 0.0)
            continue;
        const glm::dvec2 lo = glm::min(uv[0], glm::min(uv[1], uv[2]));
        const glm::dvec2 hi = glm::max(uv[0], glm::max(uv[1], uv[2]));
        const Plane p = trianglePlane(mesh, std::uint32_t(t));
        const bool onFace = glm::dot(p.n, face.n) > 0.999 && std::fabs(p.d - face.d) < 1e-3 * side;
        for (int y = std::max(0, int(std::floor(lo.y))); y <= std::min(h - 1, int(hi.y)); ++y)
            for (int x = std::max(0, int(std::floor(lo.x))); x <= std::min(w - 1, int(hi.x)); ++x) {
                const glm::dvec2 c(x + 0.5, y + 0.5);
                const double b0 =
                    ((uv[1].x - c.x) * (uv[2].y - c.y) - (uv[1].y - c.y) * (uv[2].x - c.x)) / area;
                const double b1 =
                    ((uv[2].x - c.x) * (uv[0].y - c.y) - (uv[2].y - c.y) * (uv[0].x - c.x)) / area;
                const double b2 = 1.0 - b0 - b1;
                if (b0 < 0.0 || b1 < 0.0 || b2 < 0.0)
                    continue;
                const std::size_t i = std::size_t(y) * std::size_t(w) + std::size_t(x);
                if (covered[i])
                    continue;
                covered[i] = 1;
                const glm::dvec3 point = b0 * pos[0] + b1 * pos[1] + b2 * pos[2];
                const glm::vec3 s = m_view.project(glm::vec3(point));
                const double distance = double(glm::length(glm::vec2(s) - centre));
                if (red(x, y)) {
                    ++painted;
                    worst = std::max(worst, distance);
                    paintedOutside += distance > kRadius + 2.0;
                }
                if (onFace && distance < kRadius - 1.5) {
                    ++inner;
                    innerPainted += red(x, y);
                }
            }
    }
    std::printf("[ texture ] %zu texels painted, the farthest projecting %.2f px from the dab's "
                "centre (radius %d); %zu of the %zu face texels projecting well inside the disc "
                "painted; %zu painted beyond 2 px outside it\n",
                painted, worst, kRadius, innerPainted, inner, paintedOutside);
    ASSERT_GT(inner, 100u) << "the face has too few texels under the dab to test";
    EXPECT_EQ(paintedOutside, 0u);
    EXPECT_GE(double(innerPainted), 0.98 * double(inner));
    EXPECT_GT(painted, inner / 2);
}

} // namespace uv_footprint_gltest
