// SPDX-License-Identifier: GPL-3.0-or-later
// The connectivity compute pass on a headless EGL context (llvmpipe on CI): its links must be
// byte-identical to core::computeConnectivity on built-in models, synthetic scenes and malformed
// stacks; plus the backend policy and, disabled, the timing against the C++ reference.
#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/render/gl_test.h"

#include <glm/gtc/matrix_transform.hpp>

#include "core/depth/connectivity.h"
#include "core/depth/cpu_capture.h"
#include "core/depth/depth_stack.h"
#include "core/model/builtin_models.h"
#include "core/model/camera.h"
#include "core/model/mesh_topology.h"
#include "render/depth_capture.h"
#include "render/gl_context.h"
#include "render/gpu_connectivity.h"
#include "render/software_gl.h"
#include "tests/core/captured_scenes.h"
#include "tests/core/test_scenes.h"

namespace gpu_connectivity_gltest {

using core::ConnectionTest;
using core_test::addGrid;
using core_test::frontView;

class GpuConnectivityGlTest : public render_test::GlTest {
protected:
    void SetUp() override {
        ASSERT_TRUE(s_context);
        const core::Status status = m_gpu.initialize();
        ASSERT_TRUE(status) << status.error();
    }
    void TearDown() override { m_gpu.release(); }

