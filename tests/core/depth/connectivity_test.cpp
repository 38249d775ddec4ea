// SPDX-License-Identifier: GPL-3.0-or-later
// Connectivity on CPU-captured synthetic and built-in meshes; mesh topology; CPU capture; pixel
// rays. The golden cases are in segmentation_test.cpp.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <tuple>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include "core/depth/connectivity.h"
#include "core/depth/cpu_capture.h"
#include "core/depth/depth_stack.h"
#include "core/model/builtin_models.h"
#include "core/model/camera.h"
#include "core/model/mesh_topology.h"
#include "core/regions/segmentation.h"
#include "tests/core/captured_scenes.h"
#include "tests/core/test_scenes.h"

namespace connectivity_test {

using core::ConnectionTest;

using core_test::addGrid;
using core_test::captureScene;
using core_test::frontView;
using Scene = core_test::CapturedScene;

struct Result {
    core::Connectivity conn;
    core::Segmentation seg;
    core::ConnectivityQuality quality;
};

Result run(const Scene& s, ConnectionTest test, float threshold = 0.001f) {
    core::ConnectivityOptions options;
    options.test = test;
    options.threshold = threshold;
    options.unitScale = core::unitScale(s.mesh);
    options.threads = 2;
    Result r;
    r.conn = core::computeConnectivity(s.stack, options, &s.geometry);
    r.seg = core::segmentDepthLayers(s.stack, r.conn, 2);
    r.quality = core::measureConnectivity(s.stack, r.conn, s.topology);
    return r;
}

/** A unit plane (8 × 8 quads) facing +Z, turned about Y by `degrees` away from the viewer. */
core::Mesh tiltedPlane(float degrees) {
    core::Mesh mesh;
    const glm::mat4 turn = glm::rotate(glm::mat4(1.0f), glm::radians(degrees), glm::vec3(0, 1, 0));
    const glm::vec3 u = glm::vec3(turn * glm::vec4(1, 0, 0, 0));
    const glm::vec3 v(0, 1, 0);
    addGrid(mesh, -0.5f * u - 0.5f * v, u, v, 8);
    core_test::finishGrids(mesh);
    return mesh;
}

TEST(Connectivity, SteepPlaneStaysWholeWithSurfaceAndBreaksWithPlain) {
    for (bool ortho : {false, true}) {
        SCOPED_TRACE(ortho ? "orthographic" : "perspective");
        const Scene s = captureScene(tiltedPlane(85.0f), frontView(400, 400, ortho));
        ASSERT_EQ(s.stack.maxLayers(), 1u);
        ASSERT_GT(s.stack.fragmentCount(), 1000u);
        const Result surface = run(s, ConnectionTest::Surface);
        EXPECT_EQ(surface.seg.graph.regions.size(), 1u);
        EXPECT_EQ(surface.quality.sameTriangleDisconnected, 0u);
        EXPECT_EQ(surface.quality.adjacentTriangleDisconnected, 0u);
        EXPECT_EQ(surface.quality.crossComponentConnected, 0u);
        const Result plain = run(s, ConnectionTest::Plain);
        EXPECT_GT(plain.seg.graph.regions.size(), 10u);
        EXPECT_GT(plain.quality.sameTriangleDisconnectedShare(), 0.2);
    }
}

TEST(Connectivity, SurfaceKeepsAnySlopeShortOfGrazing) {
    for (float degrees : {0.0f, 45.0f, 70.0f, 80.0f, 87.0f}) {
        SCOPED_TRACE(degrees);
        const Scene s = captureScene(tiltedPlane(degrees), frontView(300, 300));
        const Result r = run(s, ConnectionTest::Surface);
        EXPECT_EQ(r.seg.graph.regions.size(), 1u);
        EXPECT_EQ(r.quality.sameTriangleDisconnected, 0u);
        EXPECT_EQ(r.quality.adjacentTriangleDisconnected, 0u);
    }
}

TEST(Connectivity, ParallelPartsCloserThanTheThresholdStayApart) {
    // Two parts 0.0005 unit-cube units apart (half the default threshold), overlapping in the
    // middle: the plain test joins them at the front part's border, the surface test does not.
    core::Mesh mesh;
    addGrid(mesh, {-0.5f, -0.5f, 0.0f}, {0.7f, 0, 0}, {0, 1.0f, 0}, 4);
    addGrid(mesh, {-0.2f, -0.5f, -0.0005f}, {0.7f, 0, 0}, {0, 1.0f, 0}, 4);
    core_test::finishGrids(mesh);
    const Scene s = captureScene(std::move(mesh), frontView(200, 200));
    ASSERT_EQ(s.topology.componentCount, 2u);
    ASSERT_EQ(s.stack.maxLayers(), 2u);
    const Result surface = run(s, ConnectionTest::Surface);
    EXPECT_EQ(surface.quality.crossComponentConnected, 0u);
    EXPECT_EQ(surface.quality.sameTriangleDisconnected, 0u);
    EXPECT_EQ(surface.seg.graph.regions.size(), 3u); // front part, back part (layers 1 and 2)
    const Result plain = run(s, ConnectionTest::Plain);
    EXPECT_GT(plain.quality.crossComponentConnected, 0u);
}

TEST(Connectivity, TouchingPartsInOnePlaneJoin) {
    // Two coplanar parts meeting along x = 0 without shared vertices (a T-junction-like seam):
    // true contact, so they join.
    core::Mesh mesh;
    addGrid(mesh, {-0.5f, -0.5f, 0.0f}, {0.5f, 0, 0}, {0, 1.0f, 0}, 3);
    addGrid(mesh, {0.0f, -0.4f, 0.0f}, {0.5f, 0, 0}, {0, 0.8f, 0}, 2);
    core_test::finishGrids(mesh);
    const Scene s = captureScene(std::move(mesh), frontView(160, 160));
    ASSERT_EQ(s.topology.componentCount, 2u);
    const Result surface = run(s, ConnectionTest::Surface);
    EXPECT_EQ(surface.seg.graph.regions.size(), 1u);
    EXPECT_GT(surface.quality.crossComponentConnected, 0u);
}

TEST(Connectivity, WithoutGeometrySurfaceFallsBackToPlain) {
    const Scene s = captureScene(tiltedPlane(60.0f), frontView(64, 64));
    core::ConnectivityOptions options;
    options.unitScale = core::unitScale(s.mesh);
    const core::Connectivity surface = core::computeConnectivity(s.stack, options, nullptr);
    options.test = ConnectionTest::Plain;
    const core::Connectivity plain = core::computeConnectivity(s.stack, options, &s.geometry);
    EXPECT_EQ(surface.links, plain.links);
}

TEST(Connectivity, BuiltinModelsKeepTrianglesWholeAndPartsApart) {
    struct Model {
        const char* name;
        core::Mesh mesh;
        unsigned smallTriangles; // 1 when no two pixels may share a triangle
    };
    std::vector<Model> models;
    models.push_back({"trefoil", core::makeTrefoil(), 1});
    models.push_back({"trefoil-coarse", core::makeTrefoil(100, 30), 0});
    models.push_back({"hexring", core::makeHexRing(), 0});
    models.push_back({"row", core::makeRow(), 0});
    const float views[][3] = {{0.0f, 0.0f, 2.0f}, {35.0f, 25.0f, 1.8f}, {120.0f, -40.0f, 2.5f}};
    for (Model& model : models) {
        const core::MeshTopology topology = core::buildMeshTopology(model.mesh);
        for (const auto& v : views) {
            SCOPED_TRACE(std::string(model.name) + " yaw " + std::to_string(v[0]));
            const core::View view =
                core::Camera::fromOrbit(model.mesh.bounds(), v[0], v[1], v[2]).view(320, 240);
            Scene s;
            s.mesh = model.mesh;
            s.topology = topology;
            s.view = view;
            s.stack = core::captureDepthLayersCpu(s.mesh, view, {true, 2});
            s.geometry = core::makeSurfaceGeometry(s.mesh, topology, view);
            ASSERT_GT(s.stack.fragmentCount(), 0u);
            const Result surface = run(s, ConnectionTest::Surface);
            // (The full trefoil's triangles are smaller than these pixels.)
            EXPECT_GT(surface.quality.sameTrianglePairs + model.smallTriangles, 0u);
            EXPECT_EQ(surface.quality.sameTriangleDisconnected, 0u);
            EXPECT_EQ(surface.quality.crossComponentConnected, 0u);
            EXPECT_LT(surface.quality.adjacentTriangleDisconnectedShare(), 0.01);
            const Result plain = run(s, ConnectionTest::Plain);
            EXPECT_LT(surface.seg.graph.regions.size(), plain.seg.graph.regions.size());
            std::printf(
                "[ quality  ] %-14s view (%4.0f,%4.0f,%.1f): surface same-tri %.5f adj %.5f "
                "cross %.5f regions %zu | plain same-tri %.5f adj %.5f cross %.5f "
                "regions %zu\n",
                model.name, v[0], v[1], v[2], surface.quality.sameTriangleDisconnectedShare(),
                surface.quality.adjacentTriangleDisconnectedShare(),
                surface.quality.crossComponentShare(), surface.seg.graph.regions.size(),
                plain.quality.sameTriangleDisconnectedShare(),
                plain.quality.adjacentTriangleDisconnectedShare(),
                plain.quality.crossComponentShare(), plain.seg.graph.regions.size());
        }
    }
}

TEST(Connectivity, LinksPointAtExistingFragments) {
    const Scene s =
        captureScene(core::makeTrefoil(80, 24),
                     core::Camera::fromOrbit(core::makeTrefoil(80, 24).bounds(), 10.0f, 60.0f, 2.0f)
                         .view(150, 110));
    for (ConnectionTest test : {ConnectionTest::Surface, ConnectionTest::Plain}) {
        const Result r = run(s, test);
        const int w = s.stack.width, h = s.stack.height;
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const std::size_t p = std::size_t(y) * std::size_t(w) + std::size_t(x);
                for (std::uint32_t f = s.stack.offsets[p]; f < s.stack.offsets[p + 1]; ++f) {
                    const int neighbours[4][2] = {{x + 1, y}, {x - 1, y}, {x, y - 1}, {x, y + 1}};
                    for (int d = 0; d < 4; ++d) {
                        const std::uint32_t l = r.conn.link(f, d);
                        const int nx = neighbours[d][0], ny = neighbours[d][1];
                        if (nx < 0 || ny < 0 || nx >= w || ny >= h) {
                            EXPECT_EQ(l, 0u);
                            continue;
                        }
                        const std::size_t q = std::size_t(ny) * std::size_t(w) + std::size_t(nx);
                        EXPECT_LE(l, s.stack.layerCount(q));
                    }
                }
            }
    }
}

