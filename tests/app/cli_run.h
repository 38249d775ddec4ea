// SPDX-License-Identifier: GPL-3.0-or-later
// Runs the built layerpaint-cli as a user would, for the tests of the headless tool.
#pragma once

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <sys/wait.h>

namespace cli_test {

/** A finished run: exit code (-1 if it did not exit normally), what it wrote to stdout and stderr.
 */
struct CliRun {
    int exitCode = -1;
    std::string out, err;
};

/** The whole file at path, or empty if it cannot be read. */
inline std::string readFile(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

/**
 * Runs layerpaint-cli with arguments (each is quoted, so no shell expansion happens in them);
 * its output goes through the files out.txt and err.txt in dir, which must exist.
 */
inline CliRun runCli(const std::vector<std::string>& args, const std::filesystem::path& dir) {
    std::string command = std::string("'") + LAYERPAINT_CLI + "'";
    for (const std::string& a : args)
        command += " '" + a + "'";
    command += " >'" + (dir / "out.txt").string() + "' 2>'" + (dir / "err.txt").string() + "'";
    CliRun run;
    const int status = std::system(command.c_str());
    run.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    run.out = readFile(dir / "out.txt");
    run.err = readFile(dir / "err.txt");
    return run;
}

} // namespace cli_test
