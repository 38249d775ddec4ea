// SPDX-License-Identifier: GPL-3.0-or-later
// draw_layers: the compositor's program variants and its draw, which shades the fragments, picks
// the visible ones and composes the picture (the uploads are in depth_compositor_upload.cpp).
#include "render/depth_compositor.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include <epoxy/gl.h>
#include <glm/gtc/type_ptr.hpp>
#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include "render/depth_compositor_impl.h"

namespace render {

using namespace compositor;

namespace {
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
    {kMaterial, "MATERIAL"},
    {kChannelBase, "CHANNEL_BASE"},
    {kChannelRough, "CHANNEL_ROUGHNESS"},
    {kChannelMetal, "CHANNEL_METALLIC"},
    {kWithTangents, "TANGENTS"},
    {kNormalMap, "NORMAL_MAP"},
    {kOcclusionMap, "OCCLUSION_MAP"},
    {kEmissive, "EMISSIVE"},
    {kEmissiveMap, "EMISSIVE_MAP"},
    {kBlend, "BLEND"},
};

/** composite.vert + composite.frag, or composite_shade.comp, with the variant's defines. */
core::Result<Program> buildProgram(unsigned variant) {
    std::vector<std::string> defines;
    for (const auto& [bit, name] : kDefines)
        if (variant & bit)
            defines.emplace_back(name);
    auto built = variant & kShade
                     ? ShaderProgram::build({"composite_shade.comp"}, defines)
                     : ShaderProgram::build(
                           {"composite.vert", "composite.frag", "material_shading.frag"}, defines);
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
                     {&p.triangleFirst, "uTriangleFirst"},
                     {&p.meshTriangles, "uMeshTriangles"},
                     {&p.firstPart, "uFirstPart"},
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
                     {&p.opacity, "uOpacity"},
                     {&p.metallicRoughness, "uMetallicRoughness"}});
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

/** The composing variant's material channel: what the picture shows of the material. */
unsigned channelVariant(MaterialChannel channel) {
    switch (channel) {
    case MaterialChannel::Material:
        break;
    case MaterialChannel::BaseColor:
        return kChannelBase;
    case MaterialChannel::Roughness:
        return kChannelRough;
    case MaterialChannel::Metallic:
        return kChannelMetal;
    }
    return 0;
}
} // namespace

core::Result<const Program*> DepthCompositor::Impl::program(unsigned variant) {
    auto found = programs.find(variant);
    if (found == programs.end()) {
        auto built = buildProgram(variant);
        if (!built)
            return core::Error{built.error()};
        found = programs.emplace(variant, std::move(built).value()).first;
    }
    return &found->second;
}

DepthCompositor::DepthCompositor() : m_impl(std::make_unique<Impl>()) {}

DepthCompositor::~DepthCompositor() {
    release();
}