TEST(Connectivity, DeepPixelsBatchedGiveTheSameLinksAsOneByOne) {
    // Deep pixels of random triangles, made so that every case of the Surface test occurs:
    // planes through a few shared points at random angles (so they cross between pixels),
    // grazing and degenerate planes, triangles out of range, three mesh parts and a part
    // unknown, corners drawn from a small pool (shared often) or unknown, and depths on, near
    // or off the planes.
    const int w = 28, h = 20, triangles = 60;
    const core::View view = frontView(w, h);
    std::mt19937 rng(20261129);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    core::SurfaceGeometry geometry;
    geometry.rays = core::PixelRays::fromView(view);
    const auto rayAt = [&](float px, float py) {
        return std::pair(geometry.rays.origin(px, py), geometry.rays.direction(px, py));
    };
    const auto randomUnit = [&] {
        glm::vec3 v;
        do
            v = glm::vec3(unit(rng), unit(rng), unit(rng)) * 2.0f - 1.0f;
        while (glm::dot(v, v) < 0.01f || glm::dot(v, v) > 1.0f);
        return glm::normalize(v);
    };
    std::vector<glm::vec3> anchors;
    for (int k = 0; k < 5; ++k) {
        const auto [o, d] = rayAt(unit(rng) * float(w), unit(rng) * float(h));
        anchors.push_back(o + (1.8f + 0.4f * unit(rng)) * d);
    }
    for (int t = 0; t < triangles; ++t) {
        core::SurfaceTriangle tri;
        const glm::vec3 at = anchors[std::size_t(t) % anchors.size()];
        glm::vec3 normal = randomUnit();
        if (t % 11 == 3) // grazing: along the view direction
            normal =
                glm::normalize(glm::cross(rayAt(float(w) / 2, float(h) / 2).second, randomUnit()));
        if (t % 13 != 5) // else degenerate: a zero plane
            tri.plane = glm::vec4(normal, -glm::dot(normal, at));
        tri.component = t % 7 == 6 ? core::kNone : std::uint32_t(t % 3);
        for (std::uint32_t& corner : tri.corners)
            corner = std::uint32_t(rng() % 24);
        if (t % 9 == 4)
            tri.corners[0] = core::kNone;
        geometry.triangles.push_back(tri);
    }
    core::DepthStack stack;
    stack.width = w;
    stack.height = h;
    stack.offsets.push_back(0);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            // Up to 19 fragments: groups of four and of eight lanes, whole and in part.
            const std::uint32_t layers = std::uint32_t(rng() % 20);
            std::vector<std::pair<float, std::uint32_t>> fragments;
            for (std::uint32_t k = 0; k < layers; ++k) {
                const auto t = std::uint32_t(rng() % std::uint32_t(triangles + 4));
                float depth = 1.5f + unit(rng);
                if (t < std::uint32_t(triangles)) {
                    const glm::vec4 plane = geometry.triangles[t].plane;
                    const auto [o, d] = rayAt(float(x) + 0.5f, float(y) + 0.5f);
                    const float onPlane =
                        -(plane.w + glm::dot(glm::vec3(plane), o)) / glm::dot(glm::vec3(plane), d);
                    const float off[] = {0.0f, 1e-4f, 3e-3f, 0.05f};
                    if (std::isfinite(onPlane) && onPlane > 0.5f && onPlane < 4.0f)
                        depth = onPlane + off[rng() % 4] * (unit(rng) < 0.5f ? -1.0f : 1.0f);
                }
                fragments.emplace_back(depth, t);
            }
            std::sort(fragments.begin(), fragments.end());
            for (const auto& [depth, t] : fragments) {
                stack.depth.push_back(depth);
                stack.triangle.push_back(t);
            }
            stack.offsets.push_back(std::uint32_t(stack.depth.size()));
        }
    for (float threshold : {0.002f, 0.02f}) {
        core::ConnectivityOptions options;
        options.threshold = threshold;
        options.contactFactor = 0.5f;
        options.threads = 1;
        const core::Connectivity batched = core::computeConnectivity(stack, options, &geometry);
        options.wideLanes = false;
        const core::Connectivity fourLanes = core::computeConnectivity(stack, options, &geometry);
        options.batchDeepPixels = false;
        const core::Connectivity oneByOne = core::computeConnectivity(stack, options, &geometry);
        const auto linked = std::count_if(oneByOne.links.begin(), oneByOne.links.end(),
                                          [](std::uint8_t l) { return l != 0; });
        EXPECT_GT(linked, std::ptrdiff_t(oneByOne.links.size() / 20)) << threshold;
        EXPECT_TRUE(batched.links == oneByOne.links) << "threshold " << threshold;
        EXPECT_TRUE(fourLanes.links == oneByOne.links) << "threshold " << threshold;
    }
}

