// SPDX-License-Identifier: GPL-3.0-or-later
// Shared by the fuzz targets: the loaders read files, so each input is written to a scratch file
// (in memory where /dev/shm exists) with the extension that picks the loader.
#pragma once

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>

#include <unistd.h>

#include "core/io/mesh_io.h"

namespace fuzz {

/** Writes size bytes to a per-process scratch file ending in extension; its path. */
inline std::string writeInput(const std::uint8_t* data, std::size_t size, const char* extension) {
    static const std::string folder = [] {
        std::filesystem::path base = std::filesystem::exists("/dev/shm")
                                         ? std::filesystem::path("/dev/shm")
                                         : std::filesystem::temp_directory_path();
        base /= "layerpaint-fuzz-" + std::to_string(::getpid());
        std::filesystem::create_directories(base);
        return base.string();
    }();
    const std::string path = folder + "/input" + extension;
    if (FILE* f = std::fopen(path.c_str(), "wb")) {
        if (size > 0)
            std::fwrite(data, 1, size, f);
        std::fclose(f);
    }
    return path;
}

/**
 * Limits small enough that a hostile input cannot make the harness run out of memory (the real
 * defaults allow hundreds of megabytes, which libFuzzer would report as a leak or an OOM).
 */
inline core::LoadLimits limits() {
    core::LoadLimits l;
    l.maxFileBytes = 4u << 20;
    l.maxVertices = 1u << 20;
    l.maxTriangles = 1u << 20;
    l.maxImagePixels = 1024u * 1024u;
    return l;
}

} // namespace fuzz
