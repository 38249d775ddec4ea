// SPDX-License-Identifier: GPL-3.0-or-later
// Internal to the compositor's .cpp files (it includes the GL header): the GL objects of
// DepthCompositor, shared by its drawing (depth_compositor.cpp) and its uploads
// (depth_compositor_upload.cpp).
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

#include <epoxy/gl.h>
#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

#include "core/base/result.h"
#include "core/depth/connectivity.h"
#include "core/depth/depth_layers.h"
#include "render/depth_compositor.h"
#include "render/gl_buffer.h"
#include "render/paint_texture.h"
#include "render/shader_library.h"
#include "render/surface_maps.h"

namespace render::compositor {

constexpr std::size_t kMinBufferBytes = 16;    // a binding needs storage even for empty data
constexpr int kTileSize = 16;                  // pixels; only tiles holding fragments are drawn
constexpr std::size_t kMaxTexturePasses = 255; // the texture byte of a fragment's shading
constexpr std::uint32_t kMaxFragments = 0x7fffffff; // Visible keeps a flag in bit 31
constexpr GLuint kShadeGroupSize = 64;              // composite_shade.comp's local size

/** Shader storage bindings, as declared in composite.frag and composite_shade.comp. */
enum Binding : GLuint {
    kOffsets,
    kFragmentTriangles,
    kFragmentDepths,
    kFragmentRegions,
    kFragmentLinks,
    kRanks,
    kTriangles,
    kPositions,
    kNormals,
    kUvs,
    kColors,
    kMaterials,
    kVisible,
    kFragmentPixels,
    kShadingColor, // a fragment's shading: one word in each of four buffers
    kShadingUv,
    kShadingLight,
    kShadingNormal,
    kTangents,       // a mesh array of MeshPart::tangents (normal maps only)
    kShadingTangent, // a fragment's view-space tangent (normal maps only)
    kTiles,          // a vertex buffer, not shader storage
    kBufferCount
};
constexpr GLuint kStorageBindings = kTiles;
/** The mesh arrays a MeshPart holds: bindings kTriangles .. kColors. */
constexpr std::size_t kMeshArrays = kColors - kTriangles + 1;

/** Features compiled into a program variant (see composite.frag, composite_shade.comp). */
enum Variant : unsigned {
    kShade = 1u << 0, // composite_shade.comp instead of composite.vert/.frag
    kResolve = 1u << 1,
    kSingleLayer = 1u << 2,
    kTextured = 1u << 3,
    kWithUvs = 1u << 4,
    kWithColors = 1u << 5,
    kSegmentation = 1u << 6,
    kShadeSegmentation = 1u << 7,
    kBoundaries = 1u << 8,
    kHighlight = 1u << 9,
    kTransparency = 1u << 10,
    kUnder = 1u << 11,
    kMaterial = 1u << 12,     // the pass has a metallic-roughness texture
    kChannelBase = 1u << 13,  // MaterialChannel::BaseColor
    kChannelRough = 1u << 14, // MaterialChannel::Roughness
    kChannelMetal = 1u << 15, // MaterialChannel::Metallic
    kWithTangents = 1u << 16, // the shading keeps tangents (a pass has a normal map)
    // A pass's maps in the Material channel (render::SurfaceFeature bits, shifted).
    kSurfaceShift = 17,
    kNormalMap = kSurfaceNormalMap << kSurfaceShift,
    kOcclusionMap = kSurfaceOcclusionMap << kSurfaceShift,
    kEmissive = kSurfaceEmissive << kSurfaceShift,
    kEmissiveMap = kSurfaceEmissiveMap << kSurfaceShift,
    kBlend = 1u << 21, // a material blends (alphaMode BLEND) and the lit view shows it
};

/** composite.frag's Material (std430). */
struct GpuMaterial {
    glm::vec4 baseColorFactor;
    std::int32_t texturePass; // -1 for none
    std::int32_t textureWidth;
    std::int32_t textureHeight;
    std::int32_t blend; // 1: alphaMode BLEND
};

/** A shader storage buffer of the compositor: 16-byte elements, room to grow on request. */
struct Buffer : GlBuffer {
    /**
     * Stores size bytes from source (or only makes room when it is null); slack leaves room to
     * grow.
     * False if GL could not allocate (the buffer is then empty).
     */
    bool upload(const void* source, std::size_t size, std::size_t limit, bool slack = false) {
        std::size_t allocation = std::max(size, kMinBufferBytes);
        if (slack)
            allocation = std::max(allocation, std::min(allocation + allocation / 4, limit));
        allocation = (allocation + 15) / 16 * 16; // whole elements for any std430 array
        return GlBuffer::upload(source, size, allocation);
    }
    template <typename T>
    bool upload(const std::vector<T>& values, std::size_t limit, bool slack = false) {
        return upload(values.data(), values.size() * sizeof(T), limit, slack);
    }
    /** As upload(), the count values that fill(T*) writes straight into the storage. */
    template <typename T, typename Fill>
    bool write(std::size_t count, std::size_t limit, Fill&& fill) {
        const std::size_t size = count * sizeof(T);
        if (!upload(nullptr, size, limit))
            return false;
        if (size == 0)
            return true;
        void* out = glMapNamedBufferRange(id, 0, GLsizeiptr(size),
                                          GL_MAP_WRITE_BIT | GL_MAP_INVALIDATE_RANGE_BIT);
        if (!out)
            return false;
        fill(static_cast<T*>(out));
        return glUnmapNamedBuffer(id) == GL_TRUE;
    }
};

/**
 * A run of consecutive triangles and the vertices they use, each array within one storage
 * block. A mesh whose arrays fit one block is one part that holds them unchanged; a larger one
 * is split into parts (their triangles indexing the part's own vertices, shared ones copied at
 * the seams), and composite_shade.comp runs once per part with the part's buffers at the same
 * bindings. So the mesh is limited by GL memory, not by the block size, and the shader keeps
 * one plain array per binding (no per-load choice among bindings, which llvmpipe pays for in
 * every invocation).
 */
struct MeshPart {
    std::uint32_t firstTriangle = 0;
    std::uint32_t triangleCount = 0;
    bool renumbered = false;             // false: the mesh's own numbering (a mesh in one part)
    std::vector<std::uint32_t> vertices; // renumbered: the mesh vertex of each local one, ascending
    std::array<Buffer, kMeshArrays> buffers; // binding kTriangles + i
    Buffer tangents;                         // binding kTangents, with normal maps only
};

/** A linked program variant and the locations of its uniforms (-1 where it has none). */
struct Program {
    ShaderProgram shader;
    GLint width = -1, height = -1, tileSize = -1, layer = -1, regionCount = -1, maxLayers = -1,
          fragmentCount = -1, triangleCount = -1, triangleFirst = -1, meshTriangles = -1,
          firstPart = -1, view = -1;
    GLint rayOrigin0 = -1, rayOriginDx = -1, rayOriginDy = -1, rayDirection0 = -1,
          rayDirectionDx = -1, rayDirectionDy = -1;
    GLint background = -1, highlight = -1, highlightBox = -1, pass = -1, texture = -1, opacity = -1,
          metallicRoughness = -1;
};

} // namespace render::compositor