// ---------------------------------------------------------------------------------------------

TEST(SurfaceGeometry, WithAStackOnlyTheShownTrianglesGetPlanes) {
    // A view showing a good share of the mesh finds entries through a word per mesh triangle; a
    // small one, with fewer fragments than an eighth of the triangles, through a table.
    for (const auto& [segments, width, height, sparse] :
         {std::tuple{60, 120, 80, false}, {240, 48, 32, true}}) {
        SCOPED_TRACE(std::to_string(segments) + " segments, " + std::to_string(width) + "x" +
                     std::to_string(height));
        const core::Mesh mesh = core::makeTrefoil(segments, segments * 2 / 5);
        const core::MeshTopology topology = core::buildMeshTopology(mesh);
        const core::Camera camera = core::Camera::fromOrbit(mesh.bounds(), 30.0f, 20.0f, 2.0f);
        const core::View view = camera.view(width, height);
        const core::DepthStack stack = core::captureDepthLayersCpu(mesh, view, {true, 2});
        const core::SurfaceGeometry all = core::makeSurfaceGeometry(mesh, topology, view);
        const core::SurfaceGeometry shown = core::makeSurfaceGeometry(mesh, topology, view, &stack);
        ASSERT_EQ(sparse, 8 * stack.fragmentCount() < mesh.triangleCount());
        EXPECT_EQ(shown.entry.size(), sparse ? 0 : mesh.triangleCount());
        EXPECT_EQ(shown.entryTable.empty(), !sparse);
        std::vector<bool> inView(mesh.triangleCount(), false);
        for (std::uint32_t t : stack.triangle)
            inView[t] = true;
        std::size_t computed = 0, skipped = 0;
        for (std::uint32_t t = 0; t < mesh.triangleCount(); ++t) {
            const core::SurfaceTriangle* got = shown.find(t);
            if (inView[t]) {
                ++computed;
                ASSERT_NE(got, nullptr) << "triangle " << t;
                EXPECT_EQ(got->plane, all.triangles[t].plane) << "triangle " << t;
                EXPECT_EQ(got->corners, all.triangles[t].corners) << "triangle " << t;
                EXPECT_EQ(got->component, all.triangles[t].component) << "triangle " << t;
            } else {
                ++skipped;
                EXPECT_EQ(got, nullptr) << "triangle " << t;
            }
        }
        EXPECT_EQ(shown.find(core::kNone), nullptr);
        EXPECT_EQ(shown.find(std::uint32_t(mesh.triangleCount())), nullptr);
        // Only the shown triangles are kept, each fragment finds its own.
        EXPECT_EQ(shown.triangles.size(), computed);
        EXPECT_GT(computed, 100u);
        EXPECT_GT(skipped, 100u); // back faces and hidden sides are skipped
        for (std::size_t f = 0; f < stack.fragmentCount(); ++f)
            ASSERT_EQ(shown.fragmentEntry[f], shown.entryOf(stack.triangle[f])) << "fragment " << f;
        // The same links as with every triangle's plane.
        core::ConnectivityOptions options;
        options.unitScale = core::unitScale(mesh);
        EXPECT_EQ(core::computeConnectivity(stack, options, &shown).links,
                  core::computeConnectivity(stack, options, &all).links);
    }
}

