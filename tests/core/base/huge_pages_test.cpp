// SPDX-License-Identifier: GPL-3.0-or-later
// When the executables start again with glibc's huge-page setting.
#include <gtest/gtest.h>

#include "core/base/huge_pages.h"

namespace huge_pages_test {

constexpr const char* kMadvise = "always [madvise] never\n";

TEST(HugePages, AProcessStartsAgainOnlyWhenTheKernelGivesThemOnRequestAndTheSettingIsMissing) {
    EXPECT_TRUE(core::wantsHugePageRestart(nullptr, kMadvise, nullptr));
    EXPECT_TRUE(core::wantsHugePageRestart("glibc.malloc.check=0", kMadvise, nullptr));
    EXPECT_TRUE(core::wantsHugePageRestart(nullptr, kMadvise, "1"));
    // Set already (by the start before, or by the user, either way): never again, no loop.
    EXPECT_FALSE(core::wantsHugePageRestart("glibc.malloc.hugetlb=1", kMadvise, nullptr));
    EXPECT_FALSE(core::wantsHugePageRestart("a=1:glibc.malloc.hugetlb=0", kMadvise, nullptr));
    // Given without asking, or not at all; or turned off.
    EXPECT_FALSE(core::wantsHugePageRestart(nullptr, "[always] madvise never\n", nullptr));
    EXPECT_FALSE(core::wantsHugePageRestart(nullptr, "always madvise [never]\n", nullptr));
    EXPECT_FALSE(core::wantsHugePageRestart(nullptr, "", nullptr));
    EXPECT_FALSE(core::wantsHugePageRestart(nullptr, kMadvise, "0"));
}

} // namespace huge_pages_test
