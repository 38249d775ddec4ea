// SPDX-License-Identifier: GPL-3.0-or-later
// Internal to render's .cpp files (it includes the GL header): one GL buffer.
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

#include <epoxy/gl.h>

namespace render {

/**
 * A buffer with immutable storage, kept while new data fits so that a rebuild does not
 * reallocate. With mapping flags (GL_MAP_READ_BIT / GL_MAP_WRITE_BIT) it is mapped persistently
 * and coherently, so the CPU reads or writes it in place; without, it takes glNamedBufferSubData
 * uploads or a mapping for one write. Freed explicitly (the context must be current).
 */
struct GlBuffer {
    GLuint id = 0;
    void* data = nullptr;  // the mapping, for a mapped buffer
    std::size_t bytes = 0; // the storage's size

    /** Replaces the storage with size bytes; false (and nothing allocated) on a GL error. */
    bool allocate(std::size_t size, GLbitfield mapping = 0) {
        free();
        const GLbitfield flags = mapping ? mapping | GL_MAP_PERSISTENT_BIT | GL_MAP_COHERENT_BIT
                                         : GL_DYNAMIC_STORAGE_BIT | GL_MAP_WRITE_BIT;
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

    /**
     * Keeps the storage if it holds size bytes, else allocates allocation bytes (at least size:
     * the caller's headroom); false (and nothing allocated) on a GL error.
     */
    bool reserve(std::size_t size, std::size_t allocation, GLbitfield mapping = 0) {
        if (id && size <= bytes)
            return true;
        return allocate(std::max(size, allocation), mapping);
    }

    /**
     * An unmapped buffer's upload: makes room for size bytes (allocation bytes when it grows, as
     * reserve()) and stores those at source, if not null. False if GL could not allocate.
     */
    bool upload(const void* source, std::size_t size, std::size_t allocation) {
        if (!reserve(size, allocation))
            return false;
        if (source && size > 0)
            glNamedBufferSubData(id, 0, GLsizeiptr(size), source);
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
