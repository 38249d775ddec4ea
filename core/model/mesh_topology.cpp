// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/model/mesh_topology.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <unordered_map>
#include <utility>

#include <glm/geometric.hpp>

#include "core/base/index.h"
#include "core/base/parallel.h"

namespace core {

namespace {

/** Union-find whose root is always the smallest index of its set (deterministic numbering). */
class MinUnionFind {
public:
    explicit MinUnionFind(std::size_t n) : m_parent(n) {
        std::iota(m_parent.begin(), m_parent.end(), std::uint32_t(0));
    }
    std::uint32_t find(std::uint32_t x) {
        while (m_parent[x] != x) {
            m_parent[x] = m_parent[m_parent[x]];
            x = m_parent[x];
        }
        return x;
    }
    void unite(std::uint32_t a, std::uint32_t b) {
        a = find(a);
        b = find(b);
        if (a < b)
            m_parent[b] = a;
        else if (b < a)
            m_parent[a] = b;
    }

private:
    std::vector<std::uint32_t> m_parent;
};

constexpr int kCellBits = 21;
constexpr std::uint64_t kCellMask = (std::uint64_t(1) << kCellBits) - 1;
/** A cluster bigger than this is only partly compared with its neighbour cells (bad input). */
constexpr std::size_t kMaxCompared = 64;

std::uint64_t cellKey(std::uint64_t x, std::uint64_t y, std::uint64_t z) {
    return (x << (2 * kCellBits)) | (y << kCellBits) | z;
}

/** Renumbers union-find roots 0, 1, ... in order of first occurrence among ids 0 .. n-1. */
template <typename RootOf>
std::uint32_t numberRoots(std::size_t n, RootOf rootOf, std::vector<std::uint32_t>& out) {
    std::vector<std::uint32_t> idOfRoot(n, kNone);
    std::uint32_t next = 0;
    out.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        const std::uint32_t root = rootOf(i);
        if (idOfRoot[root] == kNone)
            idOfRoot[root] = next++;
        out[i] = idOfRoot[root];
    }
    return next;
}

/** A weld in progress: the vertices sorted by cell, each cell's range of them, the sets so far. */
struct WeldCells {
    explicit WeldCells(std::size_t vertexCount) : sets(vertexCount) {}