TEST(SurfaceGeometry, PlanesAreTheViewSpaceTrianglesPlanesForAnyViewMatrix) {
    // The planes come from the mesh's own planes (MeshTopology::planes) through the view matrix;
    // each must be the plane of the triangle's corners taken to view space, for a camera's view
    // and for mirrored, scaled and sheared ones, with and without the topology's planes.
    const core::Mesh mesh = core::makeTrefoil(40, 16);
    core::MeshTopology topology = core::buildMeshTopology(mesh);
    ASSERT_EQ(topology.planes.size(), mesh.triangleCount());
    core::MeshTopology withoutPlanes = topology;
    withoutPlanes.planes.clear();
    const core::View cameraView =
        core::Camera::fromOrbit(mesh.bounds(), 30.0f, 20.0f, 2.0f).view(120, 80);
    const glm::mat4 shear(1.0f, 0.0f, 0.0f, 0.0f, 0.4f, 1.0f, 0.0f, 0.0f, 0.0f, 0.0f, 1.0f, 0.0f,
                          0.0f, 0.0f, 0.0f, 1.0f);
    const glm::mat4 models[] = {glm::mat4(1.0f), glm::scale(glm::mat4(1.0f), glm::vec3(3.0f)),
                                glm::scale(glm::mat4(1.0f), glm::vec3(-1.0f, 1.0f, 1.0f)),
                                glm::scale(glm::mat4(1.0f), glm::vec3(2.0f, 1.0f, 0.5f)), shear};
    for (const glm::mat4& model : models)
        for (const core::MeshTopology* topo : {&topology, &withoutPlanes}) {
            core::View view = cameraView;
            view.view = cameraView.view * model;
            const glm::dmat4 toView(view.view);
            const core::SurfaceGeometry geometry = core::makeSurfaceGeometry(mesh, *topo, view);
            ASSERT_EQ(geometry.triangles.size(), mesh.triangleCount());
            for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
                glm::dvec3 v[3];
                for (int c = 0; c < 3; ++c)
                    v[c] = glm::dvec3(
                        toView *
                        glm::dvec4(glm::dvec3(mesh.positions[mesh.indices[3 * t + c]]), 1.0));
                const glm::dvec3 n = glm::normalize(glm::cross(v[1] - v[0], v[2] - v[0]));
                const glm::dvec3 centroid = (v[0] + v[1] + v[2]) / 3.0;
                const glm::vec4 got = geometry.triangles[t].plane;
                ASSERT_LT(glm::length(glm::dvec3(got) - n), 1e-4) << "triangle " << t;
                ASSERT_LT(std::abs(glm::dot(glm::dvec3(got), centroid) + double(got.w)),
                          1e-5 * glm::length(centroid))
                    << "triangle " << t;
            }
        }
}

