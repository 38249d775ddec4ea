// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/base/progress.h"
#include "core/base/result.h"
#include "core/io/atomic_write.h"
#include "core/model/mesh.h"

namespace core {

/**
 * Encodes mesh as a binary glTF 2.0 file. A mesh flattened from a glTF scene (Mesh::source) is
 * written back into that scene (gltf_write_back.h): only what was painted changes. Otherwise, or
 * when the scene cannot be kept (a warning says why), the mesh is written flattened
 * (docs/architecture.md §3 step 7): one scene, one node, one
 * mesh with one primitive per run of consecutive triangles sharing a material, in triangle order,
 * so loadMesh() gives the triangles back in the same order. Each primitive holds the vertices its
 * triangles use, in their original order: a mesh whose material runs use disjoint, ascending
 * vertex ranges (every mesh loadMesh() returns) comes back with identical vertices and indices;
 * otherwise vertices shared between runs are duplicated and unused ones dropped.
 * Attributes: POSITION (with min/max), NORMAL, TEXCOORD_0 and COLOR_0 (float RGBA, linear) when
 * present; uint32 indices. Materials are glTF metallic-roughness materials with every field of
 * Material (maps placed otherwise than the UVs with KHR_texture_transform, an emissive strength
 * other than 1 with KHR_materials_emissive_strength). Only the textures a material uses are
 * stored, in the binary chunk: the base colour textures first in the order of first use, then the
 * other maps'; a texture with a kept file (Mesh::textureSources) as those bytes, the others as
 * PNG (empty images are left out). extras (a JSON object, or null for none) goes
 * under asset.extras.
 *
 * Returns the file's bytes, or an Error (an invalid mesh, extras that are not an object, an image
 * that cannot be encoded, more than 4 GiB of data, cancelled through progress).
 */
Result<std::vector<std::uint8_t>> encodeGlb(const Mesh& mesh, const nlohmann::json& extras = {},
                                            const ProgressFn& progress = {});

/** What a glTF file holds beyond the mesh: material channels and binary attachments. */
struct GlbAdditions {
    /** asset.extras (a JSON object, or null for none). */
    nlohmann::json extras;
    /**
     * glTF metallic-roughness images (linear; G roughness, B metallic), and per material an
     * index into them or -1. A material with one and without a metallic-roughness map of its own
     * gets it as metallicRoughnessTexture with metallic and roughness factors 1.
     */
    std::vector<Image> metallicRoughness;
    std::vector<int> materialMetallicRoughness;
    /**
     * Encoded files (PNG images) stored as buffer views after the textures; the array of their
     * view indices is written into extras at attachmentsAt.
     */
    std::vector<std::vector<std::uint8_t>> attachments;
    nlohmann::json::json_pointer attachmentsAt;
    /** Where what the file cannot keep is named (nullptr: nowhere). */
    std::vector<std::string>* warnings = nullptr;
};

/** encodeGlb() with additions. */
Result<std::vector<std::uint8_t>> encodeGlbWith(const Mesh& mesh, const GlbAdditions& additions,
                                                const ProgressFn& progress = {});

/**
 * Saves mesh as a binary glTF file at path (see encodeGlb), atomically (writeFileAtomically),
 * keeping the previous file as path + ".bak" unless keepBackup is false. On failure the old file
 * is intact and the Error names path and the problem.
 */
Status saveGlb(const std::string& path, const Mesh& mesh, const nlohmann::json& extras = {},
               const ProgressFn& progress = {}, bool keepBackup = true);
/** saveGlb() with additions. */
Status saveGlbWith(const std::string& path, const Mesh& mesh, const GlbAdditions& additions,
                   const ProgressFn& progress = {}, bool keepBackup = true);

/**
 * The asset.extras object of a glTF file (binary or JSON); reads only the JSON. An empty object
 * if the file has none; an Error naming path if it cannot be read, is not glTF or its extras are
 * not an object.
 */
Result<nlohmann::json> readGlbExtras(const std::string& path);

/**
 * The bytes of buffer views of a binary glTF file (of its BIN chunk), in the order asked; reads
 * only the JSON and those bytes. An Error naming path if the file is not a binary glTF, a view
 * is missing or lies outside the chunk, or the views add up to more than maxBytes.
 */
Result<std::vector<std::vector<std::uint8_t>>>
readGlbViews(const std::string& path, const std::vector<int>& views, std::uint64_t maxBytes);

} // namespace core
