// SPDX-License-Identifier: GPL-3.0-or-later
// Writing a painted mesh back into the glTF scene it was flattened from (Mesh::source):
// copy-on-write, so that nodes, names, transforms, instancing, animations, skins, vertex
// attributes, extras and extensions stay as the file had them and only what was painted changes.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/base/progress.h"
#include "core/base/result.h"
#include "core/io/gltf/gltf_export.h"
#include "core/model/mesh.h"

namespace core::detail::gltf {

/** A binary glTF's JSON and BIN chunk. */
struct GlbContent {
    nlohmann::json root;
    std::vector<std::uint8_t> bin;
};

/**
 * Why mesh (a Document::paintedMesh()) cannot be written back into mesh.source, in words that
 * follow "the scene is not kept: ", or "" if it can: the file's scene was not kept, the
 * triangles, vertices or texture coordinates differ from what was flattened, or vertex colours
 * were painted on Draco-compressed primitives.
 */
std::string writeBackBlocker(const Mesh& mesh);

/**
 * mesh.source's scene with what was painted: a painted base colour page replaces the image it
 * was made from when nothing else uses that image (else it is added as a new image and texture),
 * its materials' base colour factors become white and their primitives' COLOR_0 is dropped (both
 * are baked into the page); a painted metallic-roughness page likewise, on the placement of the
 * base colour, with factors 1; painted vertex colours become each primitive's COLOR_0 (the
 * factors baked in, so those become white too). Images nothing painted keep their bytes.
 * additions.extras goes under asset.extras beside the file's own (a previous project's state and
 * its attachments are dropped); additions.attachments become buffer views. What cannot be kept is
 * named in warnings. An Error if the scene does not match mesh (then the caller writes the mesh
 * flattened).
 */
Result<GlbContent> writeBack(const Mesh& mesh, const GlbAdditions& additions,
                             const ProgressFn& progress, std::vector<std::string>& warnings);

} // namespace core::detail::gltf