TEST(PixelRays, MatchViewUnproject) {
    core::Camera camera;
    camera.frame({glm::vec3(-0.5f), glm::vec3(0.5f)});
    camera.orbit(30.0f, 20.0f);
    for (bool ortho : {false, true}) {
        camera.orthographic = ortho;
        const core::View view = camera.view(320, 200);
        const core::PixelRays rays = core::PixelRays::fromView(view);
        for (glm::vec2 pixel : {glm::vec2(0.5f, 0.5f), glm::vec2(160.0f, 100.0f),
                                glm::vec2(319.5f, 12.25f), glm::vec2(7.0f, 199.5f)}) {
            for (float depth : {1.0f, 1.7f, 2.9f}) {
                const glm::vec3 world = view.unproject(pixel, depth);
                const glm::vec3 expected = glm::vec3(view.view * glm::vec4(world, 1.0f));
                const glm::vec3 got =
                    rays.origin(pixel.x, pixel.y) + depth * rays.direction(pixel.x, pixel.y);
                EXPECT_NEAR(glm::distance(got, expected), 0.0f, 1e-4f)
                    << (ortho ? "ortho " : "perspective ") << pixel.x << "," << pixel.y;
            }
        }
    }
}

// ---------------------------------------------------------------------------------------------

TEST(MeshTopology, WeldsSeamDuplicatesAndFindsComponents) {
    core::Mesh mesh;
    // A quad whose two triangles do not share vertex indices (a UV seam on the diagonal).
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    mesh.indices = {0, 1, 2, 3, 4, 5};
    // A second, separate triangle; one vertex a hair off a cell border from its twin.
    mesh.positions.push_back({3, 0, 0});
    mesh.positions.push_back({4, 0, 0});
    mesh.positions.push_back({3, 1, 0});
    mesh.positions.push_back({4.0000001f, 0, 0});
    mesh.positions.push_back({4, 1, 0});
    mesh.indices.insert(mesh.indices.end(), {6, 7, 8, 9, 10, 8});
    core_test::finishGrids(mesh);
    const core::MeshTopology topo = core::buildMeshTopology(mesh);
    EXPECT_EQ(topo.weldedVertexCount, 8u);
    EXPECT_EQ(topo.weldedVertex[3], topo.weldedVertex[0]);
    EXPECT_EQ(topo.weldedVertex[4], topo.weldedVertex[2]);
    EXPECT_EQ(topo.weldedVertex[9], topo.weldedVertex[7]);
    EXPECT_EQ(topo.componentCount, 2u);
    EXPECT_EQ(topo.component, (std::vector<std::uint32_t>{0, 0, 1, 1}));
    EXPECT_EQ(topo.sharedCorners(0, 1), 2);
    EXPECT_EQ(topo.sharedCorners(0, 2), 0);
    EXPECT_EQ(topo.edgeNeighbors[0][2], 1u); // edge (corner 2, corner 0) is the diagonal
    EXPECT_EQ(topo.edgeNeighbors[0][0], core::kNone);
}