    std::vector<std::pair<std::uint64_t, std::uint32_t>> keyed; // (cell key, vertex), sorted
    /** Cell key → [first, end) in keyed. */
    std::unordered_map<std::uint64_t, std::pair<std::uint32_t, std::uint32_t>> cells;
    MinUnionFind sets;
};

/** Every vertex keyed by its cell of size cell from bounds.min, sorted by key. */
void keyVerticesByCell(const Mesh& mesh, const Bounds& bounds, float cell, WeldCells& w) {
    const std::size_t vertexCount = mesh.positions.size();
    w.keyed.resize(vertexCount);
    for (std::size_t v = 0; v < vertexCount; ++v) {
        const glm::vec3 q = (mesh.positions[v] - bounds.min) / cell;
        auto quantize = [](float c) {
            return std::uint64_t(
                std::clamp(std::isfinite(c) ? c : 0.0f, 0.0f, float(kCellMask - 1)));
        };
        w.keyed[v] = {cellKey(quantize(q.x), quantize(q.y), quantize(q.z)), std::uint32_t(v)};
    }
    std::sort(w.keyed.begin(), w.keyed.end());
}

/** The vertices of one cell joined; each cell's range in keyed recorded. */
void joinWholeCells(WeldCells& w) {
    const auto& keyed = w.keyed;
    w.cells.reserve(keyed.size());
    for (std::size_t i = 0; i < keyed.size();) {
        std::size_t j = i + 1;
        while (j < keyed.size() && keyed[j].first == keyed[i].first) {
            w.sets.unite(keyed[i].second, keyed[j].second);
            ++j;
        }
        w.cells.emplace(keyed[i].first, std::pair{std::uint32_t(i), std::uint32_t(j)});
        i = j;
    }
}

/**
 * Vertices of neighbouring cells within tolerance joined (two close points can straddle a cell
 * border). Only 13 of the 26 neighbour offsets are needed because joining is symmetric.
 */
void joinNeighbourCells(const Mesh& mesh, float tolerance, WeldCells& w) {
    const float tolerance2 = tolerance * tolerance;
    const auto& keyed = w.keyed;
    for (const auto& [key, range] : w.cells) {
        const std::uint64_t x = key >> (2 * kCellBits), y = (key >> kCellBits) & kCellMask,
                            z = key & kCellMask;
        for (int d = 1; d <= 13; ++d) {
            // Offsets (dx, dy, dz) in {-1,0,1}^3 after the origin in lexicographic order.
            const int code = 13 + d;
            const int dx = code / 9 - 1, dy = (code / 3) % 3 - 1, dz = code % 3 - 1;
            if ((dx < 0 && x == 0) || (dy < 0 && y == 0) || (dz < 0 && z == 0))
                continue;
            const auto other = w.cells.find(cellKey(x + dx, y + dy, z + dz));
            if (other == w.cells.end())
                continue;
            const auto [b0, b1] = other->second;
            const std::uint32_t a1 =
                std::min<std::uint32_t>(range.second, range.first + kMaxCompared);
            const std::uint32_t b1c = std::min<std::uint32_t>(b1, b0 + kMaxCompared);
            for (std::uint32_t a = range.first; a < a1; ++a)
                for (std::uint32_t b = b0; b < b1c; ++b) {
                    const glm::vec3 diff =
                        mesh.positions[keyed[a].second] - mesh.positions[keyed[b].second];
                    if (glm::dot(diff, diff) <= tolerance2)
                        w.sets.unite(keyed[a].second, keyed[b].second);
                }
        }
    }
}

/**
 * Weld: quantize to cells of the tolerance, join whole cells, then join vertices of neighbouring
 * cells that are within the tolerance. Fills topo.weldedVertex and weldedVertexCount.
 */
void weldVertices(const Mesh& mesh, float weldTolerance, MeshTopology& topo) {
    const std::size_t vertexCount = mesh.positions.size();
    const Bounds bounds = mesh.bounds();
    const float longest = std::max(bounds.longestSide(), 1e-30f);
    const float tolerance = std::max(weldTolerance, 0.0f) * longest;
    // Keep cell coordinates within kCellBits bits.
    const float cell = std::max(tolerance, longest / float(1 << (kCellBits - 1)));
    WeldCells w(vertexCount);
    keyVerticesByCell(mesh, bounds, cell, w);
    joinWholeCells(w);
    if (tolerance > 0.0f)
        joinNeighbourCells(mesh, tolerance, w);
    topo.weldedVertexCount = numberRoots(
        vertexCount, [&](std::size_t v) { return w.sets.find(std::uint32_t(v)); },
        topo.weldedVertex);
}

/** Corners; an out-of-range index becomes a fresh vertex of its own. Returns the vertex count
 *  with those. */
std::uint32_t assignCorners(const Mesh& mesh, MeshTopology& topo) {
    const std::size_t vertexCount = mesh.positions.size();
    const std::size_t triangleCount = mesh.triangleCount();
    topo.corners.resize(triangleCount);
    std::uint32_t nextLoose = topo.weldedVertexCount;
    for (std::size_t t = 0; t < triangleCount; ++t)
        for (int c = 0; c < 3; ++c) {
            const std::uint32_t index = mesh.indices[3 * t + c];
            topo.corners[t][c] = index < vertexCount ? topo.weldedVertex[index] : nextLoose++;
        }
    return nextLoose;
}

/** Edge neighbours: sort the undirected welded edges; a pair of equal edges is a manifold edge. */
void linkEdgeNeighbors(MeshTopology& topo) {
    const std::size_t triangleCount = topo.corners.size();
    std::vector<std::pair<std::uint64_t, std::uint32_t>> edges;
    edges.reserve(triangleCount * 3);
    for (std::size_t t = 0; t < triangleCount; ++t)
        for (int e = 0; e < 3; ++e) {
            const std::uint32_t a = topo.corners[t][e], b = topo.corners[t][(e + 1) % 3];
            if (a != b)
                edges.emplace_back((std::uint64_t(std::min(a, b)) << 32) | std::max(a, b),
                                   std::uint32_t(3 * t + e));
        }
    std::sort(edges.begin(), edges.end());
    topo.edgeNeighbors.assign(triangleCount, {kNone, kNone, kNone});
    for (std::size_t i = 0; i < edges.size();) {
        std::size_t j = i + 1;
        while (j < edges.size() && edges[j].first == edges[i].first)
            ++j;
        if (j - i == 2) {
            const std::uint32_t u = edges[i].second, w = edges[i + 1].second;
            topo.edgeNeighbors[u / 3][u % 3] = w / 3;
            topo.edgeNeighbors[w / 3][w % 3] = u / 3;
        }
        i = j;
    }
}

/** Components through shared welded vertices (of cornerVertexCount), numbered by their first
 *  triangle. */
void numberComponents(std::uint32_t cornerVertexCount, MeshTopology& topo) {
    const std::size_t triangleCount = topo.corners.size();
    MinUnionFind cornerSets(cornerVertexCount);
    for (const auto& c : topo.corners) {
        cornerSets.unite(c[0], c[1]);
        cornerSets.unite(c[0], c[2]);
    }
    std::vector<std::uint32_t> triangleRoot(triangleCount);
    for (std::size_t t = 0; t < triangleCount; ++t)
        triangleRoot[t] = cornerSets.find(topo.corners[t][0]);
    // Number components by their first triangle: renumber the corner roots in triangle order.
    std::vector<std::uint32_t> idOfRoot(cornerVertexCount, kNone);
    topo.component.resize(triangleCount);
    for (std::size_t t = 0; t < triangleCount; ++t) {
        std::uint32_t& id = idOfRoot[triangleRoot[t]];
        if (id == kNone)
            id = topo.componentCount++;
        topo.component[t] = id;
    }
}

} // namespace

