// SPDX-License-Identifier: GPL-3.0-or-later
// Helper of save_crash_test.cpp: `loop PATH` saves version B, A, B, ... to PATH until it is
// killed, printing "ready" before the first save and "saved N" after each; `save PATH` saves
// version A once and prints the error, if any (exit code 1).
#include <cstdio>
#include <cstring>
#include <string>

#include "tests/core/io/save_crash_versions.h"

int main(int argc, char** argv) {
    if (argc != 3) {
        std::fprintf(stderr, "usage: save_crash_helper loop|save PATH\n");
        return 2;
    }
    const std::string mode = argv[1], path = argv[2];
    const save_crash::Version versions[2] = {save_crash::makeVersion(0),
                                             save_crash::makeVersion(1)};
    if (mode == "save") {
        const core::Status s = core::saveProject(path, versions[0].mesh, versions[0].state);
        if (!s) {
            std::printf("%s\n", s.error().c_str());
            return 1;
        }
        return 0;
    }
    if (mode != "loop")
        return 2;
    std::printf("ready\n");
    std::fflush(stdout);
    for (unsigned n = 1;; ++n) {
        const save_crash::Version& v = versions[n % 2];
        if (const core::Status s = core::saveProject(path, v.mesh, v.state); !s) {
            std::printf("failed %s\n", s.error().c_str());
            return 1;
        }
        std::printf("saved %u\n", n);
        std::fflush(stdout);
    }
}