    render::GpuConnectivity m_gpu;
};

using Scene = core_test::CapturedScene;

Scene makeScene(std::string name, core::Mesh mesh, const core::View& view, bool cull = true) {
    Scene s = core_test::captureScene(std::move(mesh), view, cull);
    s.name = std::move(name);
    return s;
}

core::View orbitView(const core::Mesh& mesh, float yaw, float pitch, float distance, int width,
                     int height, bool orthographic) {
    core::Camera camera = core::Camera::fromOrbit(mesh.bounds(), yaw, pitch, distance);
    camera.orthographic = orthographic;
    return camera.view(width, height);
}

/**
 * Byte-compares the GPU's links with the reference's; describes the first mismatches. On a
 * software renderer (llvmpipe on CI) they must be identical. Hardware may round division and
 * square roots differently in the last bit (GLSL allows it), which flips a rare decision that
 * hinges on it: there up to 1 byte in 10,000 may differ.
 */
void expectSameLinks(const core::Connectivity& cpu, const core::Connectivity& gpu,
                     const core::DepthStack& stack, const std::string& what) {
    EXPECT_EQ(gpu.width, cpu.width) << what;
    EXPECT_EQ(gpu.height, cpu.height) << what;
    EXPECT_EQ(gpu.truncated, cpu.truncated) << what;
    ASSERT_EQ(gpu.links.size(), cpu.links.size()) << what;
    if (gpu.links == cpu.links)
        return;
    std::size_t mismatches = 0;
    std::string first;
    for (std::size_t i = 0; i < cpu.links.size(); ++i) {
        if (gpu.links[i] == cpu.links[i])
            continue;
        if (++mismatches <= 8) {
            const std::size_t fragment = i / 4;
            const auto pixel =
                std::size_t(std::upper_bound(stack.offsets.begin(), stack.offsets.end(), fragment) -
                            stack.offsets.begin() - 1);
            first += "\n  pixel (" + std::to_string(pixel % std::size_t(stack.width)) + ", " +
                     std::to_string(pixel / std::size_t(stack.width)) + ") layer " +
                     std::to_string(fragment - stack.offsets[pixel] + 1) + " direction " +
                     std::to_string(i % 4) + ": cpu " + std::to_string(cpu.links[i]) + ", gpu " +
                     std::to_string(gpu.links[i]);
        }
    }
    const std::string message = what + ": " + std::to_string(mismatches) + " of " +
                                std::to_string(cpu.links.size()) + " link bytes differ" + first;
    if (render::isSoftwareRenderer() || mismatches > cpu.links.size() / 10000)
        ADD_FAILURE() << message;
    else
        std::printf("[ note     ] %s\n", message.c_str());
}

/** Both tests at several thresholds: GPU links against the reference's. */
void expectSameAsReference(render::GpuConnectivity& gpu, const Scene& s,
                           std::vector<float> thresholds = {0.0003f, 0.001f, 0.004f, 0.02f}) {
    ASSERT_GT(s.stack.fragmentCount(), 0u) << s.name;
    for (ConnectionTest test : {ConnectionTest::Surface, ConnectionTest::Plain})
        for (float threshold : thresholds) {
            const std::string what = s.name +
                                     (test == ConnectionTest::Surface ? " surface" : " plain") +
                                     " threshold " + std::to_string(threshold);
            core::ConnectivityOptions options;
            options.test = test;
            options.threshold = threshold;
            options.unitScale = core::unitScale(s.mesh);
            options.threads = 2;
            const core::Connectivity cpu = core::computeConnectivity(s.stack, options, &s.geometry);
            auto result = gpu.compute(s.stack, options, &s.geometry);
            ASSERT_TRUE(result) << what << ": " << result.error();
            expectSameLinks(cpu, *result, s.stack, what);
            if (test != ConnectionTest::Surface || threshold != 0.001f)
                continue;
            // The planes of the shown triangles only (what a build makes), on both sides.
            const core::SurfaceGeometry shown =
                core::makeSurfaceGeometry(s.mesh, s.topology, s.view, &s.stack);
            ASSERT_TRUE(shown.hasEntries());
            const core::Connectivity cpuShown = core::computeConnectivity(s.stack, options, &shown);
            EXPECT_EQ(cpuShown.links, cpu.links) << what << " (shown triangles only)";
            auto gpuShown = gpu.compute(s.stack, options, &shown);
            ASSERT_TRUE(gpuShown) << what << ": " << gpuShown.error();
            expectSameLinks(cpu, *gpuShown, s.stack, what + " (shown triangles only)");
        }
}

/** How many link bytes are set and how deep the stack goes: the comparisons are not vacuous. */
void expectNontrivial(const Scene& s, std::uint32_t minLayers) {
    EXPECT_GE(s.stack.maxLayers(), minLayers) << s.name;
    core::ConnectivityOptions options;
    options.unitScale = core::unitScale(s.mesh);
    const core::Connectivity cpu = core::computeConnectivity(s.stack, options, &s.geometry);
    const auto linked =
        std::count_if(cpu.links.begin(), cpu.links.end(), [](std::uint8_t l) { return l != 0; });
    EXPECT_GT(std::size_t(linked), cpu.links.size() / 2) << s.name;
}

// ---------------------------------------------------------------------------------------------

TEST_F(GpuConnectivityGlTest, BuiltinModelsMatchReferenceFromSeveralViews) {
    struct Model {
        const char* name;
        core::Mesh mesh;
    };
    std::vector<Model> models;
    models.push_back({"trefoil", core::makeTrefoil()});
    models.push_back({"trefoil-coarse", core::makeTrefoil(100, 30)});
    models.push_back({"hexring", core::makeHexRing()});
    models.push_back({"row", core::makeRow()});
    const float views[][3] = {{0.0f, 0.0f, 2.0f}, {35.0f, 25.0f, 1.8f}, {120.0f, -40.0f, 2.5f}};
    for (Model& model : models) {
        const core::MeshTopology topology = core::buildMeshTopology(model.mesh);
        for (const auto& v : views)
            for (bool orthographic : {false, true}) {
                Scene s;
                s.name = std::string(model.name) + " yaw " + std::to_string(int(v[0])) +
                         (orthographic ? " ortho" : " persp");
                s.mesh = model.mesh;
                s.topology = topology;
                s.view = orbitView(s.mesh, v[0], v[1], v[2], 320, 240, orthographic);
                s.stack = core::captureDepthLayersCpu(s.mesh, s.view, {true, 2});
                s.geometry = core::makeSurfaceGeometry(s.mesh, topology, s.view);
                expectSameAsReference(m_gpu, s);
            }
    }
}

TEST_F(GpuConnectivityGlTest, TwoSidedCapturesMatchReference) {
    for (const char* name : {"trefoil", "hexring", "row"}) {
        auto mesh = core::makeBuiltinModel(name);
        ASSERT_TRUE(mesh) << mesh.error();
        for (bool orthographic : {false, true}) {
            const core::View view = orbitView(*mesh, 10.0f, 5.0f, 1.7f, 320, 240, orthographic);
            const Scene s =
                makeScene(std::string(name) + " two-sided" + (orthographic ? " ortho" : " persp"),
                          *mesh, view, false);
            expectNontrivial(s, 4);
            expectSameAsReference(m_gpu, s, {0.001f, 0.004f});
        }
    }
}

TEST_F(GpuConnectivityGlTest, Trefoil1280x720MatchesReference) {
    const Scene s = makeScene("trefoil 1280x720", core::makeTrefoil(),
                              orbitView(core::makeTrefoil(), 30.0f, 20.0f, 1.6f, 1280, 720, false));
    expectNontrivial(s, 3);
    expectSameAsReference(m_gpu, s, {0.001f, 0.005f});
}

TEST_F(GpuConnectivityGlTest, GlCaptureMatchesReference) {
    // Stacks from the GL capture (a different rasterizer than the CPU stand-in).
    render::DepthCapture capture;
    ASSERT_TRUE(capture.initialize());
    for (const char* name : {"trefoil", "row"}) {
        auto mesh = core::makeBuiltinModel(name);
        ASSERT_TRUE(mesh) << mesh.error();
        capture.setMesh(*mesh);
        for (bool twoSided : {false, true}) {
            Scene s;
            s.name = std::string(name) + " gl capture" + (twoSided ? " two-sided" : "");
            s.mesh = *mesh;
            s.topology = core::buildMeshTopology(s.mesh);
            s.view = orbitView(s.mesh, -70.0f, 15.0f, 1.7f, 400, 300, false);
            render::DepthCaptureOptions options;
            options.cullBackFaces = !twoSided;
            auto stack = capture.capture(s.view, options);
            ASSERT_TRUE(stack) << stack.error();
            s.stack = std::move(stack).value();
            s.geometry = core::makeSurfaceGeometry(s.mesh, s.topology, s.view);
            expectSameAsReference(m_gpu, s, {0.001f});
        }
    }
    capture.release();
}

TEST_F(GpuConnectivityGlTest, SyntheticScenesMatchReference) {
    // The core tests' hard cases: slopes up to grazing (the Plain fallback and its arc test),
    // parts closer than the threshold, coplanar parts touching, a coarse mesh (facets).
    for (float degrees : {0.0f, 45.0f, 80.0f, 85.0f, 88.0f, 89.0f})
        for (bool orthographic : {false, true}) {
            core::Mesh mesh;
            const glm::mat4 turn =
                glm::rotate(glm::mat4(1.0f), glm::radians(degrees), glm::vec3(0, 1, 0));
            const glm::vec3 u = glm::vec3(turn * glm::vec4(1, 0, 0, 0)), v(0, 1, 0);
            addGrid(mesh, -0.5f * u - 0.5f * v, u, v, 8);
            core_test::finishGrids(mesh);
            expectSameAsReference(
                m_gpu,
                makeScene("plane " + std::to_string(degrees) + (orthographic ? " ortho" : " persp"),
                          std::move(mesh), frontView(200, 160, orthographic)));
        }
    {
        core::Mesh mesh;
        addGrid(mesh, {-0.5f, -0.5f, 0.0f}, {0.7f, 0, 0}, {0, 1.0f, 0}, 4);
        addGrid(mesh, {-0.2f, -0.5f, -0.0005f}, {0.7f, 0, 0}, {0, 1.0f, 0}, 4);
        core_test::finishGrids(mesh);
        expectSameAsReference(
            m_gpu, makeScene("parallel parts", std::move(mesh), frontView(200, 200, false)));
    }
    {
        core::Mesh mesh;
        addGrid(mesh, {-0.5f, -0.5f, 0.0f}, {0.5f, 0, 0}, {0, 1.0f, 0}, 3);
        addGrid(mesh, {0.0f, -0.4f, 0.0f}, {0.5f, 0, 0}, {0, 0.8f, 0}, 2);
        core_test::finishGrids(mesh);
        expectSameAsReference(
            m_gpu, makeScene("touching parts", std::move(mesh), frontView(160, 160, true)));
    }
    // Yaw 77 is captured two-sided.
    const core::Mesh coarse = core::makeTrefoil(24, 8);
    for (float yaw : {0.0f, 77.0f, 200.0f})
        expectSameAsReference(m_gpu, makeScene("coarse trefoil " + std::to_string(yaw), coarse,
                                               orbitView(coarse, yaw, 40.0f, 1.4f, 240, 200, false),
                                               yaw != 77.0f));
}

TEST_F(GpuConnectivityGlTest, NonDefaultAnglesAndUnknownTrianglesMatchReference) {
    const core::Mesh mesh = core::makeHexRing(12);
    Scene s = makeScene("hexring", mesh, orbitView(mesh, 20.0f, 50.0f, 1.5f, 256, 192, false));
    // Drop the last third of the triangles from the geometry: their fragments are unknown and
    // take the plain test; mark some corners and components unknown too.
    s.geometry.triangles.resize(s.geometry.triangles.size() * 2 / 3);
    for (std::size_t t = 0; t < s.geometry.triangles.size(); t += 7)
        s.geometry.triangles[t].corners = {core::kNone, core::kNone, core::kNone};
    for (std::size_t t = 3; t < s.geometry.triangles.size(); t += 11)
        s.geometry.triangles[t].component = 5;
    for (std::size_t t = 5; t < s.geometry.triangles.size(); t += 13)
        s.geometry.triangles[t].plane = glm::vec4(0.0f); // degenerate
    for (float crease : {0.0f, 30.0f, 180.0f})
        for (float smooth : {0.0f, 20.0f, 90.0f})
            for (float contact : {0.0f, 0.1f, 3.0f}) {
                core::ConnectivityOptions options;
                options.unitScale = core::unitScale(mesh);
                options.creaseAngleDegrees = crease;
                options.smoothAngleDegrees = smooth;
                options.contactFactor = contact;
                const core::Connectivity cpu =
                    core::computeConnectivity(s.stack, options, &s.geometry);
                auto gpu = m_gpu.compute(s.stack, options, &s.geometry);
                ASSERT_TRUE(gpu) << gpu.error();
                expectSameLinks(cpu, *gpu, s.stack,
                                "angles " + std::to_string(crease) + " " + std::to_string(smooth) +
                                    " contact " + std::to_string(contact));
            }
    // Surface without geometry falls back to Plain, as in the reference; a unit scale of 0 counts
    // as 1.
    core::ConnectivityOptions options;
    options.unitScale = 0.0f;
    auto gpu = m_gpu.compute(s.stack, options, nullptr);
    ASSERT_TRUE(gpu) << gpu.error();
    expectSameLinks(core::computeConnectivity(s.stack, options, nullptr), *gpu, s.stack,
                    "no geometry");
}

TEST_F(GpuConnectivityGlTest, FragmentsBeyondLayer255AreTruncatedAsInReference) {
    // Three pixels in an L with 300 fragments each (more layers than a capture of a real mesh
    // reaches), coincident and on stacked planes, for both tests.
    core::DepthStack stack;
    stack.width = 2;
    stack.height = 2;
    const std::uint32_t n = 300;
    stack.offsets = {0, n, 2 * n, 3 * n, 3 * n};
    for (int p = 0; p < 3; ++p)
        for (std::uint32_t k = 0; k < n; ++k) {
            stack.depth.push_back(1.0f + 0.01f * float(k) +
                                  (p == 2 ? 0.0004f * float(k % 3) : 0.0f));
            stack.triangle.push_back(k % 150);
        }
    core::SurfaceGeometry geometry;
    geometry.rays = core::PixelRays::fromView(frontView(2, 2, false));
    geometry.triangles.resize(100); // ids 100..149 are unknown
    for (std::uint32_t t = 0; t < 100; ++t) {
        geometry.triangles[t].plane = glm::vec4(0.0f, 0.0f, 1.0f, 1.0f + 0.01f * float(t));
        geometry.triangles[t].corners = {t, t + 1, t + 2};
        geometry.triangles[t].component = t / 50;
    }
    for (ConnectionTest test : {ConnectionTest::Plain, ConnectionTest::Surface}) {
        core::ConnectivityOptions options;
        options.test = test;
        options.threshold = 0.002f;
        const core::Connectivity cpu = core::computeConnectivity(stack, options, &geometry);
        auto gpu = m_gpu.compute(stack, options, &geometry);
        ASSERT_TRUE(gpu) << gpu.error();
        EXPECT_TRUE(gpu->truncated);
        EXPECT_EQ(gpu->link(255, core::kRight), 0);
        EXPECT_NE(gpu->link(0, core::kRight), 0);
        expectSameLinks(cpu, *gpu, stack, test == ConnectionTest::Plain ? "plain" : "surface");
    }
}

TEST_F(GpuConnectivityGlTest, MalformedAndEmptyStacks) {
    core::ConnectivityOptions options;
    // No fragments at all.
    core::DepthStack empty;
    empty.width = 5;
    empty.height = 3;
    empty.offsets.assign(16, 0);
    auto result = m_gpu.compute(empty, options, nullptr);
    ASSERT_TRUE(result) << result.error();
    EXPECT_TRUE(result->links.empty());
    EXPECT_FALSE(result->truncated);
    // Wrong offsets size: the reference's all-zero links.
    core::DepthStack wrongSize;
    wrongSize.width = 2;
    wrongSize.height = 1;
    wrongSize.offsets = {0, 1};
    wrongSize.depth = {1.0f};
    wrongSize.triangle = {0};
    result = m_gpu.compute(wrongSize, options, nullptr);
    ASSERT_TRUE(result) << result.error();
    EXPECT_EQ(result->links, core::computeConnectivity(wrongSize, options).links);
    // Offsets that do not describe the fragments: an error, not a read out of bounds.
    core::DepthStack descending;
    descending.width = 2;
    descending.height = 1;
    descending.offsets = {0, 2, 1};
    descending.depth = {1.0f};
    descending.triangle = {0};
    EXPECT_FALSE(m_gpu.compute(descending, options, nullptr));
    descending.offsets = {0, 1, 2};
    EXPECT_FALSE(m_gpu.compute(descending, options, nullptr));
    // Not initialized.
    render::GpuConnectivity uninitialized;
    EXPECT_FALSE(uninitialized.initialized());
    EXPECT_FALSE(uninitialized.compute(empty, options, nullptr));
}

TEST_F(GpuConnectivityGlTest, BuffersShrinkAndGrowBetweenCalls) {
    // A large view, a small one, then the large one again: stale words of the large view must not
    // leak into the small one's result.
    const core::Mesh mesh = core::makeTrefoil(100, 30);
    for (int size : {480, 96, 480, 160}) {
        const Scene s = makeScene("trefoil " + std::to_string(size), mesh,
                                  orbitView(mesh, 10.0f, 5.0f, 1.7f, size, size * 3 / 4, false));
        expectSameAsReference(m_gpu, s, {0.001f});
    }
}

TEST_F(GpuConnectivityGlTest, ManyFragmentsDispatchInRowsOfGroups) {
    // More fragments than one row of work groups holds on llvmpipe (65535 × 64): the dispatch
    // becomes two-dimensional. One fragment a pixel, depths in steps around the threshold.
    core::DepthStack stack;
    stack.width = 2100;
    stack.height = 2100;
    const std::size_t pixels = stack.pixelCount();
    stack.offsets.resize(pixels + 1);
    stack.depth.resize(pixels);
    stack.triangle.resize(pixels);
    for (std::size_t p = 0; p < pixels; ++p) {
        stack.offsets[p] = std::uint32_t(p);
        stack.depth[p] = 1.0f + 0.0004f * float((p % 2100 * 7 + p / 2100 * 13) % 5);
        stack.triangle[p] = std::uint32_t(p % 3);
    }
    stack.offsets[pixels] = std::uint32_t(pixels);
    ASSERT_GT(pixels, std::size_t(65535) * 64);
    core::ConnectivityOptions options;
    options.test = ConnectionTest::Plain;
    auto gpu = m_gpu.compute(stack, options, nullptr);
    ASSERT_TRUE(gpu) << gpu.error();
    expectSameLinks(core::computeConnectivity(stack, options), *gpu, stack, "2100x2100");
}

TEST_F(GpuConnectivityGlTest, BackendPolicy) {
    using render::ConnectivityBackend;
    EXPECT_TRUE(render::isSoftwareRenderer("llvmpipe (LLVM 15.0.6, 256 bits)"));
    EXPECT_TRUE(render::isSoftwareRenderer("softpipe"));
    EXPECT_TRUE(render::isSoftwareRenderer("Google SwiftShader"));
    EXPECT_FALSE(render::isSoftwareRenderer("NVIDIA GeForce RTX 3060/PCIe/SSE2"));
    EXPECT_FALSE(render::isSoftwareRenderer("AMD Radeon RX 6600 (radeonsi, navi23, LLVM 15.0.6)"));
    EXPECT_FALSE(render::isSoftwareRenderer("Mesa Intel(R) UHD Graphics 620 (KBL GT2)"));
    EXPECT_EQ(render::isSoftwareRenderer(),
              render::isSoftwareRenderer(render::HeadlessContext::rendererName()));

    EXPECT_EQ(render::resolveConnectivityBackend(ConnectivityBackend::Auto, true),
              ConnectivityBackend::Cpu);
    EXPECT_EQ(render::resolveConnectivityBackend(ConnectivityBackend::Auto, false),
              ConnectivityBackend::Gpu);
    for (bool software : {false, true}) {
        EXPECT_EQ(render::resolveConnectivityBackend(ConnectivityBackend::Cpu, software),
                  ConnectivityBackend::Cpu);
        EXPECT_EQ(render::resolveConnectivityBackend(ConnectivityBackend::Gpu, software),
                  ConnectivityBackend::Gpu);
    }
    for (ConnectivityBackend b :
         {ConnectivityBackend::Auto, ConnectivityBackend::Cpu, ConnectivityBackend::Gpu})
        EXPECT_EQ(render::parseConnectivityBackend(render::connectivityBackendName(b)), b);
    EXPECT_EQ(render::parseConnectivityBackend("GPU"), ConnectivityBackend::Gpu);
    EXPECT_FALSE(render::parseConnectivityBackend("cuda"));
    EXPECT_FALSE(render::parseConnectivityBackend(""));

    // The dispatcher: the same links whichever backend runs; Gpu falls back without a pass.
    const core::Mesh mesh = core::makeRow(16);
    const Scene s = makeScene("row", mesh, orbitView(mesh, 30.0f, 10.0f, 2.0f, 160, 120, false));
    core::ConnectivityOptions options;
    options.unitScale = core::unitScale(mesh);
    const core::Connectivity reference = core::computeConnectivity(s.stack, options, &s.geometry);
    const bool software = render::isSoftwareRenderer();
    struct Case {
        ConnectivityBackend requested;
        render::GpuConnectivity* gpu;
        ConnectivityBackend expected;
    };
    const Case cases[] = {
        {ConnectivityBackend::Cpu, &m_gpu, ConnectivityBackend::Cpu},
        {ConnectivityBackend::Gpu, &m_gpu, ConnectivityBackend::Gpu},
        {ConnectivityBackend::Gpu, nullptr, ConnectivityBackend::Cpu},
        {ConnectivityBackend::Auto, &m_gpu,
         software ? ConnectivityBackend::Cpu : ConnectivityBackend::Gpu},
    };
    for (const Case& c : cases) {
        ConnectivityBackend used = ConnectivityBackend::Auto;
        const core::Connectivity links =
            render::computeConnectivity(c.requested, c.gpu, s.stack, options, &s.geometry, &used);
        EXPECT_EQ(used, c.expected) << render::connectivityBackendName(c.requested);
        EXPECT_EQ(links.links, reference.links);
    }
}

} // namespace gpu_connectivity_gltest