core::Status DepthCompositor::initialize() {
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

bool DepthCompositor::hasDepthLayers() const {
    return m_impl->hasDepthLayers;
}

/** One draw(): its program variants, its composing passes and the GL work of each step. */
struct DepthCompositor::Impl::DrawPass {
    /** A composing pass: its program variant, its texture pass and whether it blends. */
    struct Step {
        unsigned variant;
        std::size_t pass;
        bool blend;
    };

    Impl& d;
    const CompositeOptions& options;
    unsigned shadeVariant = kShade;
    unsigned resolveVariant = 0; // what Visible must hold: the fragment picked, boundaries marked
    unsigned composeVariant = 0;
    std::uint32_t layer = 0;
    bool transparent = false;
    bool shade = false;   // Shading is out of date
    bool resolve = false; // Visible is out of date
    std::vector<Step> steps;
    const Program* shadeProgram = nullptr;

    /**
     * Clears to the background: the view's rectangle only (pixels outside the drawn tiles are
     * background), or everything without depth layers. False when there is nothing to compose.
     */
    bool clearView() {
        const glm::vec4& background = options.background;
        glClearColor(background.r, background.g, background.b, background.a);
        if (!d.hasDepthLayers) {
            glClear(GL_COLOR_BUFFER_BIT);
            return false;
        }
        // Leaves the caller's scissor state as it was.
        GLint scissorBox[4] = {0, 0, 0, 0};
        const GLboolean scissor = glIsEnabled(GL_SCISSOR_TEST);
        glGetIntegerv(GL_SCISSOR_BOX, scissorBox);
        glEnable(GL_SCISSOR_TEST);
        glScissor(0, 0, d.width, d.height);
        glClear(GL_COLOR_BUFFER_BIT);
        glScissor(scissorBox[0], scissorBox[1], scissorBox[2], scissorBox[3]);
        if (!scissor)
            glDisable(GL_SCISSOR_TEST);
        return !d.tiles.empty();
    }

    /** The shading, picking and composing variants the options ask for, and what is stale. */
    void chooseVariants() {
        const bool segmentation = options.display == DepthLayerDisplay::Segmentation;
        const bool textured = d.hasMesh && !d.passTexture.empty();
        if (textured)
            shadeVariant |= kTextured | (d.hasUvs ? kWithUvs : 0u) |
                            (d.hasUvs && d.hasTangents ? kWithTangents : 0u);
        if (d.hasMesh && d.hasColors)
            shadeVariant |= kWithColors;
        if (d.hasMesh && d.hasBlend)
            shadeVariant |= kBlend;
        if (options.display == DepthLayerDisplay::SingleLayer)
            resolveVariant |= kSingleLayer;
        if (options.boundaries)
            resolveVariant |= kBoundaries;
        if (segmentation)
            composeVariant |= kSegmentation | (options.shadeSegmentation ? kShadeSegmentation : 0u);
        else if (textured)
            composeVariant |= kTextured;
        if (!segmentation)
            composeVariant |= channelVariant(options.channel);
        if (options.boundaries)
            composeVariant |= kBoundaries;
        if (options.highlightRegion != core::kNone)
            composeVariant |= kHighlight;
        layer = options.display == DepthLayerDisplay::SingleLayer ? options.layer : 0;
        const bool singleLayer = options.display == DepthLayerDisplay::SingleLayer;
        // Blending materials show what lies behind in the lit view, as glTF viewers draw them.
        const bool blend = (shadeVariant & kBlend) && !segmentation && !singleLayer &&
                           options.channel == MaterialChannel::Material;
        transparent = (options.popUpOpacity < 1.0f && !singleLayer) || blend;
        if (transparent) {
            resolveVariant |= kTransparency | (blend ? kBlend : 0u);
            composeVariant |= kTransparency | (blend ? kBlend : 0u);
        }
        shade = d.shadedVersion != d.geometryVersion;
        resolve = d.resolvedVersion != d.version || d.resolvedVariant != resolveVariant ||
                  d.resolvedLayer != layer;
    }

    /**
     * A pass with a metallic-roughness texture samples it, one with maps samples them in the
     * Material channel (only then: llvmpipe pays for code).
     */
    unsigned passVariant(unsigned variant, std::size_t pass) const {
        if (!(variant & kTextured))
            return variant;
        if (d.passMetallicRoughness(pass))
            variant |= kMaterial;
        if (!(variant & (kChannelBase | kChannelRough | kChannelMetal)) &&
            pass < d.passMaps.size()) {
            unsigned surface = d.passMaps[pass].features();
            if (!(shadeVariant & kWithTangents))
                surface &= ~unsigned(kSurfaceNormalMap);
            variant |= surface << kSurfaceShift;
        }
        return variant;
    }

    /**
     * One pass per texture (the first also draws background and untextured pixels); with
     * transparency the fragments under see-through ones first, then the visible ones blended
     * over them. The first pass picks again when needed; the others read what it picked.
     */
    void planSteps() {
        const std::size_t passes = composeVariant & kTextured ? d.passTexture.size() : 1;
        if (transparent)
            for (std::size_t pass = 0; pass < passes; ++pass)
                steps.push_back(
                    {(composeVariant & ~(kHighlight | kBoundaries)) | kUnder, pass, false});
        if (transparent)
            for (Step& step : steps)
                step.variant = passVariant(step.variant, step.pass);
        for (std::size_t pass = 0; pass < passes; ++pass)
            steps.push_back({passVariant(composeVariant, pass), pass, transparent});
        if (resolve)
            steps.front().variant |= resolveVariant | kResolve;
    }

    /** Every program the steps use, built on first use; false if one does not compile. */
    bool buildPrograms() {
        const auto shader = d.program(shadeVariant);
        if (!shader)
            return false;
        for (const Step& step : steps)
            if (!d.program(step.variant))
                return false;
        shadeProgram = *shader;
        return true;
    }

    /**
     * Every storage buffer at its binding. With one binding unbound, llvmpipe lost the blocks
     * after it: any buffer a failed upload left empty gets a little storage.
     */
    void bindStorage() {
        for (GLuint binding = 0; binding < kStorageBindings; ++binding) {
            if (!d.buffers[binding].id)
                d.buffers[binding].upload(nullptr, 0, d.maxBlockBytes);
            glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding, d.buffers[binding].id);
        }
    }

    /** The mesh arrays: a part's at a time (the bindings above are stand-ins without a mesh). */
    void bindMeshPart(const MeshPart& part) {
        for (std::size_t i = 0; i < kMeshArrays; ++i)
            glBindBufferBase(GL_SHADER_STORAGE_BUFFER, GLuint(kTriangles + i),
                             part.buffers[i].id ? part.buffers[i].id
                                                : d.buffers[kTriangles + i].id);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kTangents,
                         part.tangents.id ? part.tangents.id : d.buffers[kTangents].id);
    }

    /** Room for the fragments' tangents, made when a shading first keeps them. */
    bool makeShadingTangents() {
        Buffer& buffer = d.buffers[kShadingTangent];
        if (buffer.id && buffer.bytes >= d.fragments * 4)
            return true;
        if (!buffer.upload(nullptr, d.fragments * 4, d.maxBlockBytes, true))
            return false;
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kShadingTangent, buffer.id);
        return true;
    }

    /** Once per capture or mesh: every fragment's shading, 64 fragments a group. */
    void shadeFragments() {
        if ((shadeVariant & kWithTangents) && !makeShadingTangents())
            return; // out of GL memory: left unshaded, as a failed upload leaves it
        const Program& p = *shadeProgram;
        p.shader.use();
        glUniform1ui(p.fragmentCount, std::uint32_t(d.fragments));
        glUniform1ui(p.width, std::uint32_t(d.width));
        glUniform1ui(p.meshTriangles, d.hasMesh ? d.triangleCount : 0u);
        glUniformMatrix4fv(p.view, 1, GL_FALSE, glm::value_ptr(d.view));
        setRays(p);
        const std::size_t groups = (d.fragments + kShadeGroupSize - 1) / kShadeGroupSize;
        const GLuint groupsX = GLuint(std::min<std::size_t>(groups, 65535));
        // One pass per mesh part; each shades the fragments of its triangles (the first also
        // those of triangles the mesh lacks). Without a mesh one pass shades them all grey.
        const std::size_t parts = d.hasMesh ? d.meshParts.size() : 0;
        for (std::size_t i = 0; i < std::max<std::size_t>(parts, 1); ++i) {
            const bool real = i < parts;
            if (real)
                bindMeshPart(d.meshParts[i]);
            glUniform1ui(p.triangleFirst, real ? d.meshParts[i].firstTriangle : 0u);
            glUniform1ui(p.triangleCount, real ? d.meshParts[i].triangleCount : 0u);
            glUniform1ui(p.firstPart, i == 0 ? 1u : 0u);
            glDispatchCompute(groupsX, GLuint((groups + groupsX - 1) / groupsX), 1);
        }
        d.shadedVersion = d.geometryVersion;
    }

    /** The fixed-function state and the tile instances every composing pass draws with. */
    void setComposeState() {
        glViewport(0, 0, d.width, d.height);
        glDisable(GL_DEPTH_TEST);
        glDisable(GL_BLEND);
        glDisable(GL_CULL_FACE);
        glDisable(GL_STENCIL_TEST);
        // The target's alpha stays as the background and the fragments under left it.
        glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
        glVertexArrayVertexBuffer(d.vao, 0, d.buffers[kTiles].id, 0, sizeof(std::uint32_t));
        glBindVertexArray(d.vao);
    }

    /** The textures a step samples: its pass's base colour, metallic-roughness and maps. */
    void bindMaterialTextures(const Step& step, const Program& p) {
        const auto id = [](const PaintTexture* texture) { return texture ? texture->id() : 0u; };
        const PaintTexture* baseColor = d.passBaseColor(step.pass);
        if (composeVariant & kTextured)
            glBindTextureUnit(0, id(baseColor));
        if (step.variant & kMaterial)
            glBindTextureUnit(1, id(d.passMetallicRoughness(step.pass)));
        const unsigned surface = (step.variant >> kSurfaceShift) & 0xfu;
        if (!surface || !baseColor)
            return;
        bindSurfaceMaps(p.shader, d.passMaps[step.pass], surface, *d.textures, baseColor->width(),
                        baseColor->height());
        if (surface & kSurfaceNormalMap)
            setRays(p); // the view direction of the headlight on the turned normals
    }

    /** The view's pixel rays, as the shading pass reads them. */
    void setRays(const Program& p) const {
        glUniform3fv(p.rayOrigin0, 1, glm::value_ptr(d.rays.origin0));
        glUniform3fv(p.rayOriginDx, 1, glm::value_ptr(d.rays.originDx));
        glUniform3fv(p.rayOriginDy, 1, glm::value_ptr(d.rays.originDy));
        glUniform3fv(p.rayDirection0, 1, glm::value_ptr(d.rays.direction0));
        glUniform3fv(p.rayDirectionDx, 1, glm::value_ptr(d.rays.directionDx));
        glUniform3fv(p.rayDirectionDy, 1, glm::value_ptr(d.rays.directionDy));
    }

    /** Composing pass i over the tiles; the first marks what Visible now holds. */
    void drawStep(std::size_t i) {
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
        glUniform4fv(p.background, 1, glm::value_ptr(options.background));
        glUniform1ui(p.highlight, options.highlightRegion);
        const glm::ivec4 box = options.highlightRegion < d.regionBox.size()
                                   ? d.regionBox[options.highlightRegion]
                                   : glm::ivec4(0, 0, -1, -1);
        glUniform4iv(p.highlightBox, 1, glm::value_ptr(box));
        glUniform1i(p.texture, 0);
        glUniform1i(p.metallicRoughness, 1);
        glUniform1i(p.pass, int(step.pass));
        glUniform1f(p.opacity, std::clamp(options.popUpOpacity, 0.0f, 1.0f));
        bindMaterialTextures(step, p);
        glDrawArraysInstanced(GL_TRIANGLES, 0, 6, GLsizei(d.tiles.size()));
        if (i == 0 && resolve) {
            d.resolvedVersion = d.version;
            d.resolvedVariant = resolveVariant;
            d.resolvedLayer = layer;
            if (steps.size() > 1)
                glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
        }
    }

    /** Puts back what the passes bound and enabled. */
    static void unbindAll() {
        glDisable(GL_BLEND);
        glBindTextureUnit(1, 0);
        unbindSurfaceMaps();
        glBindVertexArray(0);
        for (GLuint binding = 0; binding < kStorageBindings; ++binding)
            glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding, 0);
        glUseProgram(0);
    }
};

