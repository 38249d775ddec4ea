// SPDX-License-Identifier: GPL-3.0-or-later
// Golden cases for connectivity, segmentation and the region graph (tests/data/seg_*/), plus
// determinism and structural checks on CPU-captured meshes.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/depth/connectivity.h"
#include "core/depth/cpu_capture.h"
#include "core/model/builtin_models.h"
#include "core/model/camera.h"
#include "core/model/mesh_topology.h"
#include "core/regions/segmentation.h"
#include "tests/core/golden_cases.h"

namespace segmentation_test {

namespace fs = std::filesystem;
using nlohmann::json;

using core_test::tokens;

/**
 * One golden case, read from tests/data/<case>/segmentation.json. The view is orthographic with
 * unit pixels: window position (px, py) looks along -Z from (px, -py, 0). A plane [a, bx, by]
 * has depth a + bx·x + by·y at the centre of pixel (x, y). Grids are rows of tokens, "." for
 * "no fragment"; links are 4 digits R, L, U, D.
 */
struct GoldenCase {
    std::string name;
    std::string error; // non-empty when the file is malformed
    core::DepthStack stack;
    core::ConnectivityOptions options;
    core::SurfaceGeometry geometry;
    std::vector<std::string> links;     // per fragment, "RLUD"
    std::vector<std::uint32_t> regions; // per fragment
    std::vector<core::Region> graphRegions;
    std::vector<std::vector<core::RegionLink>> graphNeighbors;
};

GoldenCase loadCase(const fs::path& file) {
    GoldenCase c;
    c.name = file.parent_path().filename().string();
    try {
        std::ifstream in(file);
        const json j = json::parse(in);
        const int w = j.at("width"), h = j.at("height");
        c.options.test =
            j.at("test") == "plain" ? core::ConnectionTest::Plain : core::ConnectionTest::Surface;
        c.options.threshold = j.at("threshold");
        c.options.unitScale = 1.0f;
        c.options.contactFactor = j.value("contactFactor", c.options.contactFactor);
        // Orthographic unit-pixel rays: origin (px, -py, 0), direction (0, 0, -1).
        c.geometry.rays.originDx = {1.0f, 0.0f, 0.0f};
        c.geometry.rays.originDy = {0.0f, -1.0f, 0.0f};
        const auto& planes = j.at("planes");
        for (std::size_t t = 0; t < planes.size(); ++t) {
            const double a = planes[t][0], bx = planes[t][1], by = planes[t][2];
            // depth = a + bx (px - 0.5) + by (py - 0.5) with view point (px, -py, -depth).
            const glm::dvec3 n(-bx, by, -1.0);
            const double offset = -(a - 0.5 * bx - 0.5 * by), len = glm::length(n);
            core::SurfaceTriangle tri;
            tri.plane = glm::vec4(glm::vec3(n / len), float(offset / len));
            if (j.contains("corners"))
                for (int k = 0; k < 3; ++k)
                    tri.corners[k] = j["corners"][t][k];
            if (j.contains("components"))
                tri.component = j["components"][t];
            c.geometry.triangles.push_back(tri);
        }
        auto depthOf = [&](std::uint32_t t, int x, int y) {
            return float(double(planes[t][0]) + double(planes[t][1]) * x +
                         double(planes[t][2]) * y);
        };
        const auto& layers = j.at("layers");
        const auto& expected = j.at("expected");
        // Per pixel, the fragments layer by layer (the layer property is checked here).
        c.stack.width = w;
        c.stack.height = h;
        c.stack.offsets.push_back(0);
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                bool gap = false;
                for (std::size_t k = 0; k < layers.size(); ++k) {
                    const auto row = tokens(layers[k].at("triangle")[std::size_t(y)]);
                    const auto linkRow = tokens(expected.at("links")[k][std::size_t(y)]);
                    const auto regionRow = tokens(expected.at("regions")[k][std::size_t(y)]);
                    if (row.size() != std::size_t(w) || linkRow.size() != std::size_t(w) ||
                        regionRow.size() != std::size_t(w))
                        throw std::runtime_error("row " + std::to_string(y) + " of layer " +
                                                 std::to_string(k + 1) + " has a wrong width");
                    const std::string& t = row[std::size_t(x)];
                    if (t == ".") {
                        gap = true;
                        continue;
                    }
                    if (gap)
                        throw std::runtime_error("layer property broken at pixel " +
                                                 std::to_string(x) + "," + std::to_string(y));
                    const auto tri = std::uint32_t(std::stoul(t));
                    c.stack.triangle.push_back(tri);
                    c.stack.depth.push_back(depthOf(tri, x, y));
                    c.links.push_back(linkRow[std::size_t(x)]);
                    c.regions.push_back(std::uint32_t(std::stoul(regionRow[std::size_t(x)])));
                }
                c.stack.offsets.push_back(std::uint32_t(c.stack.depth.size()));
            }
        for (const auto& r : expected.at("graph")) {
            core::Region region;
            region.id = std::uint32_t(c.graphRegions.size());
            region.layer = r.at("layer");
            region.pixels = r.at("pixels");
            region.minX = r.at("bbox")[0];
            region.minY = r.at("bbox")[1];
            region.maxX = r.at("bbox")[2];
            region.maxY = r.at("bbox")[3];
            c.graphRegions.push_back(region);
            std::vector<core::RegionLink> neighbors;
            for (const auto& n : r.at("neighbors"))
                neighbors.push_back({n[0], n[1]});
            c.graphNeighbors.push_back(neighbors);
        }
    } catch (const std::exception& e) {
        c.error = e.what();
    }
    return c;
}

