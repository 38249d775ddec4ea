// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target for the project reader: a binary glTF goes through core::loadProjectInProcess
// (extras first, then the strict glTF load, as the importer process runs it) and its state is
// applied to a document as opening it does (core::applyProjectState: the paint target, then
// restorePaintLayers); anything else is read as the JSON of extras.layerpaint by
// core::projectStateFromJson. A state that was read must survive being written and read again.
// Known inputs are skipped (see fuzz::isKnownCrasher).
//
// The mutator edits a project's state as JSON half the time (LLVMFuzzerCustomMutator): a value
// replaced by a boundary number, another type or a dictionary key, an array element duplicated
// or dropped, a key dropped or added, an image number pointed elsewhere; the glb is packed again
// around the edited JSON with its binary chunk unchanged. So the paint layers' reader and
// restorePaintLayers see structurally valid projects, which byte mutations seldom make.
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/document/document.h"
#include "core/document/project_state.h"
#include "core/io/gltf/glb_container.h"
#include "core/io/importer/mesh_io_in_process.h"
#include "core/io/json_nesting.h"
#include "core/io/project/project_file.h"
#include "tests/fuzz/fuzz_input.h"

extern "C" std::size_t LLVMFuzzerMutate(std::uint8_t* data, std::size_t size, std::size_t maxSize);

namespace {

using Json = nlohmann::json;
using Random = std::minstd_rand;

/** Keys of a project's state, for edits that add one. */
constexpr std::array kKeys = {"paint_layers",
                              "layers",
                              "channels",
                              "base_color",
                              "roughness",
                              "metallic",
                              "mask",
                              "pages",
                              "tiles",
                              "texel_bytes",
                              "fill",
                              "image",
                              "images",
                              "base",
                              "base_metallic_roughness",
                              "selection",
                              "layer",
                              "id",
                              "name",
                              "kind",
                              "opacity",
                              "blend",
                              "visible",
                              "lock",
                              "values",
                              "brush",
                              "tip",
                              "tip_image",
                              "brush_tip_views",
                              "paint_target",
                              "resolution",
                              "version",
                              "camera",
                              "width",
                              "height",
                              "x",
                              "y",
                              "page"};

/** A value where readers' checks are likely to be off by one or to wrap. */
Json boundaryValue(Random& random) {
    static const std::array<Json, 16> values = {Json(0),
                                                Json(1),
                                                Json(-1),
                                                Json(255),
                                                Json(256),
                                                Json(65535),
                                                Json(65536),
                                                Json(0x7fffffff),
                                                Json(0x80000000u),
                                                Json((std::uint64_t(1) << 32) + 7),
                                                Json(std::uint64_t(1) << 63),
                                                Json(0.5),
                                                Json(1e308),
                                                Json(-1e308),
                                                Json(16384),
                                                Json(8192)};
    return values[random() % values.size()];
}

/** Another kind of value altogether. */
Json otherValue(Random& random) {
    switch (random() % 5) {
    case 0:
        return nullptr;
    case 1:
        return Json("x");
    case 2:
        return Json::array();
    case 3:
        return Json::object();
    default:
        return random() % 2 == 0;
    }
}

void collect(Json& j, std::vector<Json*>& out) {
    out.push_back(&j);
    if (j.is_structured())
        for (Json& child : j)
            collect(child, out);
}

/** One structural edit of a node of the state. */
void edit(Json& node, Random& random) {
    switch (random() % 6) {
    case 0:
        node = boundaryValue(random);
        return;
    case 1:
        node = otherValue(random);
        return;
    case 2:
        if (node.is_array() && !node.empty()) {
            const Json element = node[random() % node.size()];
            for (unsigned n = 1 + random() % 64; n > 0; --n)
                node.push_back(element);
            return;
        }
        break;
    case 3:
        if (node.is_array() && !node.empty()) {
            node.erase(random() % node.size());
            return;
        }
        if (node.is_object() && !node.empty()) {
            auto it = node.begin();
            std::advance(it, random() % node.size());
            node.erase(it);
            return;
        }
        break;
    case 4:
        if (node.is_object()) {
            node[kKeys[random() % kKeys.size()]] = boundaryValue(random);
            return;
        }
        break;
    default:
        break;
    }
    if (node.is_number())
        node = boundaryValue(random);
}

/** The glb of data with its state edited, or nothing when data is no project. */
std::optional<std::vector<std::uint8_t>> mutateProject(const std::uint8_t* data, std::size_t size,
                                                       Random& random) {
    const core::Result<core::glb::Layout> layout = core::glb::readContainer({data, size});
    if (!layout)
        return std::nullopt;
    const std::string text(reinterpret_cast<const char*>(data) + layout->jsonOffset,
                           layout->jsonLength);
    if (core::jsonNestingTooDeep(text))
        return std::nullopt;
    Json root = Json::parse(text, nullptr, false);
    if (root.is_discarded() || !root.is_object() || !root.contains("asset") ||
        !root["asset"].is_object() || !root["asset"].contains("extras"))
        return std::nullopt;
    for (unsigned edits = 1 + random() % 3; edits > 0; --edits) {
        std::vector<Json*> nodes; // again after each edit, which may free some
        collect(root["asset"]["extras"], nodes);
        edit(*nodes[random() % nodes.size()], random);
    }
    return core::glb::replaceJson({data, size}, *layout, root.dump());
}

/** Opens the project in a document as the window does: mesh, then the saved state. */
void applyToDocument(core::Project& project) {
    core::Document doc;
    doc.setMesh(std::move(project.mesh), "fuzz");
    (void)core::applyProjectState(doc, *project.state);
}

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
        if (project && project->state) {
            checkRoundTrip(*project->state);
            applyToDocument(*project);
        }
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

extern "C" std::size_t LLVMFuzzerCustomMutator(std::uint8_t* data, std::size_t size,
                                               std::size_t maxSize, unsigned int seed) {
    Random random(seed);
    if (size >= 4 && std::memcmp(data, "glTF", 4) == 0 && random() % 2 == 0)
        if (const std::optional<std::vector<std::uint8_t>> edited =
                mutateProject(data, size, random);
            edited && edited->size() <= maxSize) {
            std::memcpy(data, edited->data(), edited->size());
            return edited->size();
        }
    return LLVMFuzzerMutate(data, size, maxSize);
}
