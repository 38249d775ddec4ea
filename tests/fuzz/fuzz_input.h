// SPDX-License-Identifier: GPL-3.0-or-later
// Shared by the fuzz targets: the loaders read files, so each input is written to a scratch file
// with the extension that picks the loader.
#pragma once

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <string>
#include <utility>

#include <unistd.h>

#include "core/io/mesh_io.h"

namespace fuzz {

/** Writes size bytes to a per-process scratch file ending in extension; its path. */
inline std::string writeInput(const std::uint8_t* data, std::size_t size, const char* extension) {
    // One fixed folder (LAYERPAINT_FUZZ_SCRATCH, set by scripts/fuzz.sh): paths reach the
    // loaders' comparisons, whose operands feed libFuzzer's mutations, so a path that differs
    // between runs or machines (a process id, a home folder) would make runs differ.
    static const std::string folder = [] {
        const char* fixed = std::getenv("LAYERPAINT_FUZZ_SCRATCH");
        std::filesystem::path base = fixed != nullptr && *fixed != '\0'
                                         ? std::filesystem::path(fixed)
                                         : std::filesystem::temp_directory_path() /
                                               ("layerpaint-fuzz-" + std::to_string(::getpid()));
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
 * Whether (extension, bytes) is a file of the regression corpus, the folder named by the
 * environment variable LAYERPAINT_FUZZ_KNOWN_CRASHERS (tests/data/crashers). Those inputs crash
 * or hang third-party parsers inside the importer process, where the corpus test replays them;
 * here they would stop the run instead of letting it look further. scripts/fuzz.sh also adds
 * what earlier segments of the same run found, so that a restart does not stop on it again.
 */
inline bool isKnownCrasher(const char* extension, const std::uint8_t* data, std::size_t size) {
    static const std::set<std::pair<std::string, std::string>> known = [] {
        std::set<std::pair<std::string, std::string>> files;
        const char* folder = std::getenv("LAYERPAINT_FUZZ_KNOWN_CRASHERS");
        std::error_code ec;
        if (folder == nullptr || !std::filesystem::is_directory(folder, ec))
            return files;
        for (const auto& entry : std::filesystem::directory_iterator(folder, ec)) {
            std::string ext = entry.path().extension().string();
            std::transform(ext.begin(), ext.end(), ext.begin(),
                           [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
            std::ifstream in(entry.path(), std::ios::binary);
            files.emplace(ext, std::string(std::istreambuf_iterator<char>(in), {}));
        }
        return files;
    }();
    return !known.empty() &&
           known.count({extension, std::string(reinterpret_cast<const char*>(data), size)}) > 0;
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
