// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace core {

/**
 * text with its ASCII letters in lower case; every other byte (UTF-8 included) as it is, whatever
 * the locale. For names the program compares: extensions, renderer and option names.
 */
inline std::string asciiLower(std::string_view text) {
    std::string out(text);
    for (char& c : out)
        c = char(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
    return out;
}

/** The extension of path, with its dot, in lower case: ".glb" for "Horse.GLB". */
inline std::string lowerExtension(const std::filesystem::path& path) {
    return asciiLower(path.extension().string());
}

} // namespace core
