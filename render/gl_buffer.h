// SPDX-License-Identifier: GPL-3.0-or-later
// Internal to render's .cpp files (it includes the GL header): one shader storage buffer.
#pragma once

#include <cstddef>

#include <epoxy/gl.h>

namespace render {

/**
 * Immutable storage of a fixed size. With mapping flags (GL_MAP_READ_BIT / GL_MAP_WRITE_BIT) it
 * is mapped persistently and coherently, so the CPU reads or writes it in place; without, it takes
 * glNamedBufferSubData uploads. Freed explicitly (the context must be current).
 */
struct GlStorageBuffer {
    GLuint id = 0;
    void* data = nullptr; // the mapping, for a mapped buffer
    std::size_t bytes = 0;

    /** Replaces the storage with size bytes; false (and nothing allocated) on a GL error. */
    bool allocate(std::size_t size, GLbitfield mapping) {
        free();
        const GLbitfield flags = mapping ? mapping | GL_MAP_PERSISTENT_BIT | GL_MAP_COHERENT_BIT
                                         : GL_DYNAMIC_STORAGE_BIT;
        while (glGetError() != GL_NO_ERROR) {
        }
        glCreateBuffers(1, &id);
        glNamedBufferStorage(id, GLsizeiptr(size), nullptr, flags);
        if (glGetError() != GL_NO_ERROR ||
            (mapping && !(data = glMapNamedBufferRange(id, 0, GLsizeiptr(size), flags)))) {
            free();
            return false;
        }
        bytes = size;
        return true;
    }

    void free() {
        if (id) {
            if (data)
                glUnmapNamedBuffer(id);
            glDeleteBuffers(1, &id);
        }
        id = 0;
        data = nullptr;
        bytes = 0;
    }
};

} // namespace render
