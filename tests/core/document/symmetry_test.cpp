// SPDX-License-Identifier: GPL-3.0-or-later
// Symmetric strokes in the Document, on CPU-captured layers of a generated symmetric model: bumpy
// bodies that are exact copies of each other (mirrored or turned), each painted on its own strip
// of one texture with the same UV layout, so texel (x, y) of one body is the copy of texel
// (x + strip, y) of the next. A stroke seen from an oblique view must paint a texel iff it paints
// its copy, including where the copy faces away from the camera or hides behind another body.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/matrix.hpp>
#include <gtest/gtest.h>

#include "core/document/document.h"
#include "core/document/script_symmetry.h"
#include "core/paint/brush/symmetry.h"

namespace symmetry_test {

constexpr int kWidth = 320, kHeight = 240, kTexture = 512;

/** A bumpy sphere about the origin, radius about 0.4, as a latitude-longitude grid. */
void addBody(core::Mesh& mesh, const glm::mat4& transform, int strip, int strips) {
    constexpr int kRings = 24, kSegments = 32;
    const auto base = std::uint32_t(mesh.positions.size());
    const bool reflects = glm::determinant(glm::mat3(transform)) < 0.0f;
    for (int i = 0; i <= kRings; ++i) {
        for (int j = 0; j <= kSegments; ++j) {
            const float theta = 3.14159265f * float(i) / kRings;
            const float phi = 6.2831853f * float(j) / kSegments;
            const float r = 0.4f * (1.0f + 0.12f * std::sin(3.0f * theta) * std::sin(4.0f * phi));
            const glm::vec3 p(r * std::sin(theta) * std::cos(phi), r * std::cos(theta),
                              r * std::sin(theta) * std::sin(phi));
            mesh.positions.push_back(
                glm::vec3(transform * glm::vec4(p + glm::vec3(-0.7f, 0, 0), 1)));
            // The strip's UVs, inset a little so the seam padding stays inside it.
            const float u = (0.02f + 0.96f * float(j) / kSegments + float(strip)) / float(strips);
            mesh.uvs.push_back({u, 0.02f + 0.96f * float(i) / kRings});
        }
    }
    for (int i = 0; i < kRings; ++i) {
        for (int j = 0; j < kSegments; ++j) {
            const std::uint32_t a = base + std::uint32_t(i * (kSegments + 1) + j);
            const std::uint32_t b = a + 1, c = a + kSegments + 1, d = c + 1;
            const std::uint32_t tri[2][3] = {{a, b, c}, {b, d, c}};
            for (const auto& t : tri) {
                mesh.indices.push_back(t[0]);
                mesh.indices.push_back(reflects ? t[2] : t[1]);
                mesh.indices.push_back(reflects ? t[1] : t[2]);
            }
        }
    }
}

core::Mesh symmetricScene(const std::vector<glm::mat4>& transforms) {
    core::Mesh mesh;
    for (std::size_t k = 0; k < transforms.size(); ++k)
        addBody(mesh, transforms[k], int(k), int(transforms.size()));
    mesh.normals.assign(mesh.positions.size(), glm::vec3(0, 1, 0));
    mesh.triangleMaterial.assign(mesh.indices.size() / 3, 0);
    mesh.materials.resize(1);
    return mesh;
}

struct Scene {
    core::Document doc;
    core::CpuDepthCapturer capturer;
    core::View view;
    core::PaintChanges changes;

