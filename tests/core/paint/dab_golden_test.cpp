// SPDX-License-Identifier: GPL-3.0-or-later
// The texel scan of a dab may take short cuts (triangles whose texels are all at the dab's
// opacity already, texels it cannot raise), but never change a byte: strokes with a round tip, a
// chalk tip with angle jitter, the eraser, 8 paint layers and 4-way symmetry on the trefoil give
// the same shown pages, base, layer tiles and undo results as the plain scan did. The expected
// hashes were taken from the plain scan (every texel of every triangle reaching the map). On a
// dense knot (several triangles per pixel) a dab finds its triangles through per-view caches; the
// dense cases' hashes were taken from the per-dab walk over edge neighbours. The hashes of strokes
// on the base were taken again when its colour began to mix on sRGB-encoded values, as paint
// layers do (the short cuts look at coverage only).
#include <cstdint>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "core/depth/depth_layers.h"
#include "core/document/document.h"
#include "core/model/builtin_models.h"
#include "core/model/camera.h"
#include "core/paint/paint_layers/paint_layers.h"
#include "core/paint/targets/paint_target.h"

namespace dab_golden_test {

constexpr int kWidth = 320, kHeight = 240;

struct Hash {
    std::uint64_t value = 1469598103934665603ull;
    // FNV-1a over 8-byte words (then the remaining bytes): fast enough for whole pages.
    void add(const std::uint8_t* data, std::size_t size) {
        std::size_t i = 0;
        for (; i + 8 <= size; i += 8) {
            std::uint64_t word;
            std::memcpy(&word, data + i, 8);
            value = (value ^ word) * 1099511628211ull;
        }
        for (; i < size; ++i)
            value = (value ^ data[i]) * 1099511628211ull;
    }
    void add(const std::vector<std::uint8_t>& bytes) { add(bytes.data(), bytes.size()); }
    void add(std::uint64_t v) { add(reinterpret_cast<const std::uint8_t*>(&v), sizeof v); }
};

class DabGolden : public ::testing::Test {
protected:
    void SetUp() override { setUpScene(core::makeTrefoil(), core::kDefaultModel); }

    void setUpScene(core::Mesh mesh, const std::string& name) {
        m_doc.setMesh(std::move(mesh), name);
        core::PaintTargetOptions options;
        options.kind = core::PaintTargetKind::Texture;
        options.resolution = 2048;
        ASSERT_TRUE(m_doc.setPaintTarget(options).ok());
        core::Camera camera;
        camera.frame(m_doc.mesh().bounds(), float(kWidth) / float(kHeight), 0.1f);
        camera.yawDegrees = 20.0f;
        camera.pitchDegrees = 15.0f;
        m_view = camera.view(kWidth, kHeight);
        m_capturer.setMesh(m_doc.mesh());
        ASSERT_TRUE(m_doc.buildDepthLayers(m_capturer, m_view).ok());
        core::Brush& brush = m_doc.brush();
        brush.radius = 12.0f;
        brush.hardness = 0.5f;
        brush.flow = 0.7f;
        brush.color = {0.9f, 0.3f, 0.1f, 1.0f};
        brush.roughness = 0.2f;
        brush.metallic = 0.8f;
    }

    const core::TextureTarget& target() const {
        return dynamic_cast<const core::TextureTarget&>(*m_doc.currentPaintTarget());
    }

    /** Every byte the target shows and holds: pages, base, each paint layer's tiles. */
    std::uint64_t stateHash() const {
        Hash h;
        if (const auto* colors =
                dynamic_cast<const core::VertexColorTarget*>(m_doc.currentPaintTarget())) {
            h.add(reinterpret_cast<const std::uint8_t*>(colors->colors().data()),
                  colors->colors().size() * sizeof(glm::vec4));
            return h.value;
        }
        const core::TextureTarget& t = target();
        for (std::size_t p = 0; p < t.pageCount(); ++p) {
            h.add(t.page(p).rgba);
            h.add(t.metallicRoughnessPage(p).rgba);
            h.add(t.basePixels(p));
            const core::Image& page = t.page(p);
            const std::uint32_t tiles =
                std::uint32_t((page.width + core::kTextureTile - 1) / core::kTextureTile) *
                std::uint32_t((page.height + core::kTextureTile - 1) / core::kTextureTile);
            const core::PaintLayerStack& stack = t.paintLayerStack();
            for (std::size_t l = 0; l < stack.size(); ++l) {
                for (const bool mask : {false, true}) {
                    const std::uint64_t plane =
                        core::TextureTarget::planeKey(stack.layer(l).id, mask);
                    for (std::uint32_t tile = 0; tile < tiles; ++tile) {
                        const core::TileKey key{std::uint32_t(p), tile, plane};
                        std::vector<std::uint8_t> bytes(t.tileBytes(key));
                        if (bytes.empty() || !t.readTile(key, bytes))
                            continue;
                        h.add(std::uint64_t(tile));
                        h.add(bytes);
                    }
                }
            }
        }
        return h.value;
    }

