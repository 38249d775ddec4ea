// SPDX-License-Identifier: GPL-3.0-or-later
// Reading the binary glTF container's header and chunk headers (see glb_container.h).
#include "core/io/gltf/glb_container.h"

#include <cstring>
#include <string>

namespace core::glb {

namespace {

std::uint32_t u32(std::span<const std::uint8_t> bytes, std::uint64_t at) {
    std::uint32_t v = 0;
    std::memcpy(&v, bytes.data() + at, 4);
    return v;
}

} // namespace

bool hasMagic(std::span<const std::uint8_t> bytes) {
    return bytes.size() >= 4 && u32(bytes, 0) == kMagic;
}

Result<Layout> readHead(std::span<const std::uint8_t> head, std::uint64_t fileSize) {
    if (fileSize < 12 || head.size() < 12)
        return badInput("the binary glTF file is truncated (no complete header)");
    const std::uint32_t version = u32(head, 4);
    if (version != 2)
        return Error{"binary glTF version " + std::to_string(version) +
                         " is not supported (only 2)",
                     ErrorKind::Unsupported};
    const std::uint64_t length = u32(head, 8);
    if (length > fileSize)
        return badInput("the binary glTF file is truncated (the header says " +
                        std::to_string(length) + " bytes, the file has " +
                        std::to_string(fileSize) + ")");
    if (length < kHeadBytes || head.size() < kHeadBytes)
        return badInput("the binary glTF file is truncated (no JSON chunk)");
    const std::uint64_t jsonLength = u32(head, 12);
    if (u32(head, 16) != kChunkJson)
        return badInput("the first chunk of the binary glTF file is not JSON");
    if (jsonLength == 0 || kHeadBytes + jsonLength > length)
        return badInput("the binary glTF file is truncated (the JSON chunk runs past the end)");
    return Layout{kHeadBytes, jsonLength, length};
}

Result<Layout> readContainer(std::span<const std::uint8_t> bytes) {
    Result<Layout> layout = readHead(bytes, bytes.size());
    if (!layout)
        return layout;
    const std::uint64_t length = layout->length;
    const std::uint64_t binHeader = kHeadBytes + layout->jsonLength;
    if (binHeader < length) {
        if (binHeader + 8 > length)
            return badInput("the binary glTF file is truncated (incomplete BIN chunk header)");
        const std::uint64_t binLength = u32(bytes, binHeader);
        if (u32(bytes, binHeader + 4) != kChunkBin)
            return badInput("the second chunk of the binary glTF file is not BIN");
        if (binHeader + 8 + binLength > length)
            return badInput("the binary glTF file is truncated (the BIN chunk runs past the end)");
    }
    return layout;
}

} // namespace core::glb
