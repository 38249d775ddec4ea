// SPDX-License-Identifier: GPL-3.0-or-later
#include "render/layer_compositor.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <epoxy/gl.h>
#include <glm/gtc/type_ptr.hpp>
#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include "core/layers/connectivity.h"
#include "render/gl_buffer.h"
#include "render/paint_texture.h"
#include "render/shader_library.h"

namespace render {

namespace {
constexpr std::size_t kMinBufferBytes = 16;    // a binding needs storage even for empty data
constexpr int kTileSize = 16;                  // pixels; only tiles holding fragments are drawn
constexpr std::size_t kShadingWords = 3;       // per fragment, see composite_shade.comp
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
    kShading,
    kTiles, // a vertex buffer, not shader storage
    kBufferCount
};
constexpr GLuint kStorageBindings = kTiles;

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
};
constexpr std::pair<Variant, const char*> kDefines[] = {
    {kResolve, "RESOLVE"},
    {kSingleLayer, "SINGLE_LAYER"},
    {kTextured, "TEXTURED"},
    {kWithUvs, "UVS"},
    {kWithColors, "COLORS"},
    {kSegmentation, "SEGMENTATION"},
    {kShadeSegmentation, "SHADE_SEGMENTATION"},
    {kBoundaries, "BOUNDARIES"},
    {kHighlight, "HIGHLIGHT"},
    {kTransparency, "TRANSPARENCY"},
    {kUnder, "UNDER"},
};

/** composite.frag's Material (std430). */
struct GpuMaterial {
    glm::vec4 baseColorFactor;
    std::int32_t texturePass; // -1 for none
    std::int32_t textureWidth;
    std::int32_t textureHeight;
    std::int32_t pad;
};

/** A shader storage buffer of the compositor: 16-byte elements, room to grow on request. */
struct Buffer : GlBuffer {
    /**
     * Stores bytes from data (or only makes room when data is null); slack leaves room to grow.
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
};

/** A linked program variant and the locations of its uniforms (-1 where it has none). */
struct Program {
    ShaderProgram shader;
    GLint width = -1, height = -1, tileSize = -1, layer = -1, regionCount = -1, maxLayers = -1,
          fragmentCount = -1, triangleCount = -1, view = -1;
    GLint rayOrigin0 = -1, rayOriginDx = -1, rayOriginDy = -1, rayDirection0 = -1,
          rayDirectionDx = -1, rayDirectionDy = -1;
    GLint background = -1, highlight = -1, highlightBox = -1, pass = -1, texture = -1, opacity = -1;
};

/** composite.vert + composite.frag, or composite_shade.comp, with the variant's defines. */
core::Result<Program> buildProgram(unsigned variant) {
    std::vector<std::string> defines;
    for (const auto& [bit, name] : kDefines)
        if (variant & bit)
            defines.emplace_back(name);
    auto built = variant & kShade
                     ? ShaderProgram::build({"composite_shade.comp"}, defines)
                     : ShaderProgram::build({"composite.vert", "composite.frag"}, defines);
    if (!built)
        return core::Error{built.error()};
    Program p{std::move(built).value()};
    p.shader.locate({{&p.width, "uWidth"},
                     {&p.height, "uHeight"},
                     {&p.tileSize, "uTileSize"},
                     {&p.layer, "uLayer"},
                     {&p.regionCount, "uRegionCount"},
                     {&p.maxLayers, "uMaxLayers"},
                     {&p.fragmentCount, "uFragmentCount"},
                     {&p.triangleCount, "uTriangleCount"},
                     {&p.view, "uView"},
                     {&p.rayOrigin0, "uRayOrigin0"},
                     {&p.rayOriginDx, "uRayOriginDx"},
                     {&p.rayOriginDy, "uRayOriginDy"},
                     {&p.rayDirection0, "uRayDirection0"},
                     {&p.rayDirectionDx, "uRayDirectionDx"},
                     {&p.rayDirectionDy, "uRayDirectionDy"},
                     {&p.background, "uBackground"},
                     {&p.highlight, "uHighlight"},
                     {&p.highlightBox, "uHighlightBox"},
                     {&p.pass, "uPass"},
                     {&p.texture, "uTexture"},
                     {&p.opacity, "uOpacity"}});
    return p;
}

/** lowbias32 (C. Wellons): a cheap integer hash with good avalanche, the same in GLSL. */
std::uint32_t hash32(std::uint32_t x) {
    x ^= x >> 16;
    x *= 0x7feb352du;
    x ^= x >> 15;
    x *= 0x846ca68bu;
    x ^= x >> 16;
    return x;
}

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

struct LayerCompositor::Impl {
    std::map<unsigned, Program> programs; // built on first use
    GLuint vao = 0;
    std::array<Buffer, kBufferCount> buffers;
    std::size_t maxBlockBytes = 0;

