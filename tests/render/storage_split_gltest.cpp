// SPDX-License-Identifier: GPL-3.0-or-later
// Storage split across several buffers (mesh parts, fragment chunks): the small scenes of the
// other GL tests run with the planned block size capped to a few KiB, so they take the split
// path, and every result must equal the unsplit one bit for bit.
#include <algorithm>
#include <cstring>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "tests/render/gl_test.h"

#include "core/depth/depth_layers.h"
#include "core/io/mesh_io.h"
#include "core/model/builtin_models.h"
#include "core/model/camera.h"
#include "core/model/mesh_topology.h"
#include "render/depth_capture.h"
#include "render/depth_compositor.h"
#include "render/gl_depth_capturer.h"
#include "render/offscreen_target.h"

namespace storage_split_gltest {

constexpr std::size_t kTinyBlock = 64 * 1024;

using render_test::orbitView;

/** The scenes: the built-ins, a textured box, and the trefoil with vertex colours. */
struct Scene {
    std::string name;
    core::Mesh mesh;
    core::View view;
    std::size_t block = kTinyBlock; // the capped block size
};

std::vector<Scene> scenes() {
    std::vector<Scene> out;
    const core::Mesh trefoil = core::makeTrefoil();
    out.push_back({"trefoil", trefoil, orbitView(trefoil, 45.0f, 60.0f, 320, 240, 0.6f)});
    const core::Mesh hexring = core::makeHexRing();
    out.push_back({"hexring", hexring, orbitView(hexring, 10.0f, 25.0f, 320, 240, 0.6f)});
    const core::Mesh row = core::makeRow();
    out.push_back({"row", row, orbitView(row, 30.0f, 20.0f, 320, 240)});
    core::Mesh colored = trefoil;
    colored.colors.resize(colored.vertexCount());
    for (std::size_t v = 0; v < colored.vertexCount(); ++v)
        colored.colors[v] = {float(v % 7) / 6.0f, float(v % 11) / 10.0f, float(v % 5) / 4.0f, 1.0f};
    out.push_back({"trefoil_colors", colored, orbitView(colored, 200.0f, 10.0f, 320, 240)});
    const std::string box =
        std::string(LAYERPAINT_ASSIMP_MODELS) + "/glTF2/BoxTextured-glTF-Binary/BoxTextured.glb";
    if (std::filesystem::exists(box)) {
        auto mesh = core::loadMesh(box);
        if (mesh)
            out.push_back({"box_textured", *mesh, orbitView(*mesh, 30.0f, 25.0f, 320, 240), 128});
    }
    return out;
}

class StorageSplitGlTest : public render_test::GlCaptureTest {
protected:
    void SetUp() override {
        ASSERT_NO_FATAL_FAILURE(GlCaptureTest::SetUp());
        for (render::DepthCompositor* compositor : {&m_whole, &m_split}) {
            const core::Status status = compositor->initialize();
            ASSERT_TRUE(status) << status.error();
        }
    }
    void TearDown() override {
        m_whole.release();
        m_split.release();
        GlCaptureTest::TearDown();
    }

    static core::Image draw(render::DepthCompositor& compositor, const core::DepthLayers& layers,
                            const render::CompositeOptions& options) {
        return render_test::drawComposite(compositor, layers.stack.width, layers.stack.height,
                                          options);
    }