void DepthCompositor::draw(const CompositeOptions& options) {
    Impl::DrawPass pass{*m_impl, options};
    if (!pass.clearView())
        return;
    pass.chooseVariants();
    pass.planSteps();
    if (!pass.buildPrograms())
        return; // every variant compiles when the defaults do; left as the background
    pass.bindStorage();
    if (pass.shade && m_impl->fragments > 0)
        pass.shadeFragments();
    // This draw's or an earlier one's writes must be visible to the reads below.
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    pass.setComposeState();
    for (std::size_t i = 0; i < pass.steps.size(); ++i)
        pass.drawStep(i);
    Impl::DrawPass::unbindAll();
}

std::vector<std::uint32_t> DepthCompositor::readVisible() const {
    const Impl& d = *m_impl;
    if (!d.hasDepthLayers || d.resolvedVersion != d.version)
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

void DepthCompositor::release() {
    if (!m_impl)
        return;
    Impl& d = *m_impl;
    d.releaseTextures();
    for (Buffer& buffer : d.buffers)
        buffer.free();
    for (MeshPart& part : d.meshParts)
        for (Buffer& buffer : part.buffers)
            buffer.free();
    d.meshParts.clear();
    if (d.vao)
        glDeleteVertexArrays(1, &d.vao);
    d.vao = 0;
    d.programs.clear();
    d.hasMesh = false;
    d.hasDepthLayers = false;
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
