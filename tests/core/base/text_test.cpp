// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include <filesystem>

#include "core/base/text.h"

TEST(Text, AsciiLowerChangesOnlyAsciiLetters) {
    EXPECT_EQ(core::asciiLower("LLVMpipe (LLVM 15.0.6, 256 bits)"),
              "llvmpipe (llvm 15.0.6, 256 bits)");
    EXPECT_EQ(core::asciiLower(""), "");
    // UTF-8 bytes pass through unchanged: "Ä" stays, "Ü" stays.
    EXPECT_EQ(core::asciiLower("\xC3\x84X\xC3\x9C"), "\xC3\x84x\xC3\x9C");
    EXPECT_EQ(core::asciiLower("@[`{"), "@[`{"); // the neighbours of A-Z and a-z
}

TEST(Text, LowerExtensionKeepsTheDot) {
    EXPECT_EQ(core::lowerExtension("Horse.GLB"), ".glb");
    EXPECT_EQ(core::lowerExtension(std::filesystem::path("dir.X") / "model.Obj"), ".obj");
    EXPECT_EQ(core::lowerExtension("README"), "");
    EXPECT_EQ(core::lowerExtension("archive.tar.GZ"), ".gz");
}

TEST(Text, PrintableEscapesControlCharactersAndCuts) {
    EXPECT_EQ(core::printable("Layer 1"), "Layer 1");
    // A newline cannot forge a second message line; a terminal escape cannot act.
    EXPECT_EQ(core::printable("a\nlayerpaint-cli: b"), "a\\nlayerpaint-cli: b");
    EXPECT_EQ(core::printable("\x1b[31mred\t\r"), "\\x1b[31mred\\t\\r");
    EXPECT_EQ(core::printable(std::string(1 << 20, 'x')), std::string(80, 'x') + "…");
    // Cut after whole characters: 80 "Ä" (2 bytes each) stay, the 81st goes.
    std::string umlauts;
    for (int i = 0; i < 81; ++i)
        umlauts += "\xC3\x84";
    EXPECT_EQ(core::printable(umlauts), umlauts.substr(0, 160) + "…");
    EXPECT_EQ(core::printable("abcdef", 3), "abc…");
}
