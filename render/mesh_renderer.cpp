// SPDX-License-Identifier: GPL-3.0-or-later
#include "render/mesh_renderer.h"

#include <vector>

#include <epoxy/gl.h>
#include <glm/gtc/type_ptr.hpp>

#include "render/shader_library.h"

namespace render {

namespace {
struct Vertex {
    glm::vec3 position;
    glm::vec3 normal;
    glm::vec2 uv;
    glm::vec4 color;
};

/** A range of consecutive triangles sharing one material (triangle order is kept). */
struct MaterialRun {
    std::uint32_t firstTriangle;
    std::uint32_t triangleCount;
    std::uint32_t material;
};
} // namespace

struct MeshRenderer::Impl {
    ShaderProgram program;
    GLuint vao = 0, vbo = 0, ibo = 0;
    std::vector<GLuint> textures;
    std::vector<core::Material> materials;
    std::vector<MaterialRun> runs;
    bool hasMesh = false;

    void releaseMesh() {
        if (vao)
            glDeleteVertexArrays(1, &vao);
        if (vbo)
            glDeleteBuffers(1, &vbo);
        if (ibo)
            glDeleteBuffers(1, &ibo);
        if (!textures.empty())
            glDeleteTextures(GLsizei(textures.size()), textures.data());
        vao = vbo = ibo = 0;
        textures.clear();
        runs.clear();
        hasMesh = false;
    }
};

MeshRenderer::MeshRenderer() : m_impl(std::make_unique<Impl>()) {}

MeshRenderer::~MeshRenderer() {
    release();
}

core::Status MeshRenderer::initialize() {
    auto program = ShaderProgram::build({"mesh.vert", "mesh.frag"});
    if (!program)
        return core::Error{program.error()};
    m_impl->program = std::move(program).value();
    return {};
}

void MeshRenderer::setMesh(const core::Mesh& mesh) {
    Impl& d = *m_impl;
    d.releaseMesh();

    std::vector<Vertex> vertices(mesh.vertexCount());
    for (std::size_t i = 0; i < vertices.size(); ++i) {
        vertices[i] = {mesh.positions[i], mesh.normals[i],
                       mesh.hasUvs() ? mesh.uvs[i] : glm::vec2(0.0f),
                       mesh.hasColors() ? mesh.colors[i] : glm::vec4(1.0f)};
    }
    glCreateBuffers(1, &d.vbo);
    glNamedBufferStorage(d.vbo, GLsizeiptr(vertices.size() * sizeof(Vertex)), vertices.data(), 0);
    glCreateBuffers(1, &d.ibo);
    glNamedBufferStorage(d.ibo, GLsizeiptr(mesh.indices.size() * sizeof(std::uint32_t)),
                         mesh.indices.data(), 0);

    glCreateVertexArrays(1, &d.vao);
    glVertexArrayVertexBuffer(d.vao, 0, d.vbo, 0, sizeof(Vertex));
    glVertexArrayElementBuffer(d.vao, d.ibo);
    const auto attribute = [&](GLuint location, GLint size, GLuint offset) {
        glEnableVertexArrayAttrib(d.vao, location);
        glVertexArrayAttribFormat(d.vao, location, size, GL_FLOAT, GL_FALSE, offset);
        glVertexArrayAttribBinding(d.vao, location, 0);
    };
    attribute(0, 3, offsetof(Vertex, position));
    attribute(1, 3, offsetof(Vertex, normal));
    attribute(2, 2, offsetof(Vertex, uv));
    attribute(3, 4, offsetof(Vertex, color));

    for (const core::Image& image : mesh.textures) {
        GLuint texture = 0;
        glCreateTextures(GL_TEXTURE_2D, 1, &texture);
        int levels = 1;
        for (int size = std::max(image.width, image.height); size > 1; size /= 2)
            ++levels;
        glTextureStorage2D(texture, levels, GL_SRGB8_ALPHA8, image.width, image.height);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        glTextureSubImage2D(texture, 0, 0, 0, image.width, image.height, GL_RGBA, GL_UNSIGNED_BYTE,
                            image.rgba.data());
        glGenerateTextureMipmap(texture);
        glTextureParameteri(texture, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
        glTextureParameteri(texture, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glTextureParameteri(texture, GL_TEXTURE_WRAP_S, GL_REPEAT);
        glTextureParameteri(texture, GL_TEXTURE_WRAP_T, GL_REPEAT);
        d.textures.push_back(texture);
    }
    d.materials = mesh.materials;

    for (std::uint32_t t = 0; t < mesh.triangleCount(); ++t) {
        const std::uint32_t m = mesh.triangleMaterial[t];
        if (d.runs.empty() || d.runs.back().material != m)
            d.runs.push_back({t, 0, m});
        ++d.runs.back().triangleCount;
    }
    d.hasMesh = true;
}

bool MeshRenderer::hasMesh() const {
    return m_impl->hasMesh;
}

void MeshRenderer::draw(const core::View& view, const DrawOptions& options) {
    Impl& d = *m_impl;
    glViewport(0, 0, view.width, view.height);
    if (options.clear) {
        glClearColor(options.background.r, options.background.g, options.background.b,
                     options.background.a);
        glClearDepth(1.0);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    }
    if (!d.hasMesh || !d.program.valid())
        return;
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    if (options.cullBackFaces)
        glEnable(GL_CULL_FACE);
    else
        glDisable(GL_CULL_FACE);
    d.program.use();
    glUniformMatrix4fv(d.program.uniform("uView"), 1, GL_FALSE, glm::value_ptr(view.view));
    glUniformMatrix4fv(d.program.uniform("uProj"), 1, GL_FALSE, glm::value_ptr(view.proj));
    glUniform1i(d.program.uniform("uBaseColorTexture"), 0);
    const GLint factorLocation = d.program.uniform("uBaseColorFactor");
    const GLint hasTextureLocation = d.program.uniform("uHasTexture");
    glBindVertexArray(d.vao);
    for (const MaterialRun& run : d.runs) {
        const core::Material& material = d.materials[run.material];
        glUniform4fv(factorLocation, 1, glm::value_ptr(material.baseColorFactor));
        const bool textured = material.baseColorTexture >= 0;
        glUniform1i(hasTextureLocation, textured);
        if (textured)
            glBindTextureUnit(0, d.textures[std::size_t(material.baseColorTexture)]);
        glDrawElements(GL_TRIANGLES, GLsizei(run.triangleCount * 3), GL_UNSIGNED_INT,
                       reinterpret_cast<const void*>(std::uintptr_t(run.firstTriangle) * 12));
    }
    glBindVertexArray(0);
    glUseProgram(0);
}

void MeshRenderer::release() {
    if (!m_impl)
        return;
    m_impl->releaseMesh();
    m_impl->program = ShaderProgram();
}

} // namespace render
