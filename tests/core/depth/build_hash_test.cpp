// SPDX-License-Identifier: GPL-3.0-or-later
// build_layers' CPU stages (surface planes, connectivity, segmentation, region graph) give the
// same bytes as the reference recorded below, for 1 and 2 threads: a trefoil and the
// 2CylinderEngine (17 depth layers), CPU-captured in the bench's framing. The hashes were taken
// from the straightforward implementation these stages started from; any change of a link, a
// region id or a graph edge changes them. They were retaken once, when the view's planes came
// from the mesh's own planes (MeshTopology::planes) instead of the corners taken to view space:
// the planes then differ in their last float bits, the trefoil's links not at all, and 35 of the
// engine's 3.9M links (pairs at the threshold) with its labels unchanged.
#include <cstdint>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "core/depth/connectivity.h"
#include "core/depth/cpu_capture.h"
#include "core/depth/depth_layers.h"
#include "core/io/mesh_io.h"
#include "core/model/builtin_models.h"
#include "core/model/camera.h"
#include "core/model/mesh_topology.h"

namespace build_hash_test {

/** FNV-1a over bytes, 64 bit. */
struct Hash {
    std::uint64_t value = 0xcbf29ce484222325ull;
    void bytes(const void* data, std::size_t size) {
        const auto* p = static_cast<const unsigned char*>(data);
        for (std::size_t i = 0; i < size; ++i) {
            value ^= p[i];
            value *= 0x100000001b3ull;
        }
    }
    template <typename T> void vector(const std::vector<T>& v) {
        const std::uint64_t size = v.size();
        bytes(&size, sizeof size);
        bytes(v.data(), v.size() * sizeof(T));
    }
};

struct Hashes {
    std::uint64_t stack = 0, planes = 0, links = 0, labels = 0, graph = 0;
};

/** Hashes of what build_layers derives from a CPU capture of mesh in the bench's framing. */
Hashes build(const core::Mesh& mesh, int width, int height, unsigned threads) {
    core::Camera camera;
    camera.frame(mesh.bounds());
    camera.orbit(30.0f, 20.0f);
    const core::View view = camera.view(width, height);
    core::DepthStack stack = core::captureDepthLayersCpu(mesh, view, {true, 2});
    Hashes out;
    Hash h;
    h.vector(stack.offsets);
    h.vector(stack.depth);
    h.vector(stack.triangle);
    out.stack = h.value;

    const core::MeshTopology topology = core::buildMeshTopology(mesh);
    core::DepthLayerOptions options;
    options.threads = threads;
    const core::DepthLayers layers =
        core::finishDepthLayers(std::move(stack), {}, mesh, topology, view, options);

    // The planes of the triangles the view shows (the only ones connectivity reads).
    Hash planes;
    planes.bytes(&layers.geometry.rays, sizeof layers.geometry.rays);
    for (std::uint32_t t : layers.stack.triangle) {
        const core::SurfaceTriangle* found = layers.geometry.find(t);
        if (!found) {
            ADD_FAILURE() << "fragment triangle " << t << " has no plane";
            return out;
        }
        const core::SurfaceTriangle& tri = *found;
        planes.bytes(&tri.plane, sizeof tri.plane);
        planes.bytes(tri.corners.data(), sizeof tri.corners);
        planes.bytes(&tri.component, sizeof tri.component);
    }
    out.planes = planes.value;

    Hash links;
    links.vector(layers.connectivity.links);
    links.bytes(&layers.connectivity.truncated, sizeof layers.connectivity.truncated);
    out.links = links.value;
    // The same links in four lanes where the processor has eight (AVX2).
    core::ConnectivityOptions fourLanes;
    fourLanes.threshold = options.threshold;
    fourLanes.unitScale = core::unitScale(mesh);
    fourLanes.threads = threads;
    fourLanes.wideLanes = false;
    const core::Connectivity narrow =
        core::computeConnectivity(layers.stack, fourLanes, &layers.geometry);
    EXPECT_TRUE(narrow.links == layers.connectivity.links) << "four lanes";

    Hash labels;
    labels.vector(layers.segmentation.region);
    out.labels = labels.value;

    Hash graph;
    const core::RegionGraph& g = layers.segmentation.graph;
    for (const core::Region& r : g.regions) {
        const std::uint32_t fields[3] = {r.id, r.layer, r.pixels};
        const int box[4] = {r.minX, r.minY, r.maxX, r.maxY};
        graph.bytes(fields, sizeof fields);
        graph.bytes(box, sizeof box);
    }
    graph.vector(g.neighborOffsets);
    for (const core::RegionLink& link : g.neighbors) {
        const std::uint32_t fields[2] = {link.region, link.links};
        graph.bytes(fields, sizeof fields);
    }
    out.graph = graph.value;
    return out;
}

void expectHashes(const core::Mesh& mesh, int width, int height, const Hashes& want) {
    for (unsigned threads : {1u, 2u}) {
        SCOPED_TRACE("threads " + std::to_string(threads));
        const Hashes got = build(mesh, width, height, threads);
        EXPECT_EQ(got.stack, want.stack) << std::hex << got.stack;
        EXPECT_EQ(got.planes, want.planes) << std::hex << got.planes;
        EXPECT_EQ(got.links, want.links) << std::hex << got.links;
        EXPECT_EQ(got.labels, want.labels) << std::hex << got.labels;
        EXPECT_EQ(got.graph, want.graph) << std::hex << got.graph;
    }
}

TEST(BuildHash, TrefoilMatchesTheReference) {
    expectHashes(core::makeTrefoil(), 1280, 720,
                 {0xff60a551fe3b6ae3, 0x21272581aa49d607, 0xde9bd31b4b27b4f6, 0x3dd0f4da13691b0,
                  0x32bb7bf32f77fe75});
}

TEST(BuildHash, EngineMatchesTheReference) {
    const std::string path = std::string(LAYERPAINT_ASSIMP_MODELS) +
                             "/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb";
    if (!std::filesystem::exists(path))
        GTEST_SKIP() << path << " is missing (assimp's model corpus)";
    const core::Result<core::Mesh> mesh = core::loadMesh(path);
    ASSERT_TRUE(mesh) << mesh.error();
    expectHashes(*mesh, 1920, 1080,
                 {0x903a70d6c4380a9, 0xa3a3d10e3d31ec12, 0x823cde271337379b, 0x530afd124c149a9a,
                  0x1c0179edf9bddc30});
}

} // namespace build_hash_test
