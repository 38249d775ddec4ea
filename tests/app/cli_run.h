// SPDX-License-Identifier: GPL-3.0-or-later
// Runs the built layerpaint-cli as a user would, for the tests of the headless tool, and reads
// what it painted.
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <sys/wait.h>

#include "core/io/mesh_io.h"
#include "core/model/mesh.h"

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

/**
 * Runs `paint MODEL` with script in the folder layerpaint_TAG of the temporary directory and
 * loads the saved model; a test failure and nullopt if either fails.
 */
inline std::optional<core::Mesh> paintScript(const std::string& model, const nlohmann::json& script,
                                             const std::string& tag) {
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() / ("layerpaint_" + tag);
    std::filesystem::create_directories(dir);
    std::ofstream(dir / "script.json") << script.dump();
    const CliRun run = runCli({"paint", model, "--script", (dir / "script.json").string(), "--out",
                               (dir / "result.glb").string()},
                              dir);
    EXPECT_EQ(run.exitCode, 0) << run.err;
    auto mesh = core::loadMesh((dir / "result.glb").string());
    EXPECT_TRUE(mesh) << mesh.error();
    if (!mesh)
        return std::nullopt;
    return std::move(mesh).value();
}

/** The RGBA8 texel of mesh's first texture under the centre of triangle t's UVs. */
inline const std::uint8_t* centreTexel(const core::Mesh& mesh, std::size_t t) {
    const core::Image& texture = mesh.textures.at(0);
    glm::vec2 uv(0.0f);
    for (int k = 0; k < 3; ++k)
        uv += mesh.uvs[mesh.indices[3 * t + std::size_t(k)]] / 3.0f;
    const int x = std::clamp(int(uv.x * float(texture.width)), 0, texture.width - 1);
    const int y = std::clamp(int(uv.y * float(texture.height)), 0, texture.height - 1);
    return &texture.rgba[(std::size_t(y) * std::size_t(texture.width) + std::size_t(x)) * 4];
}

} // namespace cli_test
