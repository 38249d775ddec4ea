// SPDX-License-Identifier: GPL-3.0-or-later
// The compositor's uploads: the mesh (vertices, triangles, materials, textures; its CPU share,
// prepareMesh(), on any thread), one build's fragments and segmentation, the region order, and
// painting's texel and vertex colour updates.
#include "render/depth_compositor.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include <epoxy/gl.h>
#include <glm/vec4.hpp>

#include "core/model/mesh_tangents.h"
#include "render/depth_compositor_impl.h"

namespace render {

using namespace compositor;

namespace {
/**
 * A normal octahedral-encoded as 2 × snorm16 (composite_shade.comp decodes it): one shader load
 * instead of three, within 0.01° of the direction. Zero or non-finite normals give +Z.
 */
std::uint32_t octNormal(const glm::vec3& n) {
    const float sum = std::abs(n.x) + std::abs(n.y) + std::abs(n.z);
    float x = 0.0f, y = 0.0f;
    if (sum > 0.0f && std::isfinite(sum)) {
        x = n.x / sum;
        y = n.y / sum;
        if (n.z < 0.0f) {
            const float fx = (1.0f - std::abs(y)) * (x >= 0.0f ? 1.0f : -1.0f);
            const float fy = (1.0f - std::abs(x)) * (y >= 0.0f ? 1.0f : -1.0f);
            x = fx;
            y = fy;
        }
    }
    const auto snorm = [](float v) {
        return std::uint32_t(
            std::uint16_t(std::int16_t(std::lround(std::clamp(v, -1.0f, 1.0f) * 32767.0f))));
    };
    return snorm(x) | snorm(y) << 16;
}

core::Error tooLarge(const char* what) {
    return core::Error{std::string("layer compositor: ") + what +
                       " exceed the GL's shader storage block size"};
}
core::Error outOfMemory(const char* what) {
    return core::Error{std::string("layer compositor: out of GL memory for ") + what};
}
} // namespace

void DepthCompositor::Impl::findTiles(const core::DepthStack& stack) {
    const int tilesX = (stack.width + kTileSize - 1) / kTileSize;
    const int tilesY = (stack.height + kTileSize - 1) / kTileSize;
    tiles.clear();
    std::vector<char> used(static_cast<std::size_t>(tilesX));
    for (int ty = 0; ty < tilesY; ++ty) {
        std::fill(used.begin(), used.end(), 0);
        for (int y = ty * kTileSize; y < std::min(stack.height, (ty + 1) * kTileSize); ++y) {
            const std::uint32_t* row = stack.offsets.data() + std::size_t(y) * stack.width;
            for (int tx = 0; tx < tilesX; ++tx) {
                const int x0 = tx * kTileSize, x1 = std::min(stack.width, x0 + kTileSize);
                used[std::size_t(tx)] |= row[x0] != row[x1];
            }
        }
        for (int tx = 0; tx < tilesX; ++tx)
            if (used[std::size_t(tx)])
                tiles.push_back(std::uint32_t(tx) | std::uint32_t(ty) << 16);
    }
}

bool DepthCompositor::Impl::uploadRanks(const std::vector<std::uint32_t>& rank) {
    const std::size_t regions = rank.size();
    rankData.assign(regions + maxLayers, core::kNone);
    std::copy(rank.begin(), rank.end(), rankData.begin());
    std::vector<std::uint32_t> lowestOnLayer(std::size_t(maxLayers) + 2, core::kNone);
    bool layersKnown = true;
    for (std::size_t r = 0; r < regions; ++r) {
        const std::uint32_t layer = regionLayer[r];
        if (layer < 1 || layer > maxLayers)
            layersKnown = false;
        else
            lowestOnLayer[layer] = std::min(lowestOnLayer[layer], rank[r]);
    }
    std::uint32_t deeper = core::kNone;
    for (std::uint32_t layer = maxLayers; layer >= 1; --layer) {
        // Unknown layers disable the early exit: a cutoff of 0 is never beaten.
        rankData[regions + layer - 1] = layersKnown ? deeper : 0;
        deeper = std::min(deeper, lowestOnLayer[layer]);
    }
    ++version;
    return buffers[kRanks].upload(rankData, maxBlockBytes);
}

core::Status DepthCompositor::Impl::uploadSegmentation(const core::DepthLayers& layers) {
    const core::Segmentation& segmentation = layers.segmentation;
    const core::Connectivity& connectivity = layers.connectivity;
    bool ok;
    if (segmentation.region.size() == fragments) {
        ok = buffers[kFragmentRegions].upload(segmentation.region, maxBlockBytes, true);
    } else {
        // No (matching) segmentation: every fragment unranked, drawn front-most first.
        const std::vector<std::uint32_t> none(fragments, core::kNone);
        ok = buffers[kFragmentRegions].upload(none, maxBlockBytes, true);
    }
    // Four link bytes a fragment read as one little-endian uint: byte d = direction d.
    if (connectivity.links.size() == 4 * fragments) {
        ok = ok && buffers[kFragmentLinks].upload(connectivity.links, maxBlockBytes, true);
    } else {
        const std::vector<std::uint32_t> unlinked(fragments, 0u);
        ok = ok && buffers[kFragmentLinks].upload(unlinked, maxBlockBytes, true);
    }
    const std::vector<core::Region>& regions = segmentation.graph.regions;
    regionLayer.resize(regions.size());
    regionBox.resize(regions.size());
    std::vector<std::uint32_t> rank(regions.size());
    for (std::size_t r = 0; r < regions.size(); ++r) {
        regionLayer[r] = regions[r].layer;
        regionBox[r] = {regions[r].minX, regions[r].minY, regions[r].maxX, regions[r].maxY};
        rank[r] = std::uint32_t(r); // ids are ordered by layer, then scan order
    }
    if (!fits(rank.size() + maxLayers, sizeof(std::uint32_t)))
        return tooLarge("the regions");
    ok = ok && uploadRanks(rank);
    if (!ok)
        return outOfMemory("the segmentation");
    return {};
}

namespace {
/** Where the part that begins at firstTriangle ends: as many triangles as fit a block. */
struct PartPlan {
    std::uint32_t firstTriangle = 0, triangleCount = 0;
};

/**
 * Splits triangles into runs whose triangle array and vertex arrays (vertexBytes a vertex,
 * counting each vertex once per part) each fit blockBytes. Empty if not even one triangle fits.
 */
std::vector<PartPlan> planParts(const std::vector<glm::uvec4>& packed, std::size_t vertices,
                                std::size_t blockBytes, std::size_t vertexBytes) {
    const std::size_t maxTriangles = blockBytes / sizeof(glm::uvec4);
    const std::size_t maxVertices = blockBytes / vertexBytes;
    if (maxTriangles < 1 || maxVertices < 3)
        return {};
    std::vector<PartPlan> parts;
    std::vector<std::uint32_t> partOf(vertices, core::kNone); // the last part to use a vertex
    PartPlan part;
    std::size_t used = 0;
    for (std::size_t t = 0; t < packed.size(); ++t) {
        const glm::uvec4& triangle = packed[t];
        const auto partIndex = std::uint32_t(parts.size());
        const auto fresh = [&] {
            std::size_t count = 0;
            if (triangle.w == core::kNone)
                return count; // drawn grey: reads no vertex
            for (int i = 0; i < 3; ++i)
                count += partOf[triangle[i]] != partIndex &&
                         (i == 0 || triangle[i] != triangle[0]) &&
                         (i < 2 || triangle[2] != triangle[1]);
            return count;
        };
        if (part.triangleCount + 1 > maxTriangles || used + fresh() > maxVertices) {
            parts.push_back(part);
            part = {std::uint32_t(t), 0};
            used = 0;
        }
        const auto current = std::uint32_t(parts.size());
        if (triangle.w != core::kNone)
            for (int i = 0; i < 3; ++i)
                if (partOf[triangle[i]] != current) {
                    partOf[triangle[i]] = current;
                    ++used;
                }
        ++part.triangleCount;
    }
    parts.push_back(part);
    return parts;
}

/** Triangles as (a, b, c, material); one with a bad index or material is drawn grey. */
std::vector<glm::uvec4> packTriangles(const core::Mesh& mesh, std::size_t materials) {
    const std::size_t vertices = mesh.vertexCount(), triangles = mesh.triangleCount();
    std::vector<glm::uvec4> packed(triangles);
    for (std::size_t t = 0; t < triangles; ++t) {
        const std::uint32_t a = mesh.indices[3 * t], b = mesh.indices[3 * t + 1],
                            c = mesh.indices[3 * t + 2];
        const std::uint32_t material =
            t < mesh.triangleMaterial.size() ? mesh.triangleMaterial[t] : core::kNone;
        const bool valid = a < vertices && b < vertices && c < vertices && material < materials;
        packed[t] = valid ? glm::uvec4(a, b, c, material) : glm::uvec4(0, 0, 0, core::kNone);
    }
    return packed;
}

/** The materials as the shader reads them, and the texture and maps each draw pass samples. */
struct TexturePasses {
    std::vector<GpuMaterial> materials;
    std::vector<int> images;       // per pass, its mesh texture
    std::vector<SurfaceMaps> maps; // per pass, its maps
};

/**
 * One pass per distinct texture and maps; textures beyond the resolved byte's range stay
 * unsampled.
 */
TexturePasses planTexturePasses(const core::Mesh& look, bool hasUvs) {
    TexturePasses passes;
    passes.materials.resize(look.materials.size());
    for (std::size_t m = 0; m < passes.materials.size(); ++m) {
        const core::Material& material = look.materials[m];
        const int texture = material.baseColorTexture;
        const std::int32_t blend = material.alphaMode == core::AlphaMode::Blend ? 1 : 0;
        passes.materials[m] = {material.baseColorFactor, -1, 0, 0, blend};
        if (texture < 0 || std::size_t(texture) >= look.textures.size() ||
            look.textures[std::size_t(texture)].empty())
            continue;
        const SurfaceMaps maps = SurfaceMaps::of(look.textures, hasUvs, material);
        int pass = -1;
        for (std::size_t i = 0; i < passes.images.size() && pass < 0; ++i)
            if (passes.images[i] == texture && passes.maps[i] == maps)
                pass = int(i);
        if (pass < 0 && passes.images.size() < kMaxTexturePasses) {
            pass = int(passes.images.size());
            passes.images.push_back(texture);
            passes.maps.push_back(maps);
        }
        const core::Image& image = look.textures[std::size_t(texture)];
        passes.materials[m] = {material.baseColorFactor, pass, image.width, image.height, blend};
    }
    return passes;
}

/** Whether a pass has a normal map (the parts then hold tangents). */
bool needsTangents(const TexturePasses& passes) {
    return std::any_of(passes.maps.begin(), passes.maps.end(), [](const SurfaceMaps& maps) {
        return (maps.features() & kSurfaceNormalMap) != 0;
    });
}

std::vector<std::uint32_t> octNormals(const core::Mesh& mesh) {
    std::vector<std::uint32_t> normals(mesh.vertexCount(), octNormal(glm::vec3(0.0f, 0.0f, 1.0f)));
    if (mesh.normals.size() == mesh.vertexCount())
        std::transform(mesh.normals.begin(), mesh.normals.end(), normals.begin(), octNormal);
    return normals;
}

/**
 * core::vertexTangents() as composite_shade.comp reads them: the direction octahedral-encoded
 * as octNormal() does, with the bitangent's sign in bit 0 (set: negative).
 */
std::vector<std::uint32_t> octTangents(const core::Mesh& mesh) {
    const std::vector<glm::vec4> tangents = core::vertexTangents(mesh);
    std::vector<std::uint32_t> packed(tangents.size());
    for (std::size_t i = 0; i < tangents.size(); ++i)
        packed[i] = (octNormal(glm::vec3(tangents[i])) & ~1u) | (tangents[i].w < 0.0f ? 1u : 0u);
    return packed;
}

/**
 * The part's vertices in ascending order, and its triangles renumbered to them; localOf is
 * scratch (a word a mesh vertex), kept by the caller from part to part.
 */
std::vector<glm::uvec4> renumberPart(const std::vector<glm::uvec4>& packed, std::size_t vertices,
                                     const PartPlan& plan, std::vector<std::uint32_t>& used,
                                     std::vector<std::uint32_t>& localOf) {
    const auto begin = packed.begin() + plan.firstTriangle;
    std::vector<glm::uvec4> local(begin, begin + plan.triangleCount);
    // The used vertices marked, then numbered in ascending order: no sort of the corners.
    constexpr std::uint32_t kUsed = core::kNone - 1;
    localOf.assign(vertices, core::kNone);
    for (const glm::uvec4& triangle : local)
        if (triangle.w != core::kNone)
            localOf[triangle.x] = localOf[triangle.y] = localOf[triangle.z] = kUsed;
    for (std::size_t v = 0; v < vertices; ++v)
        if (localOf[v] == kUsed) {
            localOf[v] = std::uint32_t(used.size());
            used.push_back(std::uint32_t(v));
        }
    for (glm::uvec4& triangle : local)
        if (triangle.w != core::kNone)
            triangle = {localOf[triangle.x], localOf[triangle.y], localOf[triangle.z], triangle.w};
    return local;
}

/** The parts: the whole mesh as it is when it fits one storage block, else renumbered runs. */
struct MeshPlan {
    std::vector<PartPlan> parts; // empty if not even one triangle fits
    bool whole = false;
};

MeshPlan planMeshParts(const std::vector<glm::uvec4>& packed, std::size_t vertices, bool colors,
                       std::size_t blockBytes) {
    // The largest vertex element: a colour (vec4) or a position (3 floats).
    const std::size_t vertexBytes = colors ? sizeof(glm::vec4) : sizeof(glm::vec3);
    if (packed.size() <= blockBytes / sizeof(glm::uvec4) && vertices <= blockBytes / vertexBytes)
        return {{{0, std::uint32_t(packed.size())}}, true};
    return {planParts(packed, vertices, blockBytes, vertexBytes), false};
}

} // namespace

/**
 * What DepthCompositor::setMesh() works out before it touches GL: the materials as the shader
 * reads them, the draw passes, the normals (and tangents) encoded, and the triangles packed
 * with their materials, whole or split into parts with their own vertices.
 */
struct CompositorMesh {
    /** A run of triangles: renumbered to its own vertices (the mesh's of each, ascending). */
    struct Part {
        std::uint32_t firstTriangle = 0, triangleCount = 0;
        std::vector<std::uint32_t> vertices; // empty for the whole mesh
        std::vector<glm::uvec4> triangles;   // empty for the whole mesh (packed holds them)
    };
    std::size_t blockBytes = 0; // the storage block it was split for
    std::size_t vertices = 0;
    std::uint32_t triangles = 0;
    bool hasUvs = false, hasColors = false, hasBlend = false, whole = false;
    std::vector<GpuMaterial> materials; // as the shader reads them
    std::vector<int> passImages;        // per draw pass, its mesh texture
    std::vector<SurfaceMaps> passMaps;  // per draw pass, its maps
    std::vector<std::uint32_t> normals;
    std::vector<std::uint32_t> tangents; // empty without normal maps
    std::vector<glm::uvec4> packed;      // the whole mesh's triangles; empty when split
    std::vector<Part> parts;
};

namespace {

/** What every part's upload reads: the prepared mesh, its geometry and vertex colours. */
struct MeshUpload {
    const CompositorMesh& prepared;
    const core::Mesh& mesh;
    const std::vector<glm::vec4>& colors;
    std::size_t limit = 0; // bytes of one storage block
};

/** The part's buffer at binding (kTriangles and after). */
Buffer& bufferAt(MeshPart& part, std::size_t binding) {
    return part.buffers[binding - kTriangles];
}

bool uploadTo(MeshPart& part, std::size_t binding, const auto& values, bool present,
              std::size_t limit) {
    Buffer& buffer = bufferAt(part, binding);
    return present ? buffer.upload(values, limit) : buffer.upload(nullptr, 0, limit);
}

/** The part's tangents, or a little storage without normal maps. */
bool uploadTangents(MeshPart& part, const std::vector<std::uint32_t>& tangents, std::size_t limit) {
    return tangents.empty() ? part.tangents.upload(nullptr, 0, limit)
                            : part.tangents.upload(tangents, limit);
}

/** The whole mesh as one part, its arrays as they are. */
bool uploadWhole(const MeshUpload& u, MeshPart& part) {
    const CompositorMesh& p = u.prepared;
    return uploadTangents(part, p.tangents, u.limit) &&
           uploadTo(part, kTriangles, p.packed, true, u.limit) &&
           uploadTo(part, kPositions, u.mesh.positions, true, u.limit) &&
           uploadTo(part, kNormals, p.normals, true, u.limit) &&
           uploadTo(part, kUvs, u.mesh.uvs, p.hasUvs, u.limit) &&
           uploadTo(part, kColors, u.colors, p.hasColors, u.limit);
}

/**
 * The values of source at a part's vertices, gathered straight into buffer; a little storage
 * when the mesh has none.
 */
template <typename T>
bool gatherTo(Buffer& buffer, const std::vector<std::uint32_t>& vertices,
              const std::vector<T>& source, bool present, std::size_t limit) {
    if (!present)
        return buffer.upload(nullptr, 0, limit);
    return buffer.write<T>(vertices.size(), limit, [&](T* out) {
        for (std::size_t i = 0; i < vertices.size(); ++i)
            out[i] = source[vertices[i]];
    });
}

/** A run of triangles with its own renumbered copy of the vertices it uses. */
bool uploadRenumbered(const MeshUpload& u, const CompositorMesh::Part& prepared, MeshPart& part) {
    const CompositorMesh& p = u.prepared;
    const std::vector<std::uint32_t>& v = prepared.vertices;
    part.vertices = v;
    return gatherTo(part.tangents, v, p.tangents, !p.tangents.empty(), u.limit) &&
           uploadTo(part, kTriangles, prepared.triangles, true, u.limit) &&
           gatherTo(bufferAt(part, kPositions), v, u.mesh.positions, true, u.limit) &&
           gatherTo(bufferAt(part, kNormals), v, p.normals, true, u.limit) &&
           gatherTo(bufferAt(part, kUvs), v, u.mesh.uvs, p.hasUvs, u.limit) &&
           gatherTo(bufferAt(part, kColors), v, u.colors, p.hasColors, u.limit);
}

/** Uploads every prepared part (parts beyond them are freed; the others keep their buffers). */
bool uploadMeshParts(const MeshUpload& u, std::vector<MeshPart>& parts) {
    const std::vector<CompositorMesh::Part>& plan = u.prepared.parts;
    for (std::size_t i = plan.size(); i < parts.size(); ++i) {
        for (Buffer& buffer : parts[i].buffers)
            buffer.free();
        parts[i].tangents.free();
    }
    parts.resize(plan.size());
    for (std::size_t i = 0; i < plan.size(); ++i) {
        MeshPart& part = parts[i];
        part.firstTriangle = plan[i].firstTriangle;
        part.triangleCount = plan[i].triangleCount;
        part.vertices.clear();
        part.renumbered = !u.prepared.whole;
        if (!(u.prepared.whole ? uploadWhole(u, part) : uploadRenumbered(u, plan[i], part)))
            return false;
    }
    return true;
}

} // namespace

std::size_t DepthCompositor::storageBlockBytes() const {
    return m_impl->planBytes();
}

core::Result<std::shared_ptr<const CompositorMesh>>
DepthCompositor::prepareMesh(const core::Mesh& mesh, const core::Mesh& look,
                             std::size_t blockBytes) {
    const std::size_t vertices = mesh.vertexCount(), triangles = mesh.triangleCount();
    if (look.materials.size() > blockBytes / sizeof(GpuMaterial))
        return tooLarge("the mesh's materials");
    if (triangles > core::kNone - 1)
        return core::Error{"layer compositor: the mesh has more than 2^32 - 2 triangles"};
    auto out = std::make_shared<CompositorMesh>();
    out->blockBytes = blockBytes;
    out->vertices = vertices;
    out->triangles = std::uint32_t(triangles);
    std::vector<glm::uvec4> packed = packTriangles(mesh, look.materials.size());
    out->hasUvs = mesh.uvs.size() == vertices && vertices > 0;
    TexturePasses passes = planTexturePasses(look, out->hasUvs);
    out->normals = octNormals(mesh);
    out->hasColors = look.colors.size() == vertices && vertices > 0;
    if (out->hasUvs && needsTangents(passes))
        out->tangents = octTangents(mesh);
    out->materials = std::move(passes.materials);
    out->passImages = std::move(passes.images);
    out->passMaps = std::move(passes.maps);
    out->hasBlend =
        std::any_of(look.materials.begin(), look.materials.end(),
                    [](const core::Material& m) { return m.alphaMode == core::AlphaMode::Blend; });
    const MeshPlan plan = planMeshParts(packed, vertices, out->hasColors, blockBytes);
    if (plan.parts.empty())
        return tooLarge("one triangle's vertices");
    out->whole = plan.whole;
    std::vector<std::uint32_t> localOf;
    for (const PartPlan& run : plan.parts) {
        CompositorMesh::Part part{run.firstTriangle, run.triangleCount, {}, {}};
        if (!plan.whole)
            part.triangles = renumberPart(packed, vertices, run, part.vertices, localOf);
        out->parts.push_back(std::move(part));
    }
    if (plan.whole)
        out->packed = std::move(packed);
    return std::shared_ptr<const CompositorMesh>(std::move(out));
}

core::Status DepthCompositor::setMesh(const core::Mesh& mesh,
                                      std::shared_ptr<MaterialTextures> textures) {
    return setMesh(mesh, mesh, std::move(textures));
}

core::Status DepthCompositor::setMesh(const core::Mesh& mesh, const core::Mesh& look,
                                      std::shared_ptr<MaterialTextures> textures) {
    auto prepared = prepareMesh(mesh, look, storageBlockBytes());
    if (!prepared) {
        m_impl->dropMesh();
        return prepared.takeError();
    }
    return setMesh(**prepared, mesh, look, std::move(textures));
}

core::Status DepthCompositor::setMesh(const CompositorMesh& prepared, const core::Mesh& mesh,
                                      const core::Mesh& look,
                                      std::shared_ptr<MaterialTextures> textures) {
    Impl& d = *m_impl;
    if (prepared.blockBytes != d.planBytes())
        return setMesh(mesh, look, std::move(textures)); // split for another block size
    d.dropMesh();
    d.ownTextures = textures == nullptr;
    d.textures = d.ownTextures ? std::make_shared<MaterialTextures>() : std::move(textures);
    if (prepared.vertices != mesh.vertexCount() || prepared.triangles != mesh.triangleCount() ||
        prepared.materials.size() != look.materials.size())
        return core::Error{"layer compositor: the prepared mesh is another mesh's"};
    d.hasUvs = prepared.hasUvs;
    d.hasColors = prepared.hasColors;
    d.hasTangents = !prepared.tangents.empty();
    d.hasBlend = prepared.hasBlend;
    const MeshUpload upload{prepared, mesh, look.colors, d.maxBlockBytes};
    if (!d.buffers[kMaterials].upload(prepared.materials, d.maxBlockBytes) ||
        !uploadMeshParts(upload, d.meshParts)) {
        d.meshParts.clear();
        return outOfMemory("the mesh (open a model with fewer triangles)");
    }
    if (d.ownTextures)
        d.textures->create(look.textures);
    d.passTexture = prepared.passImages;
    d.passMaps = prepared.passMaps;
    d.vertexCount = prepared.vertices;
    d.triangleCount = prepared.triangles;
    d.hasMesh = true;
    return {};
}

void DepthCompositor::setStorageBlockCap(std::size_t bytes) {
    m_impl->blockCap = bytes;
}

std::size_t DepthCompositor::meshPartCount() const {
    return m_impl->hasMesh ? m_impl->meshParts.size() : 0;
}

core::Status DepthCompositor::setDepthLayers(const core::DepthLayers& layers) {
    Impl& d = *m_impl;
    d.hasDepthLayers = false;
    ++d.version;
    ++d.geometryVersion;
    const core::DepthStack& stack = layers.stack;
    const std::size_t pixels = stack.pixelCount(), fragments = stack.fragmentCount();
    if (stack.width <= 0 || stack.height <= 0 || stack.width >= 65536 || stack.height >= 65536 ||
        stack.offsets.size() != pixels + 1 || stack.triangle.size() != fragments ||
        stack.depth.size() != fragments || stack.offsets.front() != 0 ||
        stack.offsets.back() != fragments)
        return core::Error{"layer compositor: inconsistent layer stack"};
    // Every per-fragment array (the shading too) is a word a fragment; Visible two a pixel.
    if (!d.fits(2 * pixels, sizeof(std::uint32_t)) || !d.fits(fragments, sizeof(std::uint32_t)) ||
        fragments > kMaxFragments)
        return core::Error{"layer compositor: the view's " + std::to_string(fragments) +
                           " fragments exceed the GL's shader storage block size (" +
                           std::to_string(d.planBytes() / sizeof(std::uint32_t)) +
                           " at most); make the view smaller"};

    d.findTiles(stack);
    std::vector<std::uint32_t> fragmentPixel(fragments);
    for (std::size_t p = 0; p < pixels; ++p) {
        if (stack.offsets[p + 1] < stack.offsets[p])
            return core::Error{"layer compositor: inconsistent layer stack"};
        std::fill(fragmentPixel.begin() + stack.offsets[p],
                  fragmentPixel.begin() + stack.offsets[p + 1], std::uint32_t(p));
    }
    const std::size_t limit = d.maxBlockBytes;
    const bool ok =
        d.buffers[kOffsets].upload(stack.offsets, limit, true) &&
        d.buffers[kFragmentTriangles].upload(stack.triangle, limit, true) &&
        d.buffers[kFragmentDepths].upload(stack.depth, limit, true) &&
        d.buffers[kFragmentPixels].upload(fragmentPixel, limit, true) &&
        d.buffers[kShadingColor].upload(nullptr, fragments * 4, limit, true) &&
        d.buffers[kShadingUv].upload(nullptr, fragments * 4, limit, true) &&
        d.buffers[kShadingLight].upload(nullptr, fragments * 4, limit, true) &&
        d.buffers[kShadingNormal].upload(nullptr, fragments * 4, limit, true) &&
        // The visible fragments, then the under ones (transparency).
        d.buffers[kVisible].upload(nullptr, 2 * pixels * sizeof(std::uint32_t), limit, true) &&
        d.buffers[kTiles].upload(d.tiles, limit, true);
    if (!ok)
        return outOfMemory("the layer stack");
    // Pixels outside the drawn tiles are never written: they read as background.
    const std::uint32_t noFragment = 0x7fffffffu;
    glClearNamedBufferSubData(d.buffers[kVisible].id, GL_R32UI, 0,
                              GLsizeiptr(pixels * sizeof(std::uint32_t)), GL_RED_INTEGER,
                              GL_UNSIGNED_INT, &noFragment);

    d.width = stack.width;
    d.height = stack.height;
    d.fragments = fragments;
    d.view = layers.view.view;
    // The rays of the stack's own pixels, whatever size the view says.
    core::View view = layers.view;
    view.width = stack.width;
    view.height = stack.height;
    d.rays = core::PixelRays::fromView(view);
    d.maxLayers = stack.maxLayers();
    const core::Status status = d.uploadSegmentation(layers);
    d.hasDepthLayers = status.ok();
    return status;
}

core::Status DepthCompositor::updateSegmentation(const core::DepthLayers& layers) {
    Impl& d = *m_impl;
    if (!d.hasDepthLayers || layers.stack.fragmentCount() != d.fragments ||
        layers.stack.width != d.width || layers.stack.height != d.height)
        return core::Error{"layer compositor: segmentation of another capture"};
    const core::Status status = d.uploadSegmentation(layers);
    d.hasDepthLayers = status.ok();
    return status;
}

MaterialTextures& DepthCompositor::textures() {
    return *m_impl->textures;
}

void DepthCompositor::updateVertexColors(std::uint32_t first, std::span<const glm::vec4> colors) {
    Impl& d = *m_impl;
    if (!d.hasMesh || !d.hasColors || first >= d.vertexCount || colors.empty())
        return;
    const std::size_t count = std::min(colors.size(), d.vertexCount - first);
    for (MeshPart& part : d.meshParts) {
        const GLuint buffer = part.buffers[kColors - kTriangles].id;
        if (!part.renumbered) {
            glNamedBufferSubData(buffer, GLintptr(first) * GLintptr(sizeof(glm::vec4)),
                                 GLsizeiptr(count * sizeof(glm::vec4)), colors.data());
            continue;
        }
        // The part's copies of those vertices: a run of its ascending local ones.
        const auto lo = std::lower_bound(part.vertices.begin(), part.vertices.end(), first);
        const auto hi = std::lower_bound(lo, part.vertices.end(), std::uint32_t(first + count));
        if (lo == hi)
            continue;
        std::vector<glm::vec4> local;
        local.reserve(std::size_t(hi - lo));
        for (auto v = lo; v != hi; ++v)
            local.push_back(colors[*v - first]);
        glNamedBufferSubData(buffer,
                             GLintptr(lo - part.vertices.begin()) * GLintptr(sizeof(glm::vec4)),
                             GLsizeiptr(local.size() * sizeof(glm::vec4)), local.data());
    }
    // The shading holds the colours; the visible fragments stay as picked.
    ++d.geometryVersion;
}

bool DepthCompositor::setRegionRanks(const std::vector<std::uint32_t>& rank) {
    Impl& d = *m_impl;
    if (!d.hasDepthLayers || rank.size() != d.regionLayer.size())
        return false;
    return d.uploadRanks(rank);
}

} // namespace render