    render::DepthCompositor m_whole;
    render::DepthCompositor m_split;
};

std::size_t differingBytes(const core::Image& a, const core::Image& b) {
    EXPECT_EQ(a.rgba.size(), b.rgba.size());
    std::size_t n = 0;
    for (std::size_t i = 0; i < std::min(a.rgba.size(), b.rgba.size()); ++i)
        n += a.rgba[i] != b.rgba[i];
    return n;
}

TEST_F(StorageSplitGlTest, CompositorMeshPartsDrawTheSamePicture) {
    for (const Scene& scene : scenes()) {
        SCOPED_TRACE(scene.name);
        const core::DepthLayers layers = captureDepthLayers(scene.mesh, scene.view);
        ASSERT_GT(layers.stack.fragmentCount(), 0u);
        // The cap plans the mesh parts; the fragment arrays keep the whole block (a tiny one
        // would refuse them, see CompositorShadesAsManyFragmentsAsItsFragmentArraysHold).
        m_split.setStorageBlockCap(scene.block);
        for (render::DepthCompositor* compositor : {&m_whole, &m_split}) {
            core::Status status = compositor->setMesh(scene.mesh);
            ASSERT_TRUE(status) << status.error();
            compositor->setStorageBlockCap(0);
            status = compositor->setDepthLayers(layers);
            ASSERT_TRUE(status) << status.error();
        }
        EXPECT_EQ(m_whole.meshPartCount(), 1u);
        // Every scene's triangles (16 bytes each) exceed the cap.
        EXPECT_GE(m_split.meshPartCount(),
                  (scene.mesh.triangleCount() * 16 + scene.block - 1) / scene.block);
        EXPECT_GE(m_split.meshPartCount(), 2u);
        render::CompositeOptions options;
        const core::Image whole = draw(m_whole, layers, options);
        EXPECT_EQ(differingBytes(whole, draw(m_split, layers, options)), 0u);
        options.display = render::DepthLayerDisplay::SingleLayer;
        options.layer = 2;
        EXPECT_EQ(differingBytes(draw(m_whole, layers, options), draw(m_split, layers, options)),
                  0u);
        EXPECT_EQ(m_whole.readVisible(), m_split.readVisible());
        // Something was drawn: not all background.
        std::size_t background = 0;
        for (std::size_t p = 0; p < whole.rgba.size() / 4; ++p)
            background += whole.rgba[4 * p] == whole.rgba[0] &&
                          whole.rgba[4 * p + 1] == whole.rgba[1] &&
                          whole.rgba[4 * p + 2] == whole.rgba[2];
        EXPECT_LT(background, whole.rgba.size() / 4);

        if (!scene.mesh.colors.empty()) {
            // Painting vertex colours reaches every part's copy of a vertex.
            std::vector<glm::vec4> paint(scene.mesh.vertexCount() / 3,
                                         glm::vec4(0.9f, 0.1f, 0.2f, 1.0f));
            const auto first = std::uint32_t(scene.mesh.vertexCount() / 4);
            m_whole.updateVertexColors(first, paint);
            m_split.updateVertexColors(first, paint);
            options = {};
            const core::Image painted = draw(m_whole, layers, options);
            EXPECT_GT(differingBytes(painted, whole), 1000u);
            EXPECT_EQ(differingBytes(painted, draw(m_split, layers, options)), 0u);
        }
    }
}

TEST_F(StorageSplitGlTest, AMeshPreparedOnAnotherThreadDrawsTheSamePicture) {
    for (const Scene& scene : scenes()) {
        SCOPED_TRACE(scene.name);
        const core::DepthLayers layers = captureDepthLayers(scene.mesh, scene.view);
        m_split.setStorageBlockCap(scene.block);
        // The CPU's share away from the GL thread, as the view does for a new model.
        core::Result<std::shared_ptr<const render::CompositorMesh>> prepared =
            core::Error{"not run"};
        std::thread worker([&] {
            prepared = render::DepthCompositor::prepareMesh(scene.mesh, scene.mesh,
                                                            m_split.storageBlockBytes());
        });
        worker.join();
        ASSERT_TRUE(prepared) << prepared.error();
        core::Status status = m_split.setMesh(**prepared, scene.mesh, scene.mesh, nullptr);
        ASSERT_TRUE(status) << status.error();
        EXPECT_GE(m_split.meshPartCount(), 2u);
        status = m_whole.setMesh(scene.mesh);
        ASSERT_TRUE(status) << status.error();
        for (render::DepthCompositor* compositor : {&m_whole, &m_split}) {
            compositor->setStorageBlockCap(0);
            status = compositor->setDepthLayers(layers);
            ASSERT_TRUE(status) << status.error();
        }
        const render::CompositeOptions options;
        EXPECT_EQ(differingBytes(draw(m_whole, layers, options), draw(m_split, layers, options)),
                  0u);

        // Prepared for another block size: prepared again for this one, whole here.
        status = m_whole.setMesh(**prepared, scene.mesh, scene.mesh, nullptr);
        ASSERT_TRUE(status) << status.error();
        EXPECT_EQ(m_whole.meshPartCount(), 1u);
    }
    // Another mesh's preparation is refused.
    const core::Mesh trefoil = core::makeTrefoil(), hexring = core::makeHexRing();
    auto prepared =
        render::DepthCompositor::prepareMesh(hexring, hexring, m_whole.storageBlockBytes());
    ASSERT_TRUE(prepared) << prepared.error();
    EXPECT_FALSE(m_whole.setMesh(**prepared, trefoil, trefoil, nullptr));
}

TEST_F(StorageSplitGlTest, CompositorShadesAsManyFragmentsAsItsFragmentArraysHold) {
    // A fragment's shading is a word in each of four buffers, so a block holding the fragment
    // arrays holds the shading too (one buffer of four words a fragment held a quarter of them).
    const core::Mesh trefoil = core::makeTrefoil();
    // Close up: the knot fills the view, two to four sheets deep.
    const core::DepthLayers layers =
        captureDepthLayers(trefoil, orbitView(trefoil, 45.0f, 60.0f, 320, 240, 0.35f));
    const std::size_t fragments = layers.stack.fragmentCount();
    const std::size_t pixels = layers.stack.pixelCount();
    // The largest other array: the visible and under fragment of each pixel.
    const std::size_t block = std::max(fragments * 4, 2 * pixels * 4);
    ASSERT_LT(block, fragments * 16) << "the scene must have more fragments than pixels / 2";
    m_split.setStorageBlockCap(block);
    for (render::DepthCompositor* compositor : {&m_whole, &m_split}) {
        core::Status status = compositor->setMesh(trefoil);
        ASSERT_TRUE(status) << status.error();
        status = compositor->setDepthLayers(layers);
        ASSERT_TRUE(status) << status.error();
    }
    render::CompositeOptions options;
    options.channel = render::MaterialChannel::BaseColor;
    for (const bool material : {false, true}) {
        if (material)
            options.channel = render::MaterialChannel::Material;
        EXPECT_EQ(differingBytes(draw(m_whole, layers, options), draw(m_split, layers, options)),
                  0u);
    }
    EXPECT_EQ(m_whole.readVisible(), m_split.readVisible());

    // One fragment more than a block holds is refused with what to do about it.
    m_split.setStorageBlockCap(fragments * 4 - 4);
    const core::Status refused = m_split.setDepthLayers(layers);
    ASSERT_FALSE(refused);
    EXPECT_NE(refused.error().find("make the view smaller"), std::string::npos) << refused.error();
}

TEST_F(StorageSplitGlTest, CaptureNodeChunksGiveTheSameLayerStack) {
    for (const Scene& scene : scenes()) {
        SCOPED_TRACE(scene.name);
        render::DepthCapture whole, split;
        ASSERT_TRUE(whole.initialize());
        ASSERT_TRUE(split.initialize());
        whole.setMesh(scene.mesh);
        split.setMesh(scene.mesh);
        for (const bool twoSided : {false, true}) {
            render::DepthCapture::Options options;
            options.cullBackFaces = !twoSided;
            auto reference = whole.capture(scene.view, options);
            ASSERT_TRUE(reference) << reference.error();
            EXPECT_EQ(whole.nodeChunks(), 1u);
            const std::size_t fragments = reference->fragmentCount();
            ASSERT_GT(fragments, 100u);
            // Blocks of about a third of the fragments: 3 to 6 chunks.
            split.setStorageBlockCap(fragments / 3 * 12);
            // The first capture grows from its first guess, the second reuses the chunks.
            for (int round = 0; round < 2; ++round) {
                auto stack = split.capture(scene.view, options);
                ASSERT_TRUE(stack) << stack.error();
                EXPECT_GE(split.nodeChunks(), 3u);
                EXPECT_EQ(stack->offsets, reference->offsets);
                EXPECT_EQ(stack->triangle, reference->triangle);
                EXPECT_EQ(std::memcmp(stack->depth.data(), reference->depth.data(),
                                      fragments * sizeof(float)),
                          0);
            }
            // Growing from a tiny buffer across chunk boundaries.
            split.setNodeCapacity(7);
            auto grown = split.capture(scene.view, options);
            ASSERT_TRUE(grown) << grown.error();
            EXPECT_EQ(grown->offsets, reference->offsets);
            EXPECT_EQ(grown->triangle, reference->triangle);
        }
        whole.release();
        split.release();
    }
}

TEST_F(StorageSplitGlTest, CaptureBeyondEveryChunkIsAClearError) {
    const core::Mesh trefoil = core::makeTrefoil();
    render::DepthCapture capture;
    ASSERT_TRUE(capture.initialize());
    capture.setMesh(trefoil);
    // 8 chunks of 4 nodes hold 32 fragments: far fewer than the view has.
    capture.setStorageBlockCap(4 * 12);
    auto stack = capture.capture(orbitView(trefoil, 45.0f, 60.0f, 320, 240, 0.6f));
    ASSERT_FALSE(stack);
    EXPECT_NE(stack.error().find("make the view smaller"), std::string::npos) << stack.error();
    capture.setStorageBlockCap(0);
    auto retried = capture.capture(orbitView(trefoil, 45.0f, 60.0f, 320, 240, 0.6f));
    EXPECT_TRUE(retried) << retried.error();
    capture.release();
}

} // namespace storage_split_gltest