    /** Strokes along rows of the view in 3 px steps (the bench's path, denser). */
    void strokes() {
        const core::DepthStack& stack = m_doc.depthLayers()->stack;
        for (const int y : {kHeight / 2, kHeight / 2 + 7, kHeight / 3}) {
            for (int x = kWidth / 10; x < kWidth * 9 / 10; x += 3) {
                const core::StrokePoint point{{float(x) + 0.5f, float(y) + 0.5f}, 1.0f};
                if (stack.layerCount(std::size_t(y) * std::size_t(kWidth) + std::size_t(x)) == 0) {
                    if (m_doc.inStroke())
                        m_doc.endStroke(m_changes);
                    continue;
                }
                if (!m_doc.inStroke())
                    ASSERT_TRUE(m_doc.beginStroke(point, m_changes).ok());
                else
                    m_doc.moveStroke(point, m_changes);
            }
            if (m_doc.inStroke())
                m_doc.endStroke(m_changes);
        }
    }

    /**
     * The state after the strokes, then after undoing each step of the history back to the start
     * (the undo records' bytes) and redoing them all, hashed together with the history's size.
     */
    std::uint64_t run() {
        strokes();
        EXPECT_GE(m_doc.history().size(), 2u);
        Hash h;
        h.add(stateHash());
        h.add(std::uint64_t(m_doc.history().bytes()));
        std::size_t undone = 0;
        while (m_doc.history().canUndo() && m_doc.undo(m_changes)) {
            ++undone;
            h.add(stateHash());
        }
        for (std::size_t i = 0; i < undone; ++i)
            EXPECT_TRUE(m_doc.redo(m_changes));
        h.add(stateHash());
        return h.value;
    }

    void addLayers() {
        for (int i = 0; i < 8; ++i) {
            core::PaintLayerSettings settings;
            settings.name = "layer " + std::to_string(i + 1);
            ASSERT_TRUE(m_doc.addPaintLayer(settings, m_changes).ok());
        }
        core::Brush& brush = m_doc.brush();
        brush.paintBaseColor = brush.paintRoughness = brush.paintMetallic = true;
    }

    void chalk() {
        core::Brush& brush = m_doc.brush();
        brush.tip = "chalk";
        brush.angleMode = core::TipAngleMode::Stroke;
        brush.jitter.angle = 20.0f;
    }

    core::Document m_doc;
    core::CpuDepthCapturer m_capturer;
    core::View m_view;
    core::PaintChanges m_changes;
};

/**
 * A dense mesh: the knot of 300K triangles at 320 × 240 has several triangles per pixel, most too
 * small to cover a pixel centre, so a dab paints many triangles that have no fragment.
 */
class DabGoldenDense : public DabGolden {
protected:
    void SetUp() override { setUpScene(core::makeKnot(300000), "builtin:knot?triangles=300000"); }
};

// Printed on failure, so a deliberate change of the painted bytes can update them.
constexpr std::uint64_t kRound = 3208009920459622899ull, kChalk = 12729422685511427619ull,
                        kEraser = 5366515592071421789ull, kLayers = 14148109469639038919ull,
                        kLayersChalk = 8698467255929120854ull, kSymmetric = 725557882951730191ull,
                        kSymmetricLayers = 14531716853140848820ull;

TEST_F(DabGolden, RoundTip) {
    EXPECT_EQ(run(), kRound);
}

TEST_F(DabGolden, ChalkTipWithAngleJitter) {
    chalk();
    EXPECT_EQ(run(), kChalk);
}

TEST_F(DabGolden, EraserOverPaint) {
    strokes();
    m_doc.brush().eraser = true;
    m_doc.brush().radius = 9.0f;
    m_doc.brush().hardness = 0.2f;
    EXPECT_EQ(run(), kEraser);
}

TEST_F(DabGolden, TopOfEightPaintLayers) {
    addLayers();
    EXPECT_EQ(run(), kLayers);
}

TEST_F(DabGolden, ChalkOnTopOfEightPaintLayers) {
    addLayers();
    chalk();
    EXPECT_EQ(run(), kLayersChalk);
}

TEST_F(DabGolden, SymmetricFourWayChalk) {
    chalk();
    m_doc.brush().symmetry.mirrorX = true;
    m_doc.brush().symmetry.mirrorZ = true;
    EXPECT_EQ(run(), kSymmetric);
}

TEST_F(DabGolden, SymmetricFourWayOnPaintLayers) {
    addLayers();
    m_doc.brush().symmetry.mirrorX = true;
    m_doc.brush().symmetry.mirrorZ = true;
    EXPECT_EQ(run(), kSymmetricLayers);
}

constexpr std::uint64_t kDense = 14898534968652007720ull,
                        kDenseChalkLayers = 14795070879340344200ull,
                        kDenseVertexColors = 1634004172070155621ull;

TEST_F(DabGoldenDense, RoundTipOnSubPixelTriangles) {
    EXPECT_EQ(run(), kDense);
}

TEST_F(DabGoldenDense, VertexColors) {
    core::PaintTargetOptions options;
    options.kind = core::PaintTargetKind::VertexColors;
    ASSERT_TRUE(m_doc.setPaintTarget(options).ok());
    // The step holding the texture target counts its memory, which is not what this compares.
    m_doc.history().clear();
    EXPECT_EQ(run(), kDenseVertexColors);
}

TEST_F(DabGoldenDense, ChalkOnTopOfEightPaintLayers) {
    addLayers();
    chalk();
    EXPECT_EQ(run(), kDenseChalkLayers);
}

} // namespace dab_golden_test