    // Mesh
    bool hasMesh = false;
    bool hasUvs = false;
    bool hasColors = false;
    std::uint32_t triangleCount = 0;
    std::size_t vertexCount = 0;
    std::vector<PaintTexture> passTextures; // the textures materials sample: one pass each
    std::vector<int> passOfTexture;         // per mesh texture: its pass, -1 for none

    // Layers
    bool hasLayers = false;
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
        passTextures.clear();
        passOfTexture.clear();
    }

    bool fits(std::size_t count, std::size_t elementBytes) const {
        return count <= maxBlockBytes / elementBytes;
    }

    core::Result<const Program*> program(unsigned variant) {
        auto found = programs.find(variant);
        if (found == programs.end()) {
            auto built = buildProgram(variant);
            if (!built)
                return core::Error{built.error()};
            found = programs.emplace(variant, std::move(built).value()).first;
        }
        return &found->second;
    }

    /** The tiles holding at least one fragment (offsets only grow along a row). */
    void findTiles(const core::LayerStack& stack) {
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

    /** Ranks plus, per layer j, the lowest rank deeper than j (the shader's early exit). */
    bool uploadRanks(const std::vector<std::uint32_t>& rank) {
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

    core::Status uploadSegmentation(const core::Layers& layers) {
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
};

LayerCompositor::LayerCompositor() : m_impl(std::make_unique<Impl>()) {}

LayerCompositor::~LayerCompositor() {
    release();
}

core::Status LayerCompositor::initialize() {
    Impl& d = *m_impl;
    // The everyday variants, so a broken shader shows here; others build on first use.
    for (unsigned variant : {unsigned(kShade), unsigned(kResolve), 0u}) {
        auto program = d.program(variant);
        if (!program)
            return core::Error{program.error()};
    }
    GLint64 maxBlock = 0;
    glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &maxBlock);
    d.maxBlockBytes = std::size_t(std::max<GLint64>(maxBlock, 0));
    if (!d.vao) {
        glCreateVertexArrays(1, &d.vao);
        glEnableVertexArrayAttrib(d.vao, 0);
        glVertexArrayAttribIFormat(d.vao, 0, 1, GL_UNSIGNED_INT, 0);
        glVertexArrayAttribBinding(d.vao, 0, 0);
        glVertexArrayBindingDivisor(d.vao, 0, 1);
    }
    return {};
}

core::Status LayerCompositor::setMesh(const core::Mesh& mesh) {
    Impl& d = *m_impl;
    d.hasMesh = false;
    ++d.version;
    ++d.geometryVersion;
    d.releaseTextures();
    const std::size_t vertices = mesh.vertexCount(), triangles = mesh.triangleCount();
    if (!d.fits(triangles, sizeof(glm::uvec4)) || !d.fits(vertices, sizeof(glm::vec4)) ||
        !d.fits(mesh.materials.size(), sizeof(GpuMaterial)))
        return tooLarge("the mesh's triangles or vertices");

    // Triangles with a bad index or material are drawn grey rather than read out of bounds.
    std::vector<glm::uvec4> packed(triangles);
    for (std::size_t t = 0; t < triangles; ++t) {
        const std::uint32_t a = mesh.indices[3 * t], b = mesh.indices[3 * t + 1],
                            c = mesh.indices[3 * t + 2];
        const std::uint32_t material =
            t < mesh.triangleMaterial.size() ? mesh.triangleMaterial[t] : core::kNone;
        const bool valid =
            a < vertices && b < vertices && c < vertices && material < mesh.materials.size();
        packed[t] = valid ? glm::uvec4(a, b, c, material) : glm::uvec4(0, 0, 0, core::kNone);
    }

    // One pass per distinct texture; textures beyond the resolved byte's range stay unsampled.
    std::vector<int> passOf(mesh.textures.size(), -1);
    std::vector<int> passImages;
    std::vector<GpuMaterial> materials(mesh.materials.size());
    for (std::size_t m = 0; m < materials.size(); ++m) {
        const core::Material& material = mesh.materials[m];
        const int texture = material.baseColorTexture;
        materials[m] = {material.baseColorFactor, -1, 0, 0, 0};
        if (texture < 0 || std::size_t(texture) >= mesh.textures.size() ||
            mesh.textures[std::size_t(texture)].empty())
            continue;
        int& pass = passOf[std::size_t(texture)];
        if (pass < 0 && passImages.size() < kMaxTexturePasses) {
            pass = int(passImages.size());
            passImages.push_back(texture);
        }
        const core::Image& image = mesh.textures[std::size_t(texture)];
        materials[m] = {material.baseColorFactor, pass, image.width, image.height, 0};
    }

    const std::size_t limit = d.maxBlockBytes;
    bool ok = d.buffers[kTriangles].upload(packed, limit) &&
              d.buffers[kPositions].upload(mesh.positions, limit) &&
              d.buffers[kMaterials].upload(materials, limit);
    std::vector<std::uint32_t> normals(vertices, octNormal(glm::vec3(0.0f, 0.0f, 1.0f)));
    if (mesh.normals.size() == vertices)
        std::transform(mesh.normals.begin(), mesh.normals.end(), normals.begin(), octNormal);
    ok = ok && d.buffers[kNormals].upload(normals, limit);
    d.hasUvs = mesh.uvs.size() == vertices && vertices > 0;
    d.hasColors = mesh.colors.size() == vertices && vertices > 0;
    ok = ok && (d.hasUvs ? d.buffers[kUvs].upload(mesh.uvs, limit)
                         : d.buffers[kUvs].upload(nullptr, 0, limit));
    ok = ok && (d.hasColors ? d.buffers[kColors].upload(mesh.colors, limit)
                            : d.buffers[kColors].upload(nullptr, 0, limit));
    if (!ok)
        return outOfMemory("the mesh");

    // Base color textures as MeshRenderer makes them: sRGB, mipmapped, repeating.
    for (int texture : passImages) {
        d.passTextures.emplace_back();
        d.passTextures.back().create(mesh.textures[std::size_t(texture)]);
    }
    d.passOfTexture = std::move(passOf);
    d.vertexCount = vertices;
    d.triangleCount = std::uint32_t(triangles);
    d.hasMesh = true;
    return {};
}

core::Status LayerCompositor::setLayers(const core::Layers& layers) {
    Impl& d = *m_impl;
    d.hasLayers = false;
    ++d.version;
    ++d.geometryVersion;
    const core::LayerStack& stack = layers.stack;
    const std::size_t pixels = stack.pixelCount(), fragments = stack.fragmentCount();
    if (stack.width <= 0 || stack.height <= 0 || stack.width >= 65536 || stack.height >= 65536 ||
        stack.offsets.size() != pixels + 1 || stack.triangle.size() != fragments ||
        stack.depth.size() != fragments || stack.offsets.front() != 0 ||
        stack.offsets.back() != fragments)
        return core::Error{"layer compositor: inconsistent layer stack"};
    if (!d.fits(pixels + 1, sizeof(std::uint32_t)) ||
        !d.fits(fragments, kShadingWords * sizeof(std::uint32_t)) || fragments > kMaxFragments)
        return tooLarge("the view's pixels or fragments");

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
        d.buffers[kShading].upload(nullptr, fragments * kShadingWords * 4, limit, true) &&
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
    d.hasLayers = status.ok();
    return status;
}

core::Status LayerCompositor::updateSegmentation(const core::Layers& layers) {
    Impl& d = *m_impl;
    if (!d.hasLayers || layers.stack.fragmentCount() != d.fragments ||
        layers.stack.width != d.width || layers.stack.height != d.height)
        return core::Error{"layer compositor: segmentation of another capture"};
    const core::Status status = d.uploadSegmentation(layers);
    d.hasLayers = status.ok();
    return status;
}

void LayerCompositor::updateTexels(std::uint32_t texture, int x, int y, int width, int height,
                                   const core::Image& image) {
    Impl& d = *m_impl;
    if (!d.hasMesh || texture >= d.passOfTexture.size() || d.passOfTexture[texture] < 0)
        return;
    d.passTextures[std::size_t(d.passOfTexture[texture])].update(image, x, y, width, height);
}

void LayerCompositor::updateVertexColors(std::uint32_t first, std::span<const glm::vec4> colors) {
    Impl& d = *m_impl;
    if (!d.hasMesh || !d.hasColors || first >= d.vertexCount || colors.empty())
        return;
    const std::size_t count = std::min(colors.size(), d.vertexCount - first);
    glNamedBufferSubData(d.buffers[kColors].id, GLintptr(first) * GLintptr(sizeof(glm::vec4)),
                         GLsizeiptr(count * sizeof(glm::vec4)), colors.data());
    // The shading holds the colours; the visible fragments stay as picked.
    ++d.geometryVersion;
}

bool LayerCompositor::hasLayers() const {
    return m_impl->hasLayers;
}

bool LayerCompositor::setRegionRanks(const std::vector<std::uint32_t>& rank) {
    Impl& d = *m_impl;
    if (!d.hasLayers || rank.size() != d.regionLayer.size())
        return false;
    return d.uploadRanks(rank);
}

void LayerCompositor::draw(const CompositeOptions& options) {
    Impl& d = *m_impl;
    const glm::vec4& background = options.background;
    glClearColor(background.r, background.g, background.b, background.a);
    if (!d.hasLayers) {
        glClear(GL_COLOR_BUFFER_BIT);
        return;
    }
    // Pixels outside the drawn tiles are background: clear the view's rectangle only, leaving
    // the caller's scissor state as it was.
    GLint scissorBox[4] = {0, 0, 0, 0};
    const GLboolean scissor = glIsEnabled(GL_SCISSOR_TEST);
    glGetIntegerv(GL_SCISSOR_BOX, scissorBox);
    glEnable(GL_SCISSOR_TEST);
    glScissor(0, 0, d.width, d.height);
    glClear(GL_COLOR_BUFFER_BIT);
    glScissor(scissorBox[0], scissorBox[1], scissorBox[2], scissorBox[3]);
    if (!scissor)
        glDisable(GL_SCISSOR_TEST);
    if (d.tiles.empty())
        return;

    const bool segmentation = options.display == LayerDisplay::Segmentation;
    const bool textured = d.hasMesh && !d.passTextures.empty();
    unsigned shadeVariant = kShade;
    if (textured)
        shadeVariant |= kTextured | (d.hasUvs ? kWithUvs : 0u);
    if (d.hasMesh && d.hasColors)
        shadeVariant |= kWithColors;
    // What Visible must hold: which fragment is picked and whether boundaries are marked.
    unsigned resolveVariant = 0;
    if (options.display == LayerDisplay::SingleLayer)
        resolveVariant |= kSingleLayer;
    if (options.boundaries)
        resolveVariant |= kBoundaries;
    unsigned composeVariant = 0;
    if (segmentation)
        composeVariant |= kSegmentation | (options.shadeSegmentation ? kShadeSegmentation : 0u);
    else if (textured)
        composeVariant |= kTextured;
    if (options.boundaries)
        composeVariant |= kBoundaries;
    if (options.highlightRegion != core::kNone)
        composeVariant |= kHighlight;
    const std::uint32_t layer = options.display == LayerDisplay::SingleLayer ? options.layer : 0;
    const bool transparent =
        options.popUpOpacity < 1.0f && options.display != LayerDisplay::SingleLayer;
    if (transparent) {
        resolveVariant |= kTransparency;
        composeVariant |= kTransparency;
    }
    const bool shade = d.shadedVersion != d.geometryVersion;
    const bool resolve = d.resolvedVersion != d.version || d.resolvedVariant != resolveVariant ||
                         d.resolvedLayer != layer;
    // One pass per texture (the first also draws background and untextured pixels); with
    // transparency the fragments under see-through ones first, then the visible ones blended
    // over them. The first pass picks again when needed; the others read what it picked.
    struct Step {
        unsigned variant;
        std::size_t pass;
        bool blend;
    };
    std::vector<Step> steps;
    const std::size_t passes = composeVariant & kTextured ? d.passTextures.size() : 1;
    if (transparent)
        for (std::size_t pass = 0; pass < passes; ++pass)
            steps.push_back({(composeVariant & ~(kHighlight | kBoundaries)) | kUnder, pass, false});
    for (std::size_t pass = 0; pass < passes; ++pass)
        steps.push_back({composeVariant, pass, transparent});
    if (resolve)
        steps.front().variant |= resolveVariant | kResolve;
    auto shader = d.program(shadeVariant);
    for (const Step& step : steps)
        if (!shader || !d.program(step.variant))
            return; // every variant compiles when the defaults do; left as the background

    // With one binding unbound, llvmpipe lost the blocks after it: any buffer a failed upload
    // left empty gets a little storage.
    for (GLuint binding = 0; binding < kStorageBindings; ++binding) {
        if (!d.buffers[binding].id)
            d.buffers[binding].upload(nullptr, 0, d.maxBlockBytes);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding, d.buffers[binding].id);
    }

    if (shade && d.fragments > 0) {
        // Once per capture or mesh: every fragment's shading, 64 fragments a group.
        const Program& p = **shader;
        p.shader.use();
        glUniform1ui(p.fragmentCount, std::uint32_t(d.fragments));
        glUniform1ui(p.width, std::uint32_t(d.width));
        glUniform1ui(p.triangleCount, d.hasMesh ? d.triangleCount : 0u);
        glUniformMatrix4fv(p.view, 1, GL_FALSE, glm::value_ptr(d.view));
        glUniform3fv(p.rayOrigin0, 1, glm::value_ptr(d.rays.origin0));
        glUniform3fv(p.rayOriginDx, 1, glm::value_ptr(d.rays.originDx));
        glUniform3fv(p.rayOriginDy, 1, glm::value_ptr(d.rays.originDy));
        glUniform3fv(p.rayDirection0, 1, glm::value_ptr(d.rays.direction0));
        glUniform3fv(p.rayDirectionDx, 1, glm::value_ptr(d.rays.directionDx));
        glUniform3fv(p.rayDirectionDy, 1, glm::value_ptr(d.rays.directionDy));
        const std::size_t groups = (d.fragments + kShadeGroupSize - 1) / kShadeGroupSize;
        const GLuint groupsX = GLuint(std::min<std::size_t>(groups, 65535));
        glDispatchCompute(groupsX, GLuint((groups + groupsX - 1) / groupsX), 1);
        d.shadedVersion = d.geometryVersion;
    }
    // This draw's or an earlier one's writes must be visible to the reads below.
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);