    Scene(core::Mesh mesh, float yaw, float pitch) {
        doc.setMesh(std::move(mesh), "symmetric bodies");
        core::PaintTargetOptions options;
        options.resolution = kTexture;
        options.kind = core::PaintTargetKind::Texture;
        EXPECT_TRUE(doc.setPaintTarget(options).ok());
        core::Camera camera;
        camera.frame(doc.mesh().bounds(), float(kWidth) / float(kHeight), 0.1f);
        camera.yawDegrees = yaw;
        camera.pitchDegrees = pitch;
        view = camera.view(kWidth, kHeight);
        capturer.setMesh(doc.mesh());
        EXPECT_TRUE(doc.buildDepthLayers(capturer, view).ok());
        doc.brush().radius = 10.0f;
        doc.brush().hardness = 1.0f;
        doc.brush().color = {0.0f, 0.0f, 1.0f, 1.0f};
    }
    const core::TextureTarget& target() const {
        return dynamic_cast<const core::TextureTarget&>(*doc.currentPaintTarget());
    }
    /** Whether texel (x, y) took the brush's blue. */
    bool painted(int x, int y) const {
        const core::Image& p = target().page(0);
        const std::uint8_t* t =
            &p.rgba[4 * (std::size_t(y) * std::size_t(p.width) + std::size_t(x))];
        return t[2] > 128 && t[0] < 128;
    }
    void stroke(glm::vec2 from, glm::vec2 to) {
        ASSERT_TRUE(doc.beginStroke({from, 1.0f}, changes).ok());
        for (int i = 1; i <= 20; ++i)
            doc.moveStroke({from + (to - from) * (float(i) / 20.0f), 1.0f}, changes);
        doc.endStroke(changes);
    }
    /** Painted texels per strip, and those whose copy in every other strip agrees. */
    void compare(int strips, std::vector<int>& perStrip, int& agreeing, int& paintedAny) const {
        const int w = kTexture / strips;
        perStrip.assign(std::size_t(strips), 0);
        agreeing = paintedAny = 0;
        for (int y = 0; y < kTexture; ++y) {
            for (int x = 0; x < w; ++x) {
                int count = 0;
                for (int k = 0; k < strips; ++k) {
                    if (painted(x + k * w, y)) {
                        ++count;
                        ++perStrip[std::size_t(k)];
                    }
                }
                if (count > 0) {
                    ++paintedAny;
                    if (count == strips)
                        ++agreeing;
                }
            }
        }
    }
};

const glm::mat4 kMirrorX = glm::scale(glm::mat4(1.0f), glm::vec3(-1.0f, 1.0f, 1.0f));

TEST(Symmetry, MirrorPaintsTheFarSideOfTheMirroredBody) {
    // Seen from the left and above: the right body's outer side faces away from the camera.
    Scene s(symmetricScene({glm::mat4(1.0f), kMirrorX}), -60.0f, 20.0f);
    s.doc.brush().symmetry.mirrorX = true;
    // A stroke over the left body's outer, camera-facing side.
    const glm::vec3 c = s.view.project({-1.0f, 0.05f, 0.1f});
    s.stroke({c.x - 20.0f, c.y - 6.0f}, {c.x + 20.0f, c.y + 6.0f});
    std::vector<int> perStrip;
    int agreeing = 0, paintedAny = 0;
    s.compare(2, perStrip, agreeing, paintedAny);
    const double ratio = double(agreeing) / double(std::max(paintedAny, 1));
    std::printf("mirror x: %d texels painted on the left body, %d on the right, %d of %d agree "
                "(%.2f %%)\n",
                perStrip[0], perStrip[1], agreeing, paintedAny, 100.0 * ratio);
    EXPECT_GT(perStrip[0], 500);
    EXPECT_GE(ratio, 0.98);
    // The copy's surface (outward normal +X there) faces away from the camera: it is in none of
    // this view's depth layers.
    const glm::vec3 eye = glm::vec3(glm::inverse(s.view.view)[3]);
    EXPECT_GT(glm::dot(glm::vec3(1, 0, 0), glm::vec3(1.0f, 0.05f, 0.1f) - eye), 0.0f);
}

TEST(Symmetry, MirrorReachesASurfaceHiddenBehindTheOtherBody) {
    // Seen from the right, nearly along X: the left body is hidden behind the right one, and the
    // stroke on the right body's facing side mirrors onto the left body's hidden side.
    Scene s(symmetricScene({glm::mat4(1.0f), kMirrorX}), 75.0f, 10.0f);
    s.doc.brush().symmetry.mirrorX = true;
    const glm::vec3 c = s.view.project({1.1f, 0.0f, 0.0f});
    s.stroke({c.x - 8.0f, c.y - 15.0f}, {c.x + 8.0f, c.y + 15.0f});
    std::vector<int> perStrip;
    int agreeing = 0, paintedAny = 0;
    s.compare(2, perStrip, agreeing, paintedAny);
    const double ratio = double(agreeing) / double(std::max(paintedAny, 1));
    std::printf("hidden: %d texels on the left body, %d on the right, %.2f %% agree\n", perStrip[0],
                perStrip[1], 100.0 * ratio);
    EXPECT_GT(perStrip[1], 300);
    EXPECT_GE(ratio, 0.98);
    // The copy's point (the left body's inner side) is behind the right body: not depth layer 1.
    const glm::vec3 q = s.view.project({-0.3f, 0.0f, 0.0f});
    const core::DepthStack& stack = s.doc.depthLayers()->stack;
    const std::size_t pixel = std::size_t(q.y) * std::size_t(kWidth) + std::size_t(q.x);
    ASSERT_GE(stack.layerCount(pixel), 2u);
    EXPECT_LT(stack.depth[stack.offsets[pixel]], q.z - 0.2f);
}

TEST(Symmetry, RadialFourPaintsFourCopies) {
    std::vector<glm::mat4> turns;
    for (int k = 0; k < 4; ++k)
        turns.push_back(glm::rotate(glm::mat4(1.0f), 6.2831853f * float(k) / 4.0f, {0, 1, 0}));
    Scene s(symmetricScene(turns), -30.0f, 35.0f);
    s.doc.brush().symmetry.radial = 4;
    s.doc.brush().symmetry.axis = 1;
    const glm::vec3 c = s.view.project({-0.7f, 0.4f, 0.0f});
    s.stroke({c.x - 12.0f, c.y}, {c.x + 12.0f, c.y});
    std::vector<int> perStrip;
    int agreeing = 0, paintedAny = 0;
    s.compare(4, perStrip, agreeing, paintedAny);
    const double ratio = double(agreeing) / double(std::max(paintedAny, 1));
    std::printf("radial 4: %d %d %d %d texels, %.2f %% agree\n", perStrip[0], perStrip[1],
                perStrip[2], perStrip[3], 100.0 * ratio);
    for (int n : perStrip)
        EXPECT_GT(n, 200);
    EXPECT_GE(ratio, 0.98);
}

TEST(Symmetry, StrokeAlongTheMirrorPlanePaintsNoMoreThanWithout) {
    // One body cut by the plane x = 0 (its own mirror image): a soft stroke along the plane.
    const glm::mat4 centred = glm::translate(glm::mat4(1.0f), {0.7f, 0.0f, 0.0f});
    std::vector<std::uint8_t> pages[2];
    for (int symmetric = 0; symmetric < 2; ++symmetric) {
        Scene s(symmetricScene({centred}), 0.0f, 10.0f);
        s.doc.brush().hardness = 0.0f;
        s.doc.brush().flow = 0.3f;
        s.doc.brush().symmetry.mirrorX = symmetric == 1;
        const glm::vec3 a = s.view.project({0.0f, -0.25f, 0.4f});
        const glm::vec3 b = s.view.project({0.0f, 0.25f, 0.4f});
        s.stroke({a.x, a.y}, {b.x, b.y});
        pages[symmetric] = s.target().page(0).rgba;
    }
    int worst = 0;
    for (std::size_t i = 0; i < pages[0].size(); ++i)
        worst = std::max(worst, std::abs(int(pages[0][i]) - int(pages[1][i])));
    EXPECT_LE(worst, 1);
}

TEST(Symmetry, ABuildElsewhereIsAdoptedOnlyWhileCurrentAndOutlivesASymmetryOff) {
    // As the GUI does it: the copies are built off the document (any thread), a stroke never.
    Scene s(symmetricScene({glm::mat4(1.0f), kMirrorX}), -60.0f, 20.0f);
    s.doc.setSymmetryBuiltOnStroke(false);
    s.doc.brush().symmetry.mirrorX = true;
    std::optional<core::Document::SymmetryBuild> build = s.doc.symmetryBuild();
    ASSERT_TRUE(build);
    EXPECT_FALSE(s.doc.symmetryReady());
    std::vector<double> progress;
    ASSERT_TRUE(build->build([&](double f) {
        progress.push_back(f);
        return true;
    }));
    EXPECT_EQ(progress, (std::vector<double>{0.0, 0.5, 1.0}));
    // Made for mirror X: stale once the symmetry is another one.
    s.doc.brush().symmetry.mirrorY = true;
    EXPECT_FALSE(s.doc.adoptSymmetry(*build));
    s.doc.brush().symmetry.mirrorY = false;
    ASSERT_TRUE(s.doc.adoptSymmetry(std::move(*build)));
    EXPECT_TRUE(s.doc.symmetryReady());
    ASSERT_EQ(s.doc.symmetryLayers().size(), 1u);

    // A stroke with symmetry off, then on again: the copies are still there and still paint.
    const glm::vec3 c = s.view.project({-1.0f, 0.05f, 0.1f});
    s.doc.brush().symmetry.mirrorX = false;
    s.stroke({c.x - 20.0f, c.y - 6.0f}, {c.x - 10.0f, c.y - 3.0f});
    s.doc.brush().symmetry.mirrorX = true;
    EXPECT_TRUE(s.doc.symmetryReady());
    s.stroke({c.x - 5.0f, c.y}, {c.x + 20.0f, c.y + 6.0f});
    EXPECT_EQ(s.doc.symmetryLayers().size(), 1u);
    std::vector<int> perStrip;
    int agreeing = 0, paintedAny = 0;
    s.compare(2, perStrip, agreeing, paintedAny);
    EXPECT_GT(perStrip[1], 300) << "the mirror stroke painted its copy";
}

TEST(Symmetry, TransformsAndNames) {
    core::BrushSymmetry sym;
    EXPECT_FALSE(sym.active());
    EXPECT_TRUE(core::symmetryMirrorFromName("xz", sym));
    EXPECT_EQ(core::symmetryMirrorName(sym), "xz");
    EXPECT_FALSE(core::symmetryMirrorFromName("xx", sym));
    EXPECT_FALSE(core::symmetryMirrorFromName("w", sym));
    sym.radial = 3;
    // Subsets {}, {x}, {z}, {x, z} times 3 turns, less the identity.
    EXPECT_EQ(core::symmetryTransforms(sym, glm::vec3(0.0f)).size(), 11u);
    core::BrushSymmetry mirror;
    mirror.mirrorX = true;
    const glm::vec3 centre(1.0f, 2.0f, 3.0f);
    const std::vector<glm::mat4> t = core::symmetryTransforms(mirror, centre);
    ASSERT_EQ(t.size(), 1u);
    const glm::vec3 q(t[0] * glm::vec4(1.5f, 0.0f, 0.0f, 1.0f));
    EXPECT_NEAR(q.x, 0.5f, 1e-5f);
    EXPECT_TRUE(core::symmetryReflects(t[0]));
}

TEST(Symmetry, ScriptSettingsRoundTripAndBadInputIsOneError) {
    core::Brush brush;
    ASSERT_TRUE(core::applyBrushSymmetry(
                    brush, nlohmann::json::parse(
                               R"({"mirror": "xz", "center": "origin", "radial": 4, "axis": "z"})"))
                    .ok());
    EXPECT_TRUE(brush.symmetry.mirrorX && !brush.symmetry.mirrorY && brush.symmetry.mirrorZ);
    EXPECT_EQ(brush.symmetry.center, core::BrushSymmetry::Center::Origin);
    EXPECT_EQ(brush.symmetry.radial, 4);
    EXPECT_EQ(brush.symmetry.axis, 2);
    core::Brush copy;
    ASSERT_TRUE(core::applyBrushSymmetry(copy, core::brushSymmetryJson(brush)).ok());
    EXPECT_EQ(copy.symmetry, brush.symmetry);
    const core::Status bad =
        core::applyBrushSymmetry(copy, nlohmann::json::parse(R"({"radial": 40})"));
    ASSERT_FALSE(bad.ok());
    EXPECT_NE(bad.error().find("radial"), std::string::npos);
    EXPECT_EQ(copy.symmetry, brush.symmetry); // unchanged
    ASSERT_TRUE(core::applyBrushSymmetry(copy, false).ok());
    EXPECT_FALSE(copy.symmetry.active());
}

} // namespace symmetry_test