namespace render {

struct DepthCompositor::Impl {
    std::map<unsigned, compositor::Program> programs; // built on first use
    GLuint vao = 0;
    std::array<compositor::Buffer, compositor::kBufferCount> buffers;
    std::size_t maxBlockBytes = 0;
    std::size_t blockCap = 0; // setStorageBlockCap(): 0 for none

    /** The block size split arrays are planned for: the GL's, or a test's smaller cap. */
    std::size_t planBytes() const {
        return blockCap ? std::min(blockCap, maxBlockBytes) : maxBlockBytes;
    }

    // Mesh
    bool hasMesh = false;
    bool hasUvs = false;
    bool hasColors = false;
    std::uint32_t triangleCount = 0;
    std::size_t vertexCount = 0;
    std::vector<compositor::MeshPart> meshParts; // empty without a mesh
    std::shared_ptr<MaterialTextures> textures = std::make_shared<MaterialTextures>();
    bool ownTextures = true;           // made from the mesh here, not shared
    std::vector<int> passTexture;      // per pass, the mesh texture it samples
    std::vector<SurfaceMaps> passMaps; // per pass, its maps
    bool hasTangents = false;          // the parts hold tangents
    bool hasBlend = false;             // a material's alphaMode is BLEND

    // Depth layers
    bool hasDepthLayers = false;
    int width = 0;
    int height = 0;
    std::size_t fragments = 0;
    glm::mat4 view{1.0f};
    core::PixelRays rays;
    std::uint32_t maxLayers = 0;
    std::vector<std::uint32_t> regionLayer; // per region, 1-based
    std::vector<glm::ivec4> regionBox;      // per region: min x, min y, max x, max y
    std::vector<std::uint32_t> rankData;    // the Ranks buffer: ranks, then per-layer cutoffs
    std::vector<std::uint32_t> tiles;       // tiles with fragments: x | y << 16

    // What Shading and Visible hold: the passes filling them run again when an input changed.
    std::uint64_t geometryVersion = 1; // mesh or capture: Shading
    std::uint64_t version = 1;         // those, segmentation or order: Visible
    std::uint64_t shadedVersion = 0;
    std::uint64_t resolvedVersion = 0;
    unsigned resolvedVariant = 0;
    std::uint32_t resolvedLayer = 0;

    void releaseTextures() {
        passTexture.clear();
        passMaps.clear();
        if (ownTextures)
            textures->release();
    }
    /** What a new mesh starts with: none drawn, everything made for the old one outdated. */
    void dropMesh() {
        hasMesh = false;
        ++version;
        ++geometryVersion;
        releaseTextures();
    }

    /** Pass `pass`'s base colour and metallic-roughness textures, nullptr for none. */
    const PaintTexture* passBaseColor(std::size_t pass) const {
        return pass < passTexture.size() ? textures->baseColor(std::size_t(passTexture[pass]))
                                         : nullptr;
    }
    const PaintTexture* passMetallicRoughness(std::size_t pass) const {
        return pass < passTexture.size()
                   ? textures->metallicRoughness(std::size_t(passTexture[pass]))
                   : nullptr;
    }

    /** Whether count elements fit one storage block (of planBytes()). */
    bool fits(std::size_t count, std::size_t elementBytes) const {
        return count <= planBytes() / elementBytes;
    }

    /** The program of a variant, built on first use; an Error if it does not compile. */
    core::Result<const compositor::Program*> program(unsigned variant);
    /** The tiles holding at least one fragment (offsets only grow along a row). */
    void findTiles(const core::DepthStack& stack);
    /** Ranks plus, per layer j, the lowest rank deeper than j (the shader's early exit). */
    bool uploadRanks(const std::vector<std::uint32_t>& rank);
    /** Links and regions of layers, and the initial region order. */
    core::Status uploadSegmentation(const core::DepthLayers& layers);

    /** One draw()'s variants, passes and GL steps (depth_compositor.cpp). */
    struct DrawPass;
};

} // namespace render
