// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target for the project reader: a binary glTF goes through core::loadProjectInProcess
// (extras first, then the strict glTF load, as the importer process runs it); anything else is read
// as the JSON of extras.layerpaint by core::projectStateFromJson. A state that was read must
// survive being written and read again. Known inputs are skipped (see fuzz::isKnownCrasher).
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/io/importer/mesh_io_in_process.h"
#include "core/io/json_nesting.h"
#include "core/io/project/project_file.h"
#include "tests/fuzz/fuzz_input.h"

namespace {

void checkRoundTrip(const core::ProjectState& state) {
    const nlohmann::json written = core::projectStateToJson(state);
    core::Result<core::ProjectState> again =
        core::projectStateFromJson(nlohmann::json::parse(written.dump()));
    if (!again || core::projectStateToJson(*again) != written)
        __builtin_trap();
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size >= 4 && std::memcmp(data, "glTF", 4) == 0) {
        if (fuzz::isKnownCrasher(".glb", data, size))
            return 0;
        const std::string path = fuzz::writeInput(data, size, ".glb");
        core::Result<core::Project> project = core::loadProjectInProcess(path, {}, fuzz::limits());
        if (project && !project->mesh.validate().ok())
            __builtin_trap();
        if (project && project->state)
            checkRoundTrip(*project->state);
        return 0;
    }
    if (fuzz::isKnownCrasher(".json", data, size))
        return 0;
    const std::string text(reinterpret_cast<const char*>(data), size);
    if (core::jsonNestingTooDeep(text))
        return 0; // the readers refuse these before parsing
    const nlohmann::json json = nlohmann::json::parse(text, nullptr, false);
    if (json.is_discarded())
        return 0;
    std::vector<std::string> warnings;
    core::Result<core::ProjectState> state = core::projectStateFromJson(json, &warnings);
    if (state)
        checkRoundTrip(*state);
    return 0;
}
