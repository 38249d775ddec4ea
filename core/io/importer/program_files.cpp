// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/io/importer/program_files.h"

#include <cstdlib>
#include <filesystem>
#include <system_error>

#include <unistd.h>

// Where the importer and the image codecs are installed, relative to the folder of the programs
// (set by CMake from the install directories).
#ifndef LAYERPAINT_LIBEXEC_FROM_BIN
#define LAYERPAINT_LIBEXEC_FROM_BIN "../libexec"
#endif

namespace core {

namespace fs = std::filesystem;

Result<std::string> findProgramFile(const char* name, const char* variable, const char* what,
                                    bool executable) {
    auto usable = [executable](const fs::path& path) {
        std::error_code ec;
        return fs::is_regular_file(path, ec) &&
               ::access(path.c_str(), executable ? X_OK : R_OK) == 0;
    };
    const std::string named = std::string(what) + " " + name;
    if (const char* configured = std::getenv(variable);
        configured != nullptr && *configured != '\0') {
        if (usable(configured))
            return std::string(configured);
        return Error{std::string(what) + " " + configured + " (set in " + variable +
                     ") does not exist or cannot be " + (executable ? "run" : "read")};
    }
    std::error_code ec;
    const fs::path self = fs::read_symlink("/proc/self/exe", ec);
    if (ec)
        return Error{named + " cannot be found (the running program's folder is unknown; set " +
                     variable + " to its path)"};
    const fs::path beside = self.parent_path() / name;
    const fs::path installed =
        (self.parent_path() / LAYERPAINT_LIBEXEC_FROM_BIN / "layerpaint" / name).lexically_normal();
    for (const fs::path& candidate : {beside, installed})
        if (usable(candidate))
            return candidate.string();
    return Error{named + " is missing (looked for " + beside.string() + " and " +
                 installed.string() + "; set " + variable + " to its path)"};
}

} // namespace core
