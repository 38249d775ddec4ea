// SPDX-License-Identifier: GPL-3.0-or-later
#include "render/shader_library.h"

#include <cstring>
#include <regex>
#include <vector>

#include <epoxy/gl.h>

namespace render {

std::string_view shaderSource(std::string_view name) {
    for (int i = 0; i < detail::kEmbeddedShaderCount; ++i)
        if (name == detail::kEmbeddedShaders[i].name)
            return detail::kEmbeddedShaders[i].source;
    return {};
}

namespace {
GLenum stageOf(std::string_view file) {
    if (file.ends_with(".vert"))
        return GL_VERTEX_SHADER;
    if (file.ends_with(".frag"))
        return GL_FRAGMENT_SHADER;
    if (file.ends_with(".comp"))
        return GL_COMPUTE_SHADER;
    if (file.ends_with(".geom"))
        return GL_GEOMETRY_SHADER;
    return 0;
}

/** Rewrites the driver's "0:12(3):" (Mesa) or "0(12) :" (NVIDIA) as "file.frag:12:". */
std::string withFileNames(const std::string& log, std::string_view file) {
    static const std::regex mesa(R"((^|\n)0:(\d+)\((\d+)\):)");
    static const std::regex nvidia(R"((^|\n)0\((\d+)\) :)");
    const std::string name(file);
    return std::regex_replace(std::regex_replace(log, mesa, "$1" + name + ":$2:$3:"), nvidia,
                              "$1" + name + ":$2:");
}
} // namespace

ShaderProgram::~ShaderProgram() {
    if (m_id)
        glDeleteProgram(m_id);
}

ShaderProgram::ShaderProgram(ShaderProgram&& other) noexcept : m_id(other.m_id) {
    other.m_id = 0;
}

ShaderProgram& ShaderProgram::operator=(ShaderProgram&& other) noexcept {
    if (this != &other) {
        if (m_id)
            glDeleteProgram(m_id);
        m_id = other.m_id;
        other.m_id = 0;
    }
    return *this;
}

core::Result<ShaderProgram> ShaderProgram::build(std::initializer_list<std::string_view> files,
                                                 const std::vector<std::string>& defines) {
    // The variant's defines after the #version line, and a #line that keeps the file's numbers.
    std::string defineLines, variant;
    for (const std::string& name : defines) {
        defineLines += "#define " + name + "\n";
        variant += (variant.empty() ? "" : " ") + name;
    }
    if (!defineLines.empty()) {
        defineLines += "#line 2\n";
        variant = " (" + variant + ")";
    }
    ShaderProgram program;
    program.m_id = glCreateProgram();
    std::vector<GLuint> shaders;
    const auto cleanup = [&] {
        for (GLuint s : shaders)
            glDeleteShader(s);
    };
    for (std::string_view file : files) {
        std::string source(shaderSource(file));
        const GLenum stage = stageOf(file);
        const std::size_t firstLine = source.find('\n');
        if (source.empty() || stage == 0 || (!defines.empty() && firstLine == std::string::npos)) {
            cleanup();
            return core::Error{"shader " + std::string(file) + ": not embedded in this build"};
        }
        if (!defineLines.empty())
            source.insert(firstLine + 1, defineLines);
        const GLuint shader = glCreateShader(stage);
        shaders.push_back(shader);
        const char* text = source.data();
        const GLint length = GLint(source.size());
        glShaderSource(shader, 1, &text, &length);
        glCompileShader(shader);
        GLint ok = GL_FALSE;
        glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
        if (!ok) {
            GLint logLength = 0;
            glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &logLength);
            std::string log(std::size_t(std::max(logLength, 1)), '\0');
            glGetShaderInfoLog(shader, logLength, nullptr, log.data());
            cleanup();
            return core::Error{"shader " + std::string(file) + variant + " failed to compile:\n" +
                               withFileNames(log.c_str(), file)};
        }
        glAttachShader(program.m_id, shader);
    }
    glLinkProgram(program.m_id);
    cleanup();
    GLint ok = GL_FALSE;
    glGetProgramiv(program.m_id, GL_LINK_STATUS, &ok);
    if (!ok) {
        GLint logLength = 0;
        glGetProgramiv(program.m_id, GL_INFO_LOG_LENGTH, &logLength);
        std::string log(std::size_t(std::max(logLength, 1)), '\0');
        glGetProgramInfoLog(program.m_id, logLength, nullptr, log.data());
        std::string names;
        for (std::string_view f : files)
            names += (names.empty() ? "" : ", ") + std::string(f);
        return core::Error{"shader program (" + names + ")" + variant + " failed to link:\n" +
                           log.c_str()};
    }
    return program;
}

void ShaderProgram::use() const {
    glUseProgram(m_id);
}

int ShaderProgram::uniform(const char* name) const {
    return glGetUniformLocation(m_id, name);
}

void ShaderProgram::locate(std::initializer_list<std::pair<int*, const char*>> uniforms) const {
    for (const auto& [location, name] : uniforms)
        *location = uniform(name);
}

} // namespace render
