// SPDX-License-Identifier: GPL-3.0-or-later
// Reading the binary glTF container's header and chunk headers (see glb_container.h).
#include "core/io/gltf/glb_container.h"

#include <algorithm>
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

std::vector<std::uint8_t> replaceJson(std::span<const std::uint8_t> bytes, const Layout& layout,
                                      std::string_view json) {
    std::string text(json);
    while (text.size() % 4 != 0)
        text.push_back(' ');
    const std::uint64_t restStart = layout.jsonOffset + layout.jsonLength;
    const std::uint64_t restEnd = std::max(restStart, layout.length);
    std::vector<std::uint8_t> out(12);
    auto put32 = [&out](std::size_t at, std::uint64_t v) {
        const auto u = static_cast<std::uint32_t>(v);
        std::memcpy(out.data() + at, &u, 4);
    };
    put32(0, kMagic);
    put32(4, 2);
    out.resize(20);
    put32(12, text.size());
    put32(16, kChunkJson);
    out.insert(out.end(), text.begin(), text.end());
    out.insert(out.end(), bytes.begin() + static_cast<std::ptrdiff_t>(restStart),
               bytes.begin() + static_cast<std::ptrdiff_t>(restEnd));
    put32(8, out.size());
    return out;
}

} // namespace core::glb
