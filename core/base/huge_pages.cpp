// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/base/huge_pages.h"

#include <cstdlib>
#include <fstream>
#include <iterator>
#include <string>

#include <unistd.h>

namespace core {

namespace {

constexpr const char* kThpMode = "/sys/kernel/mm/transparent_hugepage/enabled";

std::string readThpMode() {
    std::ifstream in(kThpMode);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

} // namespace

bool wantsHugePageRestart(const char* tunables, std::string_view thpMode, const char* optOut) {
    if (optOut != nullptr && std::string_view(optOut) == "0")
        return false;
    // "always" gives them without asking, "never" not at all.
    if (thpMode.find("[madvise]") == std::string_view::npos)
        return false;
    return tunables == nullptr ||
           std::string_view(tunables).find("glibc.malloc.hugetlb=") == std::string_view::npos;
}

bool usesHugePages() {
    const char* tunables = std::getenv("GLIBC_TUNABLES");
    return tunables != nullptr &&
           std::string_view(tunables).find(kHugePagesTunable) != std::string_view::npos;
}

void restartWithHugePages(char** argv) {
#if defined(__GLIBC__) && defined(__linux__)
    const char* tunables = std::getenv("GLIBC_TUNABLES");
    if (argv == nullptr || argv[0] == nullptr ||
        !wantsHugePageRestart(tunables, readThpMode(), std::getenv("LAYERPAINT_HUGE_PAGES")))
        return;
    std::string value(kHugePagesTunable);
    if (tunables != nullptr && *tunables != '\0')
        value = std::string(tunables) + ":" + value;
    if (setenv("GLIBC_TUNABLES", value.c_str(), 1) != 0)
        return;
    execv("/proc/self/exe", argv);
    // Not started again: go on as it is, without the setting (which would stay unused).
    if (tunables != nullptr)
        setenv("GLIBC_TUNABLES", tunables, 1);
    else
        unsetenv("GLIBC_TUNABLES");
#else
    (void)argv;
#endif
}

} // namespace core