std::string linkString(const core::Connectivity& conn, std::size_t f) {
    std::string s;
    for (int d = 0; d < 4; ++d)
        s += std::to_string(int(conn.link(f, d)));
    return s;
}

class Golden : public testing::TestWithParam<fs::path> {};

TEST_P(Golden, LinksRegionsAndGraphMatch) {
    const GoldenCase c = loadCase(GetParam());
    ASSERT_TRUE(c.error.empty()) << GetParam() << ": " << c.error;
    for (unsigned threads : {1u, 3u}) {
        SCOPED_TRACE("threads " + std::to_string(threads));
        core::ConnectivityOptions options = c.options;
        options.threads = threads;
        const core::Connectivity conn = core::computeConnectivity(c.stack, options, &c.geometry);
        ASSERT_EQ(conn.links.size(), 4 * c.stack.fragmentCount());
        EXPECT_FALSE(conn.truncated);
        for (int y = 0; y < c.stack.height; ++y)
            for (int x = 0; x < c.stack.width; ++x) {
                const std::size_t p = std::size_t(y) * std::size_t(c.stack.width) + std::size_t(x);
                for (std::uint32_t k = 1; k <= c.stack.layerCount(p); ++k) {
                    const std::size_t f = c.stack.offsets[p] + k - 1;
                    EXPECT_EQ(linkString(conn, f), c.links[f])
                        << "links of pixel " << x << "," << y << " layer " << k;
                }
            }
        const core::Segmentation seg = core::segmentDepthLayers(c.stack, conn, threads);
        EXPECT_EQ(seg.region, c.regions);
        ASSERT_EQ(seg.graph.regions.size(), c.graphRegions.size());
        for (std::size_t r = 0; r < c.graphRegions.size(); ++r) {
            const core::Region& got = seg.graph.regions[r];
            const core::Region& want = c.graphRegions[r];
            EXPECT_EQ(got.id, want.id);
            EXPECT_EQ(got.layer, want.layer) << "region " << r;
            EXPECT_EQ(got.pixels, want.pixels) << "region " << r;
            EXPECT_EQ(std::vector<int>({got.minX, got.minY, got.maxX, got.maxY}),
                      std::vector<int>({want.minX, want.minY, want.maxX, want.maxY}))
                << "bbox of region " << r;
            const auto n = seg.graph.neighborsOf(std::uint32_t(r));
            EXPECT_EQ(std::vector<core::RegionLink>(n.begin(), n.end()), c.graphNeighbors[r])
                << "neighbours of region " << r;
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Cases, Golden,
                         testing::ValuesIn(core_test::goldenFiles("segmentation.json")),
                         core_test::goldenTestName);

TEST(GoldenData, AllExpectedCasesArePresent) {
    const std::vector<std::string> names = core_test::goldenCaseNames("segmentation.json");
    for (const char* want :
         {"seg_flat_single_layer", "seg_two_overlapping_surfaces", "seg_figure3_behind",
          "seg_fold_plain", "seg_fold_surface", "seg_steep_slope_plain", "seg_steep_slope_surface",
          "seg_near_parallel_plain", "seg_near_parallel_surface"})
        EXPECT_NE(std::find(names.begin(), names.end(), want), names.end()) << want;
}

// ---------------------------------------------------------------------------------------------
// Structural checks on captured meshes.

struct Captured {
    core::Mesh mesh;
    core::MeshTopology topology;
    core::View view;
    core::DepthStack stack;
    core::SurfaceGeometry geometry;
    core::ConnectivityOptions options;
};

Captured capture(core::Mesh mesh, float yaw, float pitch, float distance, int w, int h) {
    Captured c;
    c.mesh = std::move(mesh);
    c.topology = core::buildMeshTopology(c.mesh);
    const core::Camera camera = core::Camera::fromOrbit(c.mesh.bounds(), yaw, pitch, distance);
    c.view = camera.view(w, h);
    c.stack = core::captureDepthLayersCpu(c.mesh, c.view, {true, 2});
    c.geometry = core::makeSurfaceGeometry(c.mesh, c.topology, c.view);
    c.options.unitScale = core::unitScale(c.mesh);
    return c;
}

TEST(Segmentation, SameOutputForAnyThreadCount) {
    Captured c = capture(core::makeTrefoil(60, 24), 120.0f, -40.0f, 2.0f, 160, 97);
    ASSERT_GT(c.stack.maxLayers(), 2u);
    for (core::ConnectionTest test : {core::ConnectionTest::Surface, core::ConnectionTest::Plain}) {
        c.options.test = test;
        c.options.threads = 1;
        const core::Connectivity reference =
            core::computeConnectivity(c.stack, c.options, &c.geometry);
        const core::Segmentation refSeg = core::segmentDepthLayers(c.stack, reference, 1);
        ASSERT_GT(refSeg.graph.regions.size(), 1u);
        // 64: bands of rows with equal fragment counts, some of them empty.
        for (unsigned threads : {2u, 7u, 64u}) {
            c.options.threads = threads;
            const core::Connectivity conn =
                core::computeConnectivity(c.stack, c.options, &c.geometry);
            EXPECT_EQ(conn.links, reference.links) << threads << " threads";
            const core::Segmentation seg = core::segmentDepthLayers(c.stack, conn, threads);
            EXPECT_EQ(seg.region, refSeg.region) << threads << " threads";
            EXPECT_EQ(seg.graph.neighborOffsets, refSeg.graph.neighborOffsets);
            EXPECT_EQ(seg.graph.neighbors, refSeg.graph.neighbors);
            ASSERT_EQ(seg.graph.regions.size(), refSeg.graph.regions.size());
            for (std::size_t r = 0; r < seg.graph.regions.size(); ++r) {
                EXPECT_EQ(seg.graph.regions[r].pixels, refSeg.graph.regions[r].pixels);
                EXPECT_EQ(seg.graph.regions[r].minX, refSeg.graph.regions[r].minX);
                EXPECT_EQ(seg.graph.regions[r].maxY, refSeg.graph.regions[r].maxY);
            }
        }
    }
}

TEST(Segmentation, RegionsAreSameLayerComponentsOrderedByLayerThenScan) {
    Captured c = capture(core::makeHexRing(24), 20.0f, 35.0f, 2.0f, 120, 90);
    const core::Connectivity conn = core::computeConnectivity(c.stack, c.options, &c.geometry);
    const core::Segmentation seg = core::segmentDepthLayers(c.stack, conn, 3);
    const core::RegionGraph& g = seg.graph;
    const int w = c.stack.width;
    std::vector<std::uint32_t> firstSeen(g.regions.size(), core::kNone);
    std::vector<std::uint32_t> pixels(g.regions.size(), 0);
    for (std::size_t p = 0; p < c.stack.pixelCount(); ++p)
        for (std::uint32_t k = 1; k <= c.stack.layerCount(p); ++k) {
            const std::uint32_t f = c.stack.offsets[p] + k - 1;
            const std::uint32_t r = seg.region[f];
            ASSERT_LT(r, g.regions.size());
            EXPECT_EQ(g.regions[r].layer, k);
            ++pixels[r];
            if (firstSeen[r] == core::kNone)
                firstSeen[r] = std::uint32_t(p);
            // Same-layer links never cross a region border; cross-layer links are graph edges.
            const int x = int(p % std::size_t(w)), y = int(p / std::size_t(w));
            for (int d = 0; d < 4; ++d) {
                const std::uint32_t l = conn.link(f, d);
                if (l == 0)
                    continue;
                const int nx = x + (d == core::kRight) - (d == core::kLeft);
                const int ny = y + (d == core::kDown) - (d == core::kUp);
                const std::size_t q = std::size_t(ny) * std::size_t(w) + std::size_t(nx);
                const std::uint32_t g2 = c.stack.fragment(q, l);
                ASSERT_NE(g2, core::kNone);
                if (l == k) {
                    EXPECT_EQ(seg.region[g2], r);
                } else {
                    const auto n = g.neighborsOf(r);
                    EXPECT_TRUE(std::any_of(n.begin(), n.end(), [&](const core::RegionLink& e) {
                        return e.region == seg.region[g2] && e.links > 0;
                    }));
                }
            }
        }
    for (std::size_t r = 0; r < g.regions.size(); ++r) {
        EXPECT_EQ(g.regions[r].id, r);
        EXPECT_EQ(g.regions[r].pixels, pixels[r]);
        if (r > 0) {
            const auto& a = g.regions[r - 1];
            const auto& b = g.regions[r];
            EXPECT_TRUE(a.layer < b.layer ||
                        (a.layer == b.layer && firstSeen[r - 1] < firstSeen[r]))
                << "region order at " << r;
        }
        // Edges are symmetric and sorted.
        const auto n = g.neighborsOf(std::uint32_t(r));
        for (std::size_t i = 0; i < n.size(); ++i) {
            if (i > 0) {
                EXPECT_LT(n[i - 1].region, n[i].region);
            }
            const auto back = g.neighborsOf(n[i].region);
            EXPECT_TRUE(std::any_of(back.begin(), back.end(), [&](const core::RegionLink& e) {
                return e.region == r && e.links == n[i].links;
            }));
        }
    }
}

TEST(Segmentation, LayerPropertyHoldsByConstruction) {
    Captured c = capture(core::makeRow(16), 0.0f, 5.0f, 2.5f, 100, 60);
    const auto perLayer = c.stack.fragmentsPerLayer();
    ASSERT_EQ(perLayer.size(), c.stack.maxLayers());
    ASSERT_GT(perLayer.size(), 3u); // four bodies one behind another
    for (std::size_t k = 1; k < perLayer.size(); ++k)
        EXPECT_LE(perLayer[k], perLayer[k - 1]);
    std::uint64_t total = 0;
    for (std::uint32_t n : perLayer)
        total += n;
    EXPECT_EQ(total, c.stack.fragmentCount());
    // Front to back at every pixel.
    for (std::size_t p = 0; p < c.stack.pixelCount(); ++p)
        for (std::uint32_t f = c.stack.offsets[p] + 1; f < c.stack.offsets[p + 1]; ++f)
            EXPECT_LE(c.stack.depth[f - 1], c.stack.depth[f]);
}

TEST(Segmentation, MismatchedInputGivesAnEmptyResult) {
    core::DepthStack stack;
    stack.width = 2;
    stack.height = 1;
    stack.offsets = {0, 1, 2};
    stack.depth = {1.0f, 1.0f};
    stack.triangle = {0, 0};
    core::Connectivity conn; // wrong size
    const core::Segmentation seg = core::segmentDepthLayers(stack, conn);
    EXPECT_TRUE(seg.region.empty());
    EXPECT_TRUE(seg.graph.regions.empty());
    ASSERT_EQ(seg.graph.neighborOffsets.size(), 1u);
}

TEST(Segmentation, FragmentsBeyondLayer255AreUnlinkedSingletons) {
    // Two pixels with 300 coincident fragments each: layers 1..255 link straight across.
    core::DepthStack stack;
    stack.width = 2;
    stack.height = 1;
    const std::uint32_t n = 300;
    stack.offsets = {0, n, 2 * n};
    for (int p = 0; p < 2; ++p)
        for (std::uint32_t k = 0; k < n; ++k) {
            stack.depth.push_back(1.0f + 0.01f * float(k));
            stack.triangle.push_back(k);
        }
    core::ConnectivityOptions options;
    options.test = core::ConnectionTest::Plain;
    const core::Connectivity conn = core::computeConnectivity(stack, options);
    EXPECT_TRUE(conn.truncated);
    EXPECT_EQ(conn.link(0, core::kRight), 1);
    EXPECT_EQ(conn.link(254, core::kRight), 255);
    EXPECT_EQ(conn.link(255, core::kRight), 0);
    EXPECT_EQ(conn.link(n + 254, core::kLeft), 255);
    const core::Segmentation seg = core::segmentDepthLayers(stack, conn, 2);
    // 255 two-pixel regions plus 2 × 45 singletons.
    EXPECT_EQ(seg.graph.regions.size(), 255u + 2u * 45u);
    EXPECT_EQ(seg.region[0], seg.region[n]);
    EXPECT_NE(seg.region[255], seg.region[n + 255]);
}

} // namespace segmentation_test