int MeshTopology::sharedCorners(std::uint32_t a, std::uint32_t b) const {
    const auto& ca = corners[a];
    const auto& cb = corners[b];
    int shared = 0;
    for (std::uint32_t v : ca)
        shared += (v == cb[0] || v == cb[1] || v == cb[2]) ? 1 : 0;
    return shared;
}

glm::vec4 trianglePlane(const Mesh& mesh, std::size_t t) {
    glm::dvec3 v[3];
    for (int c = 0; c < 3; ++c) {
        const std::uint32_t index = mesh.indices[3 * t + std::size_t(c)];
        if (index >= mesh.positions.size())
            return glm::vec4(0.0f);
        v[c] = glm::dvec3(mesh.positions[index]);
    }
    const glm::dvec3 n = glm::cross(v[1] - v[0], v[2] - v[0]);
    const double length = glm::length(n);
    if (!(length > 0.0) || !std::isfinite(length))
        return glm::vec4(0.0f);
    const glm::dvec3 unit = n / length;
    return glm::vec4(glm::vec3(unit), float(-glm::dot(unit, (v[0] + v[1] + v[2]) / 3.0)));
}

namespace {

/** The triangles of double-sided materials in open components, ascending. */
std::vector<std::uint32_t> listShownBackFaces(const Mesh& mesh, const MeshTopology& topo) {
    const auto doubleSided = [&mesh](std::uint32_t t) {
        const std::uint32_t m = mesh.triangleMaterial[t];
        return m < mesh.materials.size() && mesh.materials[m].doubleSided;
    };
    const std::size_t triangles = topo.triangleCount();
    if (mesh.triangleMaterial.size() != triangles ||
        std::none_of(mesh.materials.begin(), mesh.materials.end(),
                     [](const Material& m) { return m.doubleSided; }))
        return {};
    std::vector<char> open(topo.componentCount, 0);
    for (std::uint32_t t = 0; t < triangles; ++t)
        for (std::uint32_t across : topo.edgeNeighbors[t])
            open[topo.component[t]] |= across == kNone ? 1 : 0;
    std::vector<std::uint32_t> shown;
    for (std::uint32_t t = 0; t < triangles; ++t)
        if (doubleSided(t) && open[topo.component[t]])
            shown.push_back(t);
    return shown;
}

} // namespace

bool MeshTopology::showsBackFace(std::uint32_t t) const {
    return !shownBackFaces.empty() &&
           std::binary_search(shownBackFaces.begin(), shownBackFaces.end(), t);
}

MeshTopology buildMeshTopology(const Mesh& mesh, float weldTolerance) {
    return *buildMeshTopology(mesh, ProgressFn{}, weldTolerance);
}

std::optional<MeshTopology> buildMeshTopology(const Mesh& mesh, const ProgressFn& progress,
                                              float weldTolerance) {
    MeshTopology topo;
    weldVertices(mesh, weldTolerance, topo);
    if (!reportProgress(progress, 0.35))
        return std::nullopt;
    const std::uint32_t cornerVertexCount = assignCorners(mesh, topo);
    if (!reportProgress(progress, 0.5))
        return std::nullopt;
    linkEdgeNeighbors(topo);
    if (!reportProgress(progress, 0.7))
        return std::nullopt;
    numberComponents(cornerVertexCount, topo);
    if (!reportProgress(progress, 0.8))
        return std::nullopt;
    const std::size_t triangleCount = mesh.triangleCount();
    topo.planes.resize(triangleCount);
    parallelRanges(int(triangleCount), 0, [&](int, int begin, int end) {
        for (std::size_t t = std::size_t(begin); t < std::size_t(end); ++t)
            topo.planes[t] = trianglePlane(mesh, t);
    });
    if (!reportProgress(progress, 0.9))
        return std::nullopt;
    topo.shownBackFaces = listShownBackFaces(mesh, topo);
    return topo;
}

} // namespace core
