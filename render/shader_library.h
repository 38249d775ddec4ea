// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <initializer_list>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/base/result.h"

namespace render {

namespace detail {
struct EmbeddedShader {
    const char* name;
    const char* source;
};
extern const EmbeddedShader kEmbeddedShaders[];
extern const int kEmbeddedShaderCount;
} // namespace detail

/** The source of an embedded file from shaders/ by file name, or empty if there is none. */
std::string_view shaderSource(std::string_view name);

/**
 * A linked GL program built from embedded shader files; the stage comes from the extension
 * (.vert, .frag, .comp). Needs a current context. Move-only; deletes the program when destroyed.
 */
class ShaderProgram {
public:
    ShaderProgram() = default;
    ~ShaderProgram();
    ShaderProgram(ShaderProgram&& other) noexcept;
    ShaderProgram& operator=(ShaderProgram&& other) noexcept;
    ShaderProgram(const ShaderProgram&) = delete;
    ShaderProgram& operator=(const ShaderProgram&) = delete;

    /**
     * Compiles and links; a failure names the file and line from the driver's log. Each of
     * defines becomes a "#define NAME" line after every file's #version line (a feature variant
     * of the same files; line numbers stay those of the file), and is named in a failure.
     */
    static core::Result<ShaderProgram> build(std::initializer_list<std::string_view> files,
                                             const std::vector<std::string>& defines = {});

    unsigned id() const { return m_id; }
    bool valid() const { return m_id != 0; }
    void use() const;
    int uniform(const char* name) const;
    /** Sets each location to its named uniform's (-1 where the program has none). */
    void locate(std::initializer_list<std::pair<int*, const char*>> uniforms) const;

private:
    unsigned m_id = 0;
};

} // namespace render
