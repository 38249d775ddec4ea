// SPDX-License-Identifier: GPL-3.0-or-later
// The GLB container checks shared by the loader, the project reader and the writer.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "core/io/gltf/glb_container.h"

namespace glb_container_test {

using Bytes = std::vector<std::uint8_t>;

void put(Bytes& b, std::size_t at, std::uint32_t v) {
    std::memcpy(b.data() + at, &v, 4);
}

/** A GLB with a JSON chunk of jsonLength bytes and a BIN chunk of binLength bytes. */
Bytes makeGlb(std::uint32_t jsonLength, std::uint32_t binLength) {
    Bytes b(20 + jsonLength + 8 + binLength, 0);
    put(b, 0, core::glb::kMagic);
    put(b, 4, 2);
    put(b, 8, static_cast<std::uint32_t>(b.size()));
    put(b, 12, jsonLength);
    put(b, 16, core::glb::kChunkJson);
    put(b, 20 + jsonLength, binLength);
    put(b, 24 + jsonLength, core::glb::kChunkBin);
    return b;
}

std::string problem(const Bytes& b) {
    const core::Result<core::glb::Layout> layout = core::glb::readContainer(b);
    EXPECT_FALSE(layout.ok());
    return layout.ok() ? std::string() : layout.error();
}

TEST(GlbContainer, ReadsTheLayoutOfAWellFormedFile) {
    const Bytes b = makeGlb(12, 16);
    ASSERT_TRUE(core::glb::hasMagic(b));
    const core::Result<core::glb::Layout> layout = core::glb::readContainer(b);
    ASSERT_TRUE(layout.ok()) << layout.error();
    EXPECT_EQ(layout->jsonOffset, 20u);
    EXPECT_EQ(layout->jsonLength, 12u);
    EXPECT_EQ(layout->length, b.size());
    // The head alone gives the same JSON chunk.
    const core::Result<core::glb::Layout> head =
        core::glb::readHead(std::span(b).first(core::glb::kHeadBytes), b.size());
    ASSERT_TRUE(head.ok()) << head.error();
    EXPECT_EQ(head->jsonLength, 12u);
}

TEST(GlbContainer, NamesWhatIsWrong) {
    EXPECT_FALSE(core::glb::hasMagic(Bytes{'g', 'l'}));
    EXPECT_NE(problem(Bytes(8, 0)).find("no complete header"), std::string::npos);

    Bytes b = makeGlb(12, 16);
    put(b, 4, 1);
    const core::Result<core::glb::Layout> v1 = core::glb::readContainer(b);
    ASSERT_FALSE(v1.ok());
    EXPECT_EQ(v1.error(), "binary glTF version 1 is not supported (only 2)");
    EXPECT_EQ(v1.errorKind(), core::ErrorKind::Unsupported);

    b = makeGlb(12, 16);
    put(b, 8, static_cast<std::uint32_t>(b.size() + 1));
    EXPECT_NE(problem(b).find("the header says"), std::string::npos);
    b = makeGlb(12, 16);
    put(b, 16, core::glb::kChunkBin);
    EXPECT_NE(problem(b).find("first chunk of the binary glTF file is not JSON"),
              std::string::npos);
    b = makeGlb(12, 16);
    put(b, 12, 12 + 8 + 16 + 4);
    EXPECT_NE(problem(b).find("JSON chunk runs past the end"), std::string::npos);
    b = makeGlb(12, 16);
    put(b, 24 + 12, core::glb::kChunkJson);
    EXPECT_NE(problem(b).find("second chunk of the binary glTF file is not BIN"),
              std::string::npos);
    b = makeGlb(12, 16);
    put(b, 20 + 12, 17);
    EXPECT_NE(problem(b).find("BIN chunk runs past the end"), std::string::npos);
    b = makeGlb(12, 0);
    b.resize(b.size() - 4);
    put(b, 8, static_cast<std::uint32_t>(b.size()));
    EXPECT_NE(problem(b).find("incomplete BIN chunk header"), std::string::npos);
    // The error is about the file: BadInput.
    EXPECT_EQ(core::glb::readContainer(b).errorKind(), core::ErrorKind::BadInput);
}

} // namespace glb_container_test