    glViewport(0, 0, d.width, d.height);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);
    glDisable(GL_STENCIL_TEST);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glVertexArrayVertexBuffer(d.vao, 0, d.buffers[kTiles].id, 0, sizeof(std::uint32_t));
    glBindVertexArray(d.vao);

    for (std::size_t i = 0; i < steps.size(); ++i) {
        const Step& step = steps[i];
        const Program& p = **d.program(step.variant);
        p.shader.use();
        if (step.blend)
            glEnable(GL_BLEND);
        glUniform1i(p.width, d.width);
        glUniform1i(p.height, d.height);
        glUniform1i(p.tileSize, kTileSize);
        glUniform1ui(p.layer, layer);
        glUniform1ui(p.regionCount, std::uint32_t(d.regionLayer.size()));
        glUniform1ui(p.maxLayers, d.maxLayers);
        glUniform4fv(p.background, 1, glm::value_ptr(background));
        glUniform1ui(p.highlight, options.highlightRegion);
        const glm::ivec4 box = options.highlightRegion < d.regionBox.size()
                                   ? d.regionBox[options.highlightRegion]
                                   : glm::ivec4(0, 0, -1, -1);
        glUniform4iv(p.highlightBox, 1, glm::value_ptr(box));
        glUniform1i(p.texture, 0);
        glUniform1i(p.pass, int(step.pass));
        glUniform1f(p.opacity, std::clamp(options.popUpOpacity, 0.0f, 1.0f));
        if (composeVariant & kTextured)
            glBindTextureUnit(0, d.passTextures[step.pass].id());
        glDrawArraysInstanced(GL_TRIANGLES, 0, 6, GLsizei(d.tiles.size()));
        if (i == 0 && resolve) {
            d.resolvedVersion = d.version;
            d.resolvedVariant = resolveVariant;
            d.resolvedLayer = layer;
            if (steps.size() > 1)
                glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
        }
    }
    glDisable(GL_BLEND);

    glBindVertexArray(0);
    for (GLuint binding = 0; binding < kStorageBindings; ++binding)
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding, 0);
    glUseProgram(0);
}

