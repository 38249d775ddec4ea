// SPDX-License-Identifier: GPL-3.0-or-later
#include "render/mesh_renderer.h"

#include <algorithm>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <epoxy/gl.h>
#include <glm/gtc/type_ptr.hpp>

#include "core/model/mesh_tangents.h"
#include "render/paint_texture.h"
#include "render/shader_library.h"
#include "render/software_gl.h"
#include "render/surface_maps.h"

namespace render {

namespace {
struct Vertex {
    glm::vec3 position;
    glm::vec3 normal;
    glm::vec2 uv;
};

/** A range of consecutive triangles sharing one material (triangle order is kept). */
struct MaterialRun {
    std::uint32_t firstTriangle;
    std::uint32_t triangleCount;
    std::uint32_t material;
    bool backFaces = false; // its back faces are shown when back faces are culled
};

/**
 * A program variant: the channel shown, whether the material has metallic-roughness, whether it
 * is alpha-masked (every channel), and the SurfaceFeature bits of its maps (only in the lit
 * Material channel).
 */
unsigned variantKey(MaterialChannel channel, bool material, bool alphaMask, unsigned surface) {
    return unsigned(channel) | (material ? 4u : 0u) | (alphaMask ? 8u : 0u) | surface << 4;
}

/** mesh.frag with the defines of a variant. */
core::Result<ShaderProgram> buildVariant(unsigned key) {
    std::vector<std::string> defines = surfaceDefines(key >> 4);
    if (key & 4u)
        defines.emplace_back("MATERIAL");
    if (key & 8u)
        defines.emplace_back("ALPHA_MASK");
    switch (MaterialChannel(key & 3u)) {
    case MaterialChannel::Material:
        break;
    case MaterialChannel::BaseColor:
        defines.emplace_back("CHANNEL_BASE");
        break;
    case MaterialChannel::Roughness:
        defines.emplace_back("CHANNEL_ROUGHNESS");
        break;
    case MaterialChannel::Metallic:
        defines.emplace_back("CHANNEL_METALLIC");
        break;
    }
    return ShaderProgram::build({"mesh.vert", "mesh.frag", "material_shading.frag"}, defines);
}
} // namespace

struct MeshRenderer::Impl {
    // Built when first drawn (llvmpipe pays for every instruction, so features are compiled in
    // only where a run needs them); key 0, the plain one, by initialize().
    std::map<unsigned, ShaderProgram> programs;
    std::set<unsigned> failed;
    GLuint vao = 0, vbo = 0, ibo = 0;
    GLuint colorBuffer = 0;            // its own buffer, so painting updates it in place
    GLuint tangentBuffer = 0;          // only for a mesh with normal maps
    std::vector<SurfaceMaps> surfaces; // per material
    std::size_t vertexCount = 0;
    std::shared_ptr<MaterialTextures> textures = std::make_shared<MaterialTextures>();
    bool ownTextures = true; // made from the mesh here, not shared
    std::vector<core::Material> materials;
    std::vector<MaterialRun> runs;
    std::vector<char> backFaceMaterials; // per material: some of its back faces are shown
    bool hasMesh = false;
    // The stand-in: its own index buffer over the same vertex buffers.
    GLuint standInVao = 0, standInIbo = 0;
    std::vector<MaterialRun> standInRuns;
    std::size_t lastTriangles = 0;
    bool software = false; // a software rasterizer (see drawPieces())
    std::uint64_t revision = 0;

    /** A mesh between beginMesh() and finishMesh(): its mapped buffers, and its runs. */
    struct Pending {
        Vertex* vertices = nullptr;
        std::uint32_t* indices = nullptr;
        glm::vec4* tangents = nullptr; // only for a mesh with normal maps
        std::vector<MaterialRun> runs;
        bool filled = false; // the fill returned (it may throw: out of memory)

        /** The fill beginMesh() returns: touches nothing but these. */
        void fill(const core::Mesh& mesh, std::span<const std::uint32_t> shownBackFaces) {
            for (std::size_t i = 0; vertices && i < mesh.vertexCount(); ++i)
                vertices[i] = {mesh.positions[i], mesh.normals[i],
                               mesh.hasUvs() ? mesh.uvs[i] : glm::vec2(0.0f)};
            std::copy(mesh.indices.begin(), mesh.indices.end(), indices);
            if (tangents) {
                const std::vector<glm::vec4> made = core::vertexTangents(mesh);
                std::copy(made.begin(), made.end(), tangents);
            }
            auto shown = shownBackFaces.begin();
            runs = makeRuns(mesh.triangleMaterial, [&](std::uint32_t t, std::uint32_t) {
                while (shown != shownBackFaces.end() && *shown < t)
                    ++shown;
                return shown != shownBackFaces.end() && *shown == t;
            });
            filled = true;
        }
    };
    std::optional<Pending> pending;

