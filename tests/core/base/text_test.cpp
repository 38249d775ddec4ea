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
