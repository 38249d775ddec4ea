// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/base/progress.h"
#include "core/base/result.h"
#include "core/model/mesh.h"

namespace core {

/** What Export offers: the painted model, or the paint texture alone. */
enum class ExportFormat {
    Glb,   // binary glTF 2.0, without LayerPaint's state
    Obj,   // Wavefront OBJ + MTL + PNG textures
    Ply,   // binary PLY with RGBA vertex colours
    Png8,  // paint texture, 8 bits a channel, sRGB
    Png16, // paint texture, 16 bits a channel, sRGB
    Tiff,  // paint texture, 8 bits a channel, sRGB
    Exr,   // paint texture, half float, linear
};

/** Whether format writes the paint texture alone (else the whole model). */
bool isTextureFormat(ExportFormat format);
/** The file extension of format, with the dot (".glb", ".png", ...). */
const char* exportExtension(ExportFormat format);
/** "glb", "obj", "ply", "png", "png16", "tiff", "exr" ↔ the format (the CLI's names). */
const char* exportFormatName(ExportFormat format);
std::optional<ExportFormat> parseExportFormat(const std::string& name);

/**
 * Writes mesh (e.g. Document::paintedMesh()) as a model file (Glb, Obj or Ply):
 * - Glb: encodeGlb() without extras (what the file cannot keep of the model's scene is named in
 *   warnings, if given);
 * - Obj: path, the materials in STEM.mtl beside it and each texture a material uses as
 *   STEM_N.png (N from 1; a base colour factor other than white is baked into its copy, since
 *   OBJ viewers show map_Kd untinted); the other maps as the MTL's PBR entries, each texture
 *   once as STEM_mapT (T its texture from 1; a kept PNG or JPEG file as it is, else PNG):
 *   Pr and Pm (roughness and metallic factors), map_Pr and map_Pm (STEM_mapT_roughness.png and
 *   STEM_mapT_metallic.png, grey, from the metallic-roughness map), norm (normal map), map_Ka
 *   (occlusion, read back by Assimp as the ambient map), Ke (emissive factor × strength) and
 *   map_Ke; a map's placement other than the UVs is not kept. UVs are flipped to OBJ's
 *   convention (v up); vertex colours, if any, follow the positions as sRGB ("v x y z r g b").
 *   Faces keep the triangle order, each named object (Mesh::objects) an "o" line;
 * - Ply: binary little-endian; positions, normals, UVs (s, t; t up) if any and RGBA8 sRGB vertex
 *   colours: base colour
 *   factor × vertex colour × the texture at the vertex's UV (bilinear), of the first triangle
 *   that uses the vertex.
 * Every file is written atomically (writeFileAtomically, no backup). Returns the paths written;
 * on failure an Error naming the file and the problem, and files already written stay.
 * progress goes from 0 to 1; cancelling returns an Error "…: cancelled".
 */
Result<std::vector<std::string>> exportMesh(const std::string& path, ExportFormat format,
                                            const Mesh& mesh, const ProgressFn& progress = {},
                                            std::vector<std::string>* warnings = nullptr);

/** A painted material's channels beside a mesh's base colour textures. */
struct MaterialChannels {
    /**
     * Per mesh texture, the glTF metallic-roughness image (linear; G roughness, B metallic) of
     * the materials that use it, or an empty image for none.
     */
    std::vector<Image> metallicRoughness;
};

/**
 * exportMesh() with the material's roughness and metallic, for materials without a
 * metallic-roughness map of their own: Glb gets each as the materials'
 * metallicRoughnessTexture (metallic and roughness factors 1); Obj writes STEM_N_roughness.png
 * and STEM_N_metallic.png (grey, linear) beside STEM_N.png and names them in the MTL with
 * map_Pr and map_Pm; Ply has no such channels.
 */
Result<std::vector<std::string>> exportMaterial(const std::string& path, ExportFormat format,
                                                const Mesh& mesh, const MaterialChannels& channels,
                                                const ProgressFn& progress = {},
                                                std::vector<std::string>* warnings = nullptr);

/** The roughness (G) or metallic (B) of a metallic-roughness image as a grey opaque image. */
Image channelImage(const Image& metallicRoughness, int component);

/**
 * exportTextures() of the base colour pages, then, for pages with a metallic-roughness image,
 * STEM_roughness.EXT and STEM_metallic.EXT (page i from 2: STEM_i_roughness.EXT, ...) as grey
 * images of the linear values (Exr: the values, within 8-bit rounding). Returns every path
 * written, or the first Error.
 */
Result<std::vector<std::string>> exportChannelTextures(const std::string& path, ExportFormat format,
                                                       const std::vector<Image>& pages,
                                                       const std::vector<Image>& metallicRoughness,
                                                       const ProgressFn& progress = {});

/**
 * Writes image (a paint texture page: sRGB RGBA8, rows top first) as Png8, Png16 (each value ×
 * 257), Tiff (8 bits) or Exr (half float; colour decoded to linear and associated with alpha,
 * as EXR readers expect). Fully opaque images are written as RGB. Atomic, without a backup. An
 * Error naming path on failure.
 */
Status exportTexture(const std::string& path, ExportFormat format, const Image& image,
                     const ProgressFn& progress = {});

/**
 * Writes every page: the first to path, page i (from 2) to STEM_i.EXT beside it. Returns the
 * paths written, or the first Error. An Error if there is no page.
 */
Result<std::vector<std::string>> exportTextures(const std::string& path, ExportFormat format,
                                                const std::vector<Image>& pages,
                                                const ProgressFn& progress = {});

/**
 * The colour of image at uv (glTF convention: (0,0) the top-left corner, repeating), bilinear in
 * linear space; linear RGBA. Exposed for tests.
 */
glm::vec4 sampleTexture(const Image& image, glm::vec2 uv);

} // namespace core