    /** Makes buffer (bytes) mapped for writing if wanted; nullptr if not, or not mappable. */
    static void* mapNew(GLuint& buffer, std::size_t bytes, bool wanted) {
        if (!wanted)
            return nullptr;
        glCreateBuffers(1, &buffer);
        glNamedBufferStorage(buffer, GLsizeiptr(bytes), nullptr, GL_MAP_WRITE_BIT);
        return glMapNamedBufferRange(buffer, 0, GLsizeiptr(bytes),
                                     GL_MAP_WRITE_BIT | GL_MAP_INVALIDATE_BUFFER_BIT);
    }

    /** Unmaps the pending mesh's buffers; false if a mapping's contents were lost. */
    bool unmapPending() const {
        bool kept = true;
        for (const auto& [buffer, mapped] :
             {std::pair{vbo, pending->vertices != nullptr},
              std::pair{ibo, pending->indices != nullptr},
              std::pair{tangentBuffer, pending->tangents != nullptr}})
            if (mapped)
                kept = glUnmapNamedBuffer(buffer) == GL_TRUE && kept;
        return kept;
    }

    GLuint makeVao(GLuint indexBuffer) const {
        GLuint array = 0;
        glCreateVertexArrays(1, &array);
        glVertexArrayVertexBuffer(array, 0, vbo, 0, sizeof(Vertex));
        if (colorBuffer)
            glVertexArrayVertexBuffer(array, 1, colorBuffer, 0, sizeof(glm::vec4));
        if (tangentBuffer)
            glVertexArrayVertexBuffer(array, 2, tangentBuffer, 0, sizeof(glm::vec4));
        glVertexArrayElementBuffer(array, indexBuffer);
        const auto attribute = [&](GLuint location, GLint size, GLuint offset, GLuint binding) {
            glEnableVertexArrayAttrib(array, location);
            glVertexArrayAttribFormat(array, location, size, GL_FLOAT, GL_FALSE, offset);
            glVertexArrayAttribBinding(array, location, binding);
        };
        attribute(0, 3, offsetof(Vertex, position), 0);
        attribute(1, 3, offsetof(Vertex, normal), 0);
        attribute(2, 2, offsetof(Vertex, uv), 0);
        if (colorBuffer) // else white (draw() sets the attribute's value)
            attribute(3, 4, 0, 1);
        if (tangentBuffer)
            attribute(4, 4, 0, 2);
        return array;
    }

    /** Runs of one material and one way of showing back faces (shows(t)). */
    template <typename Shows>
    static std::vector<MaterialRun> makeRuns(std::span<const std::uint32_t> triangleMaterial,
                                             Shows shows) {
        std::vector<MaterialRun> made;
        for (std::uint32_t t = 0; t < triangleMaterial.size(); ++t) {
            const std::uint32_t m = triangleMaterial[t];
            const bool backFaces = shows(t, m);
            if (made.empty() || made.back().material != m || made.back().backFaces != backFaces)
                made.push_back({t, 0, m, backFaces});
            ++made.back().triangleCount;
        }
        return made;
    }

    /**
     * The program for channel and material, built on first use; the plain one where a variant
     * fails to build (the picture falls back to headlight shading instead of nothing).
     */
    const ShaderProgram* program(unsigned key) {
        auto found = programs.find(key);
        if (found == programs.end() && !failed.contains(key)) {
            auto built = buildVariant(key);
            if (built)
                found = programs.emplace(key, std::move(built).value()).first;
            else
                failed.insert(key);
        }
        return found != programs.end() ? &found->second : &programs[0];
    }

    /** What draw() keeps across runs: its view and options, the program in use, the pieces. */
    struct RunDraw {
        const core::View& view;
        const DrawOptions& options;
        const ShaderProgram* current;
        int pieces;
    };

    /** Whether run is drawn blended by its alpha (glTF's BLEND, in the lit view only). */
    bool blends(const MaterialRun& run, MaterialChannel channel) const {
        return channel == MaterialChannel::Material &&
               materials[run.material].alphaMode == core::AlphaMode::Blend;
    }