std::vector<std::uint32_t> LayerCompositor::readVisible() const {
    const Impl& d = *m_impl;
    if (!d.hasLayers || d.resolvedVersion != d.version)
        return {};
    std::vector<std::uint32_t> visible(std::size_t(d.width) * std::size_t(d.height));
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    glGetNamedBufferSubData(d.buffers[kVisible].id, 0,
                            GLsizeiptr(visible.size() * sizeof(std::uint32_t)), visible.data());
    for (std::uint32_t& word : visible) {
        word &= 0x7fffffffu; // the boundary bit
        if (word == 0x7fffffffu)
            word = core::kNone;
    }
    return visible;
}

void LayerCompositor::release() {
    if (!m_impl)
        return;
    Impl& d = *m_impl;
    d.releaseTextures();
    for (Buffer& buffer : d.buffers)
        buffer.free();
    if (d.vao)
        glDeleteVertexArrays(1, &d.vao);
    d.vao = 0;
    d.programs.clear();
    d.hasMesh = false;
    d.hasLayers = false;
    ++d.version;
    ++d.geometryVersion;
}

glm::vec4 regionColor(std::uint32_t region) {
    // Fibonacci hashing: consecutive ids (often neighbouring regions of one layer) step the hue
    // by the golden ratio, so nearby ids never get nearby hues; a hash varies saturation and
    // value on top. composite.frag's regionColor() is the same formula.
    const std::uint32_t h = region * 0x9e3779b9u;
    const float hue = float(h >> 8) / 16777216.0f;
    const std::uint32_t m = hash32(region);
    const float saturation = 0.5f + 0.2f * float(m % 3u);
    const float value = 0.75f + 0.125f * float((m >> 8) % 3u);
    const float offsets[3] = {1.0f, 2.0f / 3.0f, 1.0f / 3.0f};
    glm::vec4 color{1.0f};
    for (int c = 0; c < 3; ++c) {
        const float x = hue + offsets[c];
        const float k = std::clamp(std::abs((x - std::floor(x)) * 6.0f - 3.0f) - 1.0f, 0.0f, 1.0f);
        color[c] = value * (1.0f * (1.0f - saturation) + k * saturation);
    }
    return color;
}

} // namespace render
