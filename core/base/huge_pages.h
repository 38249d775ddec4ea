// SPDX-License-Identifier: GPL-3.0-or-later
// Large allocations on transparent huge pages, for the executables' main().
#pragma once

#include <string_view>

namespace core {

/** What GLIBC_TUNABLES holds for glibc's malloc to ask the kernel for huge pages. */
inline constexpr std::string_view kHugePagesTunable = "glibc.malloc.hugetlb=1";

/**
 * Whether a process started with tunables (the value of GLIBC_TUNABLES, nullptr when unset)
 * should start again with kHugePagesTunable: the kernel gives transparent huge pages on request
 * (thpMode is /sys/kernel/mm/transparent_hugepage/enabled, "[madvise]" chosen), the setting is
 * not there yet, and optOut (LAYERPAINT_HUGE_PAGES) is not "0".
 */
bool wantsHugePageRestart(const char* tunables, std::string_view thpMode, const char* optOut);

/** Whether this process's malloc was started with kHugePagesTunable. */
bool usesHugePages();

/**
 * Starts the program again (the same executable and arguments) with kHugePagesTunable added to
 * GLIBC_TUNABLES when wantsHugePageRestart() says so; glibc reads the setting only when a
 * process starts. Returns when there is nothing to do or the start fails. Call first in main(),
 * before any thread. On a virtual machine a page fault every 4 KiB makes filling a large mesh's
 * arrays (and the GL's copies of them) slow: docs/performance.md.
 */
void restartWithHugePages(char** argv);

} // namespace core