    /**
     * Triangles [first, first + count) of run (first counted from the run's first) with its
     * material's program, textures and culling.
     */
    void drawRun(const MaterialRun& run, std::size_t first, std::size_t count, RunDraw& state) {
        const core::Material& material = materials[run.material];
        const MaterialChannel channel = state.options.channel;
        const bool textured = material.baseColorTexture >= 0;
        const std::size_t texture = textured ? std::size_t(material.baseColorTexture) : 0;
        const PaintTexture* baseColor = textured ? textures->baseColor(texture) : nullptr;
        const PaintTexture* metallicRoughness =
            textured ? textures->metallicRoughness(texture) : nullptr;
        const bool lit = metallicRoughness != nullptr;
        const SurfaceMaps& surface = surfaces[run.material];
        unsigned features =
            channel == MaterialChannel::Material && baseColor ? surface.features() : 0u;
        if (!tangentBuffer)
            features &= ~unsigned(kSurfaceNormalMap);
        const bool alphaMask = material.alphaMode == core::AlphaMode::Mask;
        const ShaderProgram* shader = program(variantKey(channel, lit, alphaMask, features));
        if (shader != state.current) {
            state.current = shader;
            shader->use();
            glUniformMatrix4fv(shader->uniform("uView"), 1, GL_FALSE,
                               glm::value_ptr(state.view.view));
            glUniformMatrix4fv(shader->uniform("uProj"), 1, GL_FALSE,
                               glm::value_ptr(state.view.proj));
            glUniform1i(shader->uniform("uBaseColorTexture"), 0);
            glUniform1i(shader->uniform("uMetallicRoughness"), 1);
        }
        glUniform4fv(shader->uniform("uBaseColorFactor"), 1,
                     glm::value_ptr(material.baseColorFactor));
        glUniform1i(shader->uniform("uHasTexture"), textured);
        glUniform1i(shader->uniform("uBlend"), blends(run, channel));
        if (alphaMask)
            glUniform1f(shader->uniform("uAlphaCutoff"), material.alphaCutoff);
        if (textured)
            glBindTextureUnit(0, baseColor ? baseColor->id() : 0);
        if (lit && shader != &programs[0])
            glBindTextureUnit(1, metallicRoughness->id());
        if (features && shader != &programs[0])
            bindSurfaceMaps(*shader, surface, features, *textures, baseColor->width(),
                            baseColor->height());
        if (state.options.cullBackFaces && !run.backFaces)
            glEnable(GL_CULL_FACE);
        else
            glDisable(GL_CULL_FACE);
        drawInPieces(run.firstTriangle + first, count, state.pieces,
                     [](std::size_t from, std::size_t triangles) {
                         glDrawElements(GL_TRIANGLES, GLsizei(triangles * 3), GL_UNSIGNED_INT,
                                        reinterpret_cast<const void*>(std::uintptr_t(from) * 12));
                     });
        lastTriangles += count;
    }

    /** The runs draw() draws with options: the stand-in's where it has one and is asked for. */
    const std::vector<MaterialRun>& drawnRuns(const DrawOptions& options) const {
        return options.standIn && standInVao ? standInRuns : runs;
    }

    /** Draws the parts of the blended (or other) runs in [from, end); at: where they start. */
    void drawRunsIn(const std::vector<MaterialRun>& drawn, bool blended, std::size_t from,
                    std::size_t end, std::size_t& at, RunDraw& state) {
        for (const MaterialRun& run : drawn) {
            if (blends(run, state.options.channel) != blended)
                continue;
            const std::size_t begin = at;
            at += run.triangleCount;
            if (at <= from || begin >= end)
                continue;
            const std::size_t skip = from > begin ? from - begin : 0;
            drawRun(run, skip, std::min(at, end) - begin - skip, state);
        }
    }

    void releaseStandIn() {
        if (standInVao)
            glDeleteVertexArrays(1, &standInVao);
        if (standInIbo)
            glDeleteBuffers(1, &standInIbo);
        standInVao = standInIbo = 0;
        standInRuns.clear();
    }

