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

/**
 * message without a leading "path: ": for a message that is about to be named after the same
 * file again (one file name per message).
 */
inline std::string withoutFileName(std::string_view path, std::string_view message) {
    if (!path.empty() && message.size() > path.size() + 1 &&
        message.substr(0, path.size()) == path && message.substr(path.size(), 2) == ": ")
        message.remove_prefix(path.size() + 2);
    return std::string(message);
}

/**
 * name as a part of a file name: letters, digits, '-' and '_' kept, runs of anything else one
 * '-', at most maxChars characters; fallback when nothing is left.
 */
inline std::string fileNamePart(std::string_view name, std::string_view fallback,
                                std::size_t maxChars = 40) {
    std::string out;
    for (const char ch : name) {
        const auto c = static_cast<unsigned char>(ch);
        const bool keep = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') ||
                          (c >= '0' && c <= '9') || c == '-' || c == '_';
        if (keep)
            out.push_back(ch);
        else if (!out.empty() && out.back() != '-')
            out.push_back('-');
        if (out.size() >= maxChars)
            break;
    }
    while (!out.empty() && out.back() == '-')
        out.pop_back();
    return out.empty() ? std::string(fallback) : out;
}

/**
 * text from a file, safe to put into a message: control characters escaped (\n, \r, \t, \xNN)
 * and cut after maxChars characters (UTF-8 sequences kept whole) with "…".
 */
inline std::string printable(std::string_view text, std::size_t maxChars = 80) {
    static const char* const kHex = "0123456789abcdef";
    std::string out;
    std::size_t chars = 0;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const auto c = static_cast<unsigned char>(text[i]);
        const bool starts = (c & 0xC0) != 0x80; // not a UTF-8 continuation byte
        if (starts && chars++ == maxChars) {
            out += "…";
            break;
        }
        if (c == '\n')
            out += "\\n";
        else if (c == '\r')
            out += "\\r";
        else if (c == '\t')
            out += "\\t";
        else if (c < 0x20 || c == 0x7F)
            out += std::string("\\x") + kHex[c >> 4] + kHex[c & 15];
        else
            out += char(c);
    }
    return out;
}

} // namespace core
