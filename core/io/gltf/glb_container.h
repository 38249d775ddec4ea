// SPDX-License-Identifier: GPL-3.0-or-later
// The binary glTF (GLB) container: its 12-byte header and the JSON and BIN chunk headers. The
// loader, the project reader (which reads only the JSON) and the writer share these.
#pragma once

#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

#include "core/base/result.h"

namespace core::glb {

constexpr std::uint32_t kMagic = 0x46546C67u;     // "glTF"
constexpr std::uint32_t kChunkJson = 0x4E4F534Au; // "JSON"
constexpr std::uint32_t kChunkBin = 0x004E4942u;  // "BIN\0"
constexpr std::uint64_t kHeadBytes = 20;          // the header and the JSON chunk's header

/** Whether bytes start with the GLB magic. */
bool hasMagic(std::span<const std::uint8_t> bytes);

/** Where the JSON chunk is, and the length the header declares (all tinygltf may see). */
struct Layout {
    std::uint64_t jsonOffset = 0, jsonLength = 0;
    std::uint64_t length = 0;
};

/**
 * Checks the header and the JSON chunk's header of a GLB file of fileSize bytes, given at least
 * its first kHeadBytes bytes (or the whole file when it is shorter): version 2, a declared length
 * within the file, a non-empty JSON chunk first that ends within it. The Error names no file.
 */
Result<Layout> readHead(std::span<const std::uint8_t> head, std::uint64_t fileSize);

/**
 * readHead() on a whole file, then the BIN chunk's header where there is one: the chunk type and
 * a length that ends within the declared length (tinygltf 2.7 lets it run 8 bytes further).
 */
Result<Layout> readContainer(std::span<const std::uint8_t> bytes);

/**
 * A GLB like bytes (laid out as layout) with json in place of its JSON chunk (padded with
 * spaces) and the rest (the BIN chunk) as it was.
 */
std::vector<std::uint8_t> replaceJson(std::span<const std::uint8_t> bytes, const Layout& layout,
                                      std::string_view json);

} // namespace core::glb