TEST(MeshTopology, DistinctPointsStayApart) {
    core::Mesh mesh;
    addGrid(mesh, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 2);
    addGrid(mesh, {0, 0, 0.0005f}, {1, 0, 0}, {0, 1, 0}, 2);
    core_test::finishGrids(mesh);
    const core::MeshTopology topo = core::buildMeshTopology(mesh);
    EXPECT_EQ(topo.weldedVertexCount, 18u);
    EXPECT_EQ(topo.componentCount, 2u);
}

TEST(MeshTopology, TrefoilIsOneClosedComponent) {
    const core::Mesh mesh = core::makeTrefoil(60, 16);
    const core::MeshTopology topo = core::buildMeshTopology(mesh);
    EXPECT_EQ(topo.componentCount, 1u);
    for (const auto& n : topo.edgeNeighbors)
        for (std::uint32_t t : n)
            EXPECT_NE(t, core::kNone);
}

// ---------------------------------------------------------------------------------------------

TEST(CpuCapture, CoversEachPixelOfASplitQuadOnce) {
    core::Mesh mesh;
    addGrid(mesh, {-0.6f, -0.45f, 0.0f}, {1.2f, 0, 0}, {0, 0.9f, 0}, 5);
    core_test::finishGrids(mesh);
    const core::View view = frontView(97, 61, true);
    const core::DepthStack stack = core::captureDepthLayersCpu(mesh, view, {true, 3});
    ASSERT_EQ(stack.offsets.size(), stack.pixelCount() + 1);
    EXPECT_EQ(stack.maxLayers(), 1u);
    // Every pixel centre inside the quad's projection is covered.
    const glm::vec3 lo = view.project({-0.6f, -0.45f, 0.0f}), hi = view.project({0.6f, 0.45f, 0});
    for (int y = 0; y < stack.height; ++y)
        for (int x = 0; x < stack.width; ++x) {
            const float cx = float(x) + 0.5f, cy = float(y) + 0.5f;
            const bool inside =
                cx > lo.x + 0.01f && cx < hi.x - 0.01f && cy > hi.y + 0.01f && cy < lo.y - 0.01f;
            if (inside) {
                EXPECT_EQ(stack.layerCount(std::size_t(y) * stack.width + x), 1u) << x << "," << y;
            }
        }
    for (float d : stack.depth)
        EXPECT_NEAR(d, 2.0f, 1e-5f);
}