    void releaseMesh() {
        if (pending)
            unmapPending();
        pending.reset();
        releaseStandIn();
        if (vao)
            glDeleteVertexArrays(1, &vao);
        if (vbo)
            glDeleteBuffers(1, &vbo);
        if (ibo)
            glDeleteBuffers(1, &ibo);
        if (colorBuffer)
            glDeleteBuffers(1, &colorBuffer);
        if (tangentBuffer)
            glDeleteBuffers(1, &tangentBuffer);
        vao = vbo = ibo = colorBuffer = tangentBuffer = 0;
        vertexCount = 0;
        ++revision;
        if (ownTextures)
            textures->release();
        runs.clear();
        surfaces.clear();
        hasMesh = false;
    }
};

MeshRenderer::MeshRenderer() : m_impl(std::make_unique<Impl>()) {}

MeshRenderer::~MeshRenderer() {
    release();
}

core::Status MeshRenderer::initialize() {
    auto program = buildVariant(0);
    if (!program)
        return core::Error{program.error()};
    m_impl->programs[0] = std::move(program).value();
    m_impl->software = isSoftwareRenderer();
    return {};
}

void MeshRenderer::setMesh(const core::Mesh& mesh, std::shared_ptr<MaterialTextures> textures,
                           std::span<const std::uint32_t> shownBackFaces) {
    setMesh(mesh, mesh, std::move(textures), shownBackFaces);
}

void MeshRenderer::setMesh(const core::Mesh& geometry, const core::Mesh& look,
                           std::shared_ptr<MaterialTextures> textures,
                           std::span<const std::uint32_t> shownBackFaces) {
    if (const std::function<void()> fill =
            beginMesh(geometry, look, std::move(textures), shownBackFaces)) {
        fill();
        finishMesh();
    }
}

std::function<void()> MeshRenderer::beginMesh(const core::Mesh& geometry, const core::Mesh& look,
                                              std::shared_ptr<MaterialTextures> textures,
                                              std::span<const std::uint32_t> shownBackFaces) {
    const core::Mesh& mesh = geometry;
    Impl& d = *m_impl;
    d.releaseMesh();
    d.vertexCount = mesh.vertexCount();
    // Vertex colours only where the mesh has them (painting vertex colours gives them): a
    // buffer of white would cost 16 bytes a vertex for nothing.
    if (look.colors.size() == d.vertexCount && d.vertexCount > 0) {
        glCreateBuffers(1, &d.colorBuffer);
        glNamedBufferStorage(d.colorBuffer, GLsizeiptr(look.colors.size() * sizeof(glm::vec4)),
                             look.colors.data(), GL_DYNAMIC_STORAGE_BIT);
    }
    d.surfaces.clear();
    bool normalMaps = false;
    for (const core::Material& material : look.materials) {
        d.surfaces.push_back(SurfaceMaps::of(look.textures, mesh.hasUvs(), material));
        normalMaps = normalMaps || (d.surfaces.back().features() & kSurfaceNormalMap);
    }
    normalMaps = normalMaps && mesh.hasUvs(); // tangents need them
    // Written straight into the buffers: no copy is kept or made on the CPU.
    Impl::Pending& pending = d.pending.emplace();
    pending.vertices =
        static_cast<Vertex*>(d.mapNew(d.vbo, d.vertexCount * sizeof(Vertex), d.vertexCount > 0));
    pending.indices = static_cast<std::uint32_t*>(
        d.mapNew(d.ibo, mesh.indices.size() * sizeof(std::uint32_t), !mesh.indices.empty()));
    pending.tangents = static_cast<glm::vec4*>(
        d.mapNew(d.tangentBuffer, d.vertexCount * sizeof(glm::vec4), normalMaps));
    if ((d.vertexCount > 0 && !pending.vertices) || (!mesh.indices.empty() && !pending.indices) ||
        (normalMaps && !pending.tangents)) {
        d.releaseMesh(); // no GL memory for it: nothing drawn
        return {};
    }
    d.ownTextures = textures == nullptr;
    d.textures = d.ownTextures ? std::make_shared<MaterialTextures>() : std::move(textures);
    if (d.ownTextures)
        d.textures->create(look.textures);
    d.materials = look.materials;
    d.backFaceMaterials.assign(look.materials.size(), 0);
    for (const std::uint32_t t : shownBackFaces)
        if (t < mesh.triangleMaterial.size() && mesh.triangleMaterial[t] < look.materials.size())
            d.backFaceMaterials[mesh.triangleMaterial[t]] = 1;
    return [&mesh, &pending,
            backFaces = std::vector<std::uint32_t>(shownBackFaces.begin(), shownBackFaces.end())] {
        pending.fill(mesh, backFaces);
    };
}

void MeshRenderer::finishMesh() {
    Impl& d = *m_impl;
    if (!d.pending)
        return;
    const bool unmapped = d.unmapPending();
    const bool filled = d.pending->filled;
    std::vector<MaterialRun> runs = std::move(d.pending->runs);
    d.pending.reset();
    if (!unmapped || !filled) {
        d.releaseMesh(); // the buffers' contents were lost, or never written whole
        return;
    }
    d.vao = d.makeVao(d.ibo);
    d.runs = std::move(runs);
    d.hasMesh = true;
    ++d.revision;
}

bool MeshRenderer::hasMesh() const {
    return m_impl->hasMesh;
}

void MeshRenderer::setStandIn(std::span<const std::uint32_t> indices,
                              std::span<const std::uint32_t> triangleMaterial) {
    Impl& d = *m_impl;
    d.releaseStandIn();
    ++d.revision;
    const bool valid = d.hasMesh && !indices.empty() &&
                       indices.size() == triangleMaterial.size() * 3 &&
                       std::all_of(indices.begin(), indices.end(),
                                   [&](std::uint32_t v) { return v < d.vertexCount; }) &&
                       std::all_of(triangleMaterial.begin(), triangleMaterial.end(),
                                   [&](std::uint32_t m) { return m < d.materials.size(); });
    if (!valid)
        return;
    glCreateBuffers(1, &d.standInIbo);
    glNamedBufferStorage(d.standInIbo, GLsizeiptr(indices.size() * sizeof(std::uint32_t)),
                         indices.data(), 0);
    d.standInVao = d.makeVao(d.standInIbo);
    d.standInRuns = Impl::makeRuns(triangleMaterial, [&d](std::uint32_t, std::uint32_t m) {
        return d.backFaceMaterials[m] != 0;
    });
}

void MeshRenderer::clearStandIn() {
    m_impl->releaseStandIn();
    ++m_impl->revision;
}

bool MeshRenderer::hasStandIn() const {
    return m_impl->standInVao != 0;
}

std::size_t MeshRenderer::lastDrawnTriangles() const {
    return m_impl->lastTriangles;
}

MaterialTextures& MeshRenderer::textures() {
    return *m_impl->textures;
}

void MeshRenderer::updateVertexColors(std::uint32_t first, std::span<const glm::vec4> colors) {
    Impl& d = *m_impl;
    if (!d.colorBuffer || first >= d.vertexCount)
        return;
    const std::size_t count = std::min(colors.size(), d.vertexCount - first);
    ++d.revision;
    glNamedBufferSubData(d.colorBuffer, GLintptr(first) * GLintptr(sizeof(glm::vec4)),
                         GLsizeiptr(count * sizeof(glm::vec4)), colors.data());
}

void MeshRenderer::draw(const core::View& view, const DrawOptions& options) {
    drawSlice(view, options, 0, frameTriangles(options));
}

std::size_t MeshRenderer::frameTriangles(const DrawOptions& options) const {
    std::size_t triangles = 0;
    for (const MaterialRun& run : m_impl->drawnRuns(options))
        triangles += run.triangleCount;
    return triangles;
}

std::size_t MeshRenderer::drawSlice(const core::View& view, const DrawOptions& options,
                                    std::size_t from, std::size_t count) {
    Impl& d = *m_impl;
    glViewport(0, 0, view.width, view.height);
    if (options.clear && from == 0) {
        glClearColor(options.background.r, options.background.g, options.background.b,
                     options.background.a);
        glClearDepth(1.0);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    }
    d.lastTriangles = 0;
    const std::size_t triangles = frameTriangles(options);
    if (!d.hasMesh || !d.programs[0].valid())
        return triangles;
    const std::size_t end = from + std::min(count, triangles - std::min(from, triangles));
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glBindVertexArray(options.standIn && d.standInVao ? d.standInVao : d.vao);
    if (!d.colorBuffer)
        glVertexAttrib4f(3, 1.0f, 1.0f, 1.0f, 1.0f); // no vertex colours: white
    // Pieces as for the whole frame, so a slice is cut as its part of the frame would be.
    Impl::RunDraw state{view, options, nullptr,
                        drawPieces(d.software, triangles, std::size_t(view.width) * view.height)};
    // Blending materials last, over what is behind them, without hiding each other.
    std::size_t at = 0;
    for (const bool blended : {false, true}) {
        if (blended) {
            glEnable(GL_BLEND);
            glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
            glDepthMask(GL_FALSE);
        }
        d.drawRunsIn(d.drawnRuns(options), blended, from, end, at, state);
    }
    glDisable(GL_BLEND);
    glDepthMask(GL_TRUE);
    glBindVertexArray(0);
    glBindTextureUnit(1, 0);
    unbindSurfaceMaps();
    glUseProgram(0);
    return end;
}

std::uint64_t MeshRenderer::revision() const {
    return m_impl->revision;
}

void MeshRenderer::release() {
    if (!m_impl)
        return;
    m_impl->releaseMesh();
    m_impl->programs.clear();
    m_impl->failed.clear();
}

} // namespace render
