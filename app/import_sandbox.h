// SPDX-License-Identifier: GPL-3.0-or-later
// The restrictions layerpaint-import puts on itself before it opens the file it parses.
#pragma once

#include <string>
#include <vector>

namespace importer {

struct SandboxOptions {
    /** Files and folders (everything beneath) the process may read; nothing else of the user's. */
    std::vector<std::string> readable;
    /** Processor seconds before the kernel stops the process. */
    double maxSeconds = 30.0;
};

/** What could be applied on this system. */
struct SandboxReport {
    int landlockAbi = 0;   // 0: no Landlock (old kernel, or disabled): files are not restricted
    bool landlock = false; // the file rules are in force
    bool seccomp = false;  // sockets, exec and tracing are refused
    bool noNewPrivs = false;
    bool addressSpaceLimit = false; // off in sanitizer builds (their shadow memory needs it)
};

/**
 * Limits (address space, processor time, no file writes, no core dumps, few descriptors), no
 * new privileges, Landlock file rules where the kernel has them (read only: options.readable
 * and the system's library folders) and a seccomp filter. Whatever the
 * system lacks is skipped; the rest still applies.
 */
SandboxReport applySandbox(const SandboxOptions& options);

} // namespace importer
