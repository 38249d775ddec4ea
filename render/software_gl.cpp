// SPDX-License-Identifier: GPL-3.0-or-later
#include "render/software_gl.h"

#include <algorithm>
#include <string>

#include <epoxy/gl.h>

#include "core/base/text.h"

namespace render {

bool isSoftwareRenderer(std::string_view rendererName) {
    const std::string name = core::asciiLower(rendererName);
    for (const char* software : {"llvmpipe", "softpipe", "swiftshader", "software rasterizer"})
        if (name.find(software) != std::string::npos)
            return true;
    return false;
}

bool isSoftwareRenderer() {
    const auto* name = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    return name && isSoftwareRenderer(std::string_view(name));
}

int drawPieces(bool software, std::size_t triangles, std::size_t pixels) {
    return software && triangles * kPixelsPerTriangleToCut >= pixels ? kSoftwareDrawPieces : 1;
}

void drawInPieces(std::size_t first, std::size_t count, int pieces,
                  const std::function<void(std::size_t first, std::size_t count)>& draw) {
    const std::size_t cut = std::size_t(std::max(pieces, 1));
    const std::size_t piece = std::max(kMinDrawPiece, (count + cut - 1) / cut);
    for (std::size_t done = 0; done < count;) {
        const std::size_t size = std::min(piece, count - done);
        draw(first + done, size);
        done += size;
        if (done < count)
            glFlush();
    }
}

} // namespace render