TEST(CpuCapture, CullsBackFacesUnlessTwoSided) {
    core::Mesh mesh;
    addGrid(mesh, {0.5f, -0.5f, 0.0f}, {-1.0f, 0, 0}, {0, 1.0f, 0}, 1); // faces -Z
    core_test::finishGrids(mesh);
    const core::View view = frontView(40, 40);
    EXPECT_EQ(core::captureDepthLayersCpu(mesh, view, {true, 1}).fragmentCount(), 0u);
    EXPECT_GT(core::captureDepthLayersCpu(mesh, view, {false, 1}).fragmentCount(), 0u);
}

TEST(CpuCapture, PerspectiveDepthIsThePlaneDepthAndThreadsDoNotMatter) {
    const core::Mesh mesh = tiltedPlane(60.0f);
    const core::View view = frontView(90, 70);
    const core::DepthStack a = core::captureDepthLayersCpu(mesh, view, {true, 1});
    const core::DepthStack b = core::captureDepthLayersCpu(mesh, view, {true, 4});
    EXPECT_EQ(a.offsets, b.offsets);
    EXPECT_EQ(a.depth, b.depth);
    EXPECT_EQ(a.triangle, b.triangle);
    // The surface point at each pixel lies on the plane through the origin with normal n.
    const glm::vec3 n =
        glm::vec3(glm::rotate(glm::mat4(1.0f), glm::radians(60.0f), glm::vec3(0, 1, 0)) *
                  glm::vec4(0, 0, 1, 0));
    ASSERT_GT(a.fragmentCount(), 100u);
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x) {
            const std::size_t p = std::size_t(y) * a.width + x;
            if (a.layerCount(p) == 1) {
                const glm::vec3 world = view.unproject({x + 0.5f, y + 0.5f}, a.depth[a.offsets[p]]);
                EXPECT_NEAR(glm::dot(world, n), 0.0f, 1e-4f);
            }
        }
}

TEST(DepthStack, CountsLayers) {
    core::DepthStack stack;
    stack.width = 3;
    stack.height = 1;
    stack.offsets = {0, 2, 2, 5};
    stack.depth = {1, 2, 1, 2, 3};
    stack.triangle = {0, 1, 0, 1, 2};
    EXPECT_EQ(stack.maxLayers(), 3u);
    EXPECT_EQ(stack.fragmentsPerLayer(), (std::vector<std::uint32_t>{2, 2, 1}));
    EXPECT_EQ(stack.fragment(2, 3), 4u);
    EXPECT_EQ(stack.fragment(1, 1), core::kNone);
    EXPECT_EQ(core::DepthStack{}.maxLayers(), 0u);
    EXPECT_TRUE(core::DepthStack{}.fragmentsPerLayer().empty());
}

} // namespace connectivity_test
