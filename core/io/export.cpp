// SPDX-License-Identifier: GPL-3.0-or-later
// Exports of the painted model (glTF binary, OBJ + MTL + PNG, PLY with vertex colours) and of the
// paint texture alone (PNG 8/16-bit, TIFF, EXR). Everything is encoded in memory and written
// with writeFileAtomically, so a failed export never leaves half a file under the chosen name.
#include "core/io/export.h"
#include "core/base/color.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstring>
#include <exception>
#include <filesystem>
#include <map>
#include <new>
#include <string>
#include <utility>
#include <vector>

#include "core/io/gltf/gltf_export.h"
#include "core/io/image/image_encode.h"
#include "core/io/ply_write.h"
#include "core/paint/targets/paint_target.h"

namespace core {

namespace {

namespace fs = std::filesystem;
using Bytes = std::vector<std::uint8_t>;

/** Thrown inside an export when progress asks to stop; caught at the top. */
struct Cancelled {};

void step(const ProgressFn& progress, double fraction) {
    if (!reportProgress(progress, std::clamp(fraction, 0.0, 1.0)))
        throw Cancelled{};
}

/** A progress function for [from, to] of the whole. */
ProgressFn part(const ProgressFn& progress, double from, double to) {
    if (!progress)
        return {};
    return [progress, from, to](double f) { return progress(from + (to - from) * f); };
}

void appendFloat(std::string& out, float v) {
    char buffer[32];
    // Shortest text that reads back as the same float.
    const auto [end, ec] =
        std::to_chars(buffer, buffer + sizeof buffer, std::isfinite(v) ? v : 0.0f);
    out.append(buffer, ec == std::errc() ? end : buffer);
}

void appendInt(std::string& out, std::uint64_t v) {
    char buffer[24];
    const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, v);
    out.append(buffer, ec == std::errc() ? end : buffer);
}

Status writeBytes(const std::string& path, const std::string& text) {
    return writeFileAtomically(path, text.data(), text.size(), false);
}

/** "name with spaces/and:odd chars" → "name_with_spaces_and_odd_chars" (for OBJ/MTL tokens). */
std::string token(const std::string& name) {
    std::string out;
    for (unsigned char c : name)
        out.push_back(std::isalnum(c) || c == '-' || c == '_' || c == '.' ? char(c) : '_');
    return out.empty() ? std::string("unnamed") : out;
}

/** path with its extension replaced; suffix appended to the stem. */
fs::path sibling(const fs::path& path, const std::string& suffix, const std::string& extension) {
    fs::path out = path.parent_path() / (path.stem().string() + suffix + extension);
    return out;
}

// ---------------------------------------------------------------------------------------------
// Images

Status writeImageFile(const std::string& path, const Image& image, ExportFormat format,
                      const ProgressFn& progress) {
    Result<Bytes> bytes = encodeImage(image, format, part(progress, 0.0, 0.9));
    if (bytes.cancelled())
        throw Cancelled{};
    if (!bytes)
        return Error{path + ": cannot be written (" + bytes.error() + ")", bytes.errorKind()};
    Status written = writeFileAtomically(path, bytes->data(), bytes->size(), false);
    if (written)
        step(progress, 1.0);
    return written;
}

// ---------------------------------------------------------------------------------------------
// OBJ

/** texture × rgb factor, in linear space, back to sRGB bytes (alpha untouched). */
Image bakeFactor(const Image& texture, const glm::vec4& factor) {
    Image out = texture;
    for (std::size_t i = 0; i + 3 < out.rgba.size(); i += 4)
        for (int k = 0; k < 3; ++k)
            out.rgba[i + std::size_t(k)] =
                linearToSrgb(srgbToLinear(texture.rgba[i + std::size_t(k)]) * factor[k]);
    return out;
}

bool finiteFactor(float v) {
    return std::isfinite(v);
}

/** An OBJ export's materials: names unique as OBJ tokens, textures (baked with their factor) as
 *  the PNG images written beside the OBJ. */
struct ObjMaterials {
    std::string stem; // the OBJ's file stem as a token, the start of every file name
    const MaterialChannels* channels = nullptr;
    std::vector<std::string> names; // per material
    std::vector<int> materialImage; // per material: its image, or -1
    std::vector<Image> images;      // the PNGs to write
    std::vector<int> imageSource;   // the mesh texture of each image
    /** The mesh textures of the other maps, written as they are: the texture and its file. */
    std::map<int, std::string> mapFiles;
    /** Metallic-roughness maps, written as a roughness and a metallic image: texture → stem. */
    std::map<int, std::string> channelFiles;

    std::string imageName(int i) const { return stem + "_" + std::to_string(i + 1) + ".png"; }
    std::string channelName(int i, const char* channel) const {
        return stem + "_" + std::to_string(i + 1) + "_" + channel + ".png";
    }
    /** The roughness and metallic of image i's texture, where the material has them. */
    const Image* channelsOf(int i) const {
        const int t = imageSource[std::size_t(i)];
        return std::size_t(t) < channels->metallicRoughness.size() &&
                       !channels->metallicRoughness[std::size_t(t)].empty()
                   ? &channels->metallicRoughness[std::size_t(t)]
                   : nullptr;
    }
};

/** The materials' names and images; materials sharing a texture and factor share its image. */
void bakeObjMaterials(const Mesh& mesh, ObjMaterials& out) {
    out.names.resize(mesh.materials.size());
    out.materialImage.assign(mesh.materials.size(), -1);
    std::map<std::pair<int, std::array<float, 3>>, int> baked;
    for (std::size_t m = 0; m < mesh.materials.size(); ++m) {
        const Material& mat = mesh.materials[m];
        out.names[m] = "m" + std::to_string(m) + "_" + token(mat.name);
        const int t = mat.baseColorTexture;
        if (t < 0 || std::size_t(t) >= mesh.textures.size() ||
            mesh.textures[std::size_t(t)].empty())
            continue;
        std::array<float, 3> rgb;
        for (int k = 0; k < 3; ++k)
            rgb[std::size_t(k)] =
                finiteFactor(mat.baseColorFactor[k]) ? mat.baseColorFactor[k] : 1.0f;
        const auto key = std::make_pair(t, rgb);
        if (const auto it = baked.find(key); it != baked.end()) {
            out.materialImage[m] = it->second;
            continue;
        }
        const Image& source = mesh.textures[std::size_t(t)];
        out.images.push_back(rgb == std::array<float, 3>{1.0f, 1.0f, 1.0f}
                                 ? source
                                 : bakeFactor(source, glm::vec4(rgb[0], rgb[1], rgb[2], 1.0f)));
        out.imageSource.push_back(t);
        out.materialImage[m] = int(out.images.size() - 1);
        baked.emplace(key, out.materialImage[m]);
    }
    // The other maps, each texture once (its placement is not kept: OBJ has no rotation).
    for (const Material& mat : mesh.materials) {
        for (const MaterialMap* map : {&mat.normal, &mat.occlusion, &mat.emissive}) {
            const int t = map->texture;
            if (t < 0 || mesh.textures[std::size_t(t)].empty() || out.mapFiles.count(t))
                continue;
            const EncodedImage* kept = mesh.textureSource(t);
            const char* extension = kept && kept->mimeType == "image/jpeg" ? ".jpg" : ".png";
            out.mapFiles[t] = out.stem + "_map" + std::to_string(t + 1) + extension;
        }
        const int t = mat.metallicRoughness.texture;
        if (t >= 0 && !mesh.textures[std::size_t(t)].empty() && !out.channelFiles.count(t))
            out.channelFiles[t] = out.stem + "_map" + std::to_string(t + 1);
    }
}

/** The MTL lines of mat's maps other than the base colour, and its PBR factors. */
void appendMapLines(std::string& mtl, const Material& mat, const ObjMaterials& mats, int image) {
    const auto factorLine = [&](const char* key, float v) {
        mtl += key;
        mtl += ' ';
        appendFloat(mtl, finiteFactor(v) ? v : 1.0f);
        mtl += '\n';
    };
    factorLine("Pr", mat.roughnessFactor);
    factorLine("Pm", mat.metallicFactor);
    if (const auto it = mats.channelFiles.find(mat.metallicRoughness.texture);
        it != mats.channelFiles.end())
        mtl += "map_Pr " + it->second + "_roughness.png\nmap_Pm " + it->second + "_metallic.png\n";
    else if (image >= 0 && mats.channelsOf(image))
        mtl += "map_Pr " + mats.channelName(image, "roughness") + "\nmap_Pm " +
               mats.channelName(image, "metallic") + "\n";
    const glm::vec3 emissive =
        mat.emissiveFactor * (finiteFactor(mat.emissiveStrength) ? mat.emissiveStrength : 1.0f);
    if (emissive != glm::vec3(0.0f)) {
        mtl += "Ke ";
        for (int k = 0; k < 3; ++k) {
            appendFloat(mtl, emissive[k]);
            mtl += k < 2 ? " " : "\n";
        }
    }
    const auto mapLine = [&](const char* key, const MaterialMap& map) {
        if (const auto it = mats.mapFiles.find(map.texture); it != mats.mapFiles.end())
            mtl += std::string(key) + " " + it->second + "\n";
    };
    mapLine("norm", mat.normal);
    mapLine("map_Ka", mat.occlusion); // Assimp reads it back as the ambient (occlusion) map
    mapLine("map_Ke", mat.emissive);
}

std::string mtlText(const Mesh& mesh, const ObjMaterials& mats) {
    std::string mtl = "# LayerPaint export\n";
    for (std::size_t m = 0; m < mesh.materials.size(); ++m) {
        const Material& mat = mesh.materials[m];
        const int image = mats.materialImage[m];
        mtl += "\nnewmtl " + mats.names[m] + "\nKd ";
        for (int k = 0; k < 3; ++k) {
            const float f = finiteFactor(mat.baseColorFactor[k]) ? mat.baseColorFactor[k] : 1.0f;
            appendFloat(mtl, image >= 0 ? 1.0f : f);
            mtl += k < 2 ? " " : "\n";
        }
        mtl += "d ";
        appendFloat(mtl, finiteFactor(mat.baseColorFactor.a) ? mat.baseColorFactor.a : 1.0f);
        mtl += "\nillum 1\n";
        if (image >= 0)
            mtl += "map_Kd " + mats.imageName(image) + "\n";
        appendMapLines(mtl, mat, mats, image);
    }
    return mtl;
}

/** The v, vt and vn lines; progress to geometryShare / 2. */
void appendObjVertices(std::string& obj, const Mesh& mesh, double geometryShare,
                       const ProgressFn& progress) {
    const std::size_t n = mesh.vertexCount();
    for (std::size_t v = 0; v < n; ++v) {
        const glm::vec3& p = mesh.positions[v];
        obj += "v ";
        appendFloat(obj, p.x);
        obj += ' ';
        appendFloat(obj, p.y);
        obj += ' ';
        appendFloat(obj, p.z);
        if (mesh.hasColors()) {
            for (int k = 0; k < 3; ++k) {
                obj += ' ';
                appendFloat(obj, encodeSrgb(mesh.colors[v][k]));
            }
        }
        obj += '\n';
        if ((v & 0xFFFF) == 0)
            step(progress, geometryShare * 0.5 * double(v) / double(n));
    }
    if (mesh.hasUvs())
        for (const glm::vec2& uv : mesh.uvs) {
            obj += "vt ";
            appendFloat(obj, uv.x);
            obj += ' ';
            appendFloat(obj, 1.0f - uv.y); // OBJ's v runs up, glTF's down
            obj += '\n';
        }
    for (const glm::vec3& nv : mesh.normals) {
        obj += "vn ";
        appendFloat(obj, nv.x);
        obj += ' ';
        appendFloat(obj, nv.y);
        obj += ' ';
        appendFloat(obj, nv.z);
        obj += '\n';
    }
}

/**
 * The f lines, an o line where a named object (Mesh::objects) begins, a usemtl line where the
 * material changes or an object begins; progress to geometryShare.
 */
void appendObjFaces(std::string& obj, const Mesh& mesh, const std::vector<std::string>& names,
                    double geometryShare, const ProgressFn& progress) {
    const std::size_t triangles = mesh.triangleCount();
    std::uint32_t current = ~0u;
    std::size_t object = 0;
    for (std::size_t t = 0; t < triangles; ++t) {
        if (object < mesh.objects.size() && mesh.objects[object].firstTriangle == t) {
            const std::string& name = mesh.objects[object].name;
            obj += "o " + (name.empty() ? "object " + std::to_string(object + 1) : name) + "\n";
            current = ~0u;
            ++object;
        }
        if (mesh.triangleMaterial[t] != current) {
            current = mesh.triangleMaterial[t];
            obj += "usemtl " + names[current] + "\n";
        }
        obj += 'f';
        for (int c = 0; c < 3; ++c) {
            const std::uint64_t i = std::uint64_t(mesh.indices[3 * t + std::size_t(c)]) + 1;
            obj += ' ';
            appendInt(obj, i);
            obj += '/';
            if (mesh.hasUvs())
                appendInt(obj, i);
            obj += '/';
            appendInt(obj, i);
        }
        obj += '\n';
        if ((t & 0xFFFF) == 0)
            step(progress, geometryShare * (0.5 + 0.5 * double(t) / double(triangles)));
    }
}

std::string objText(const Mesh& mesh, const ObjMaterials& mats, const fs::path& mtlPath,
                    double geometryShare, const ProgressFn& progress) {
    std::string obj;
    obj.reserve(mesh.vertexCount() * 96 + mesh.triangleCount() * 40);
    obj += "# LayerPaint export: ";
    appendInt(obj, mesh.vertexCount());
    obj += " vertices, ";
    appendInt(obj, mesh.triangleCount());
    obj += " triangles\nmtllib " + mtlPath.filename().string() + "\n";
    appendObjVertices(obj, mesh, geometryShare, progress);
    appendObjFaces(obj, mesh, mats.names, geometryShare, progress);
    return obj;
}

/** The images beside path, each followed by its roughness and metallic where it has them;
 *  progress from geometryShare to 0.95. */
Status writeObjImages(const fs::path& path, const ObjMaterials& mats, double geometryShare,
                      const ProgressFn& progress, std::vector<std::string>& written) {
    const std::vector<Image>& images = mats.images;
    for (std::size_t i = 0; i < images.size(); ++i) {
        const std::string file = (path.parent_path() / mats.imageName(int(i))).string();
        const double from =
            geometryShare + (0.95 - geometryShare) * double(i) / double(images.size());
        const double to =
            geometryShare + (0.95 - geometryShare) * double(i + 1) / double(images.size());
        if (Status s =
                writeImageFile(file, images[i], ExportFormat::Png8, part(progress, from, to));
            !s)
            return s;
        written.push_back(file);
        if (const Image* mr = mats.channelsOf(int(i))) {
            for (const auto& [channel, component] : {std::pair{"roughness", 1}, {"metallic", 2}}) {
                const std::string name =
                    (path.parent_path() / mats.channelName(int(i), channel)).string();
                if (Status s =
                        writeImageFile(name, channelImage(*mr, component), ExportFormat::Png8, {});
                    !s)
                    return s;
                written.push_back(name);
            }
        }
    }
    return {};
}

/** The other maps beside path: kept files as they are, the rest as PNG; metallic-roughness
 *  maps as a roughness and a metallic image. */
Status writeObjMaps(const fs::path& path, const Mesh& mesh, const ObjMaterials& mats,
                    std::vector<std::string>& written) {
    for (const auto& [t, name] : mats.mapFiles) {
        const std::string file = (path.parent_path() / name).string();
        const EncodedImage* kept = mesh.textureSource(t);
        const Status s =
            kept ? writeFileAtomically(file, kept->bytes.data(), kept->bytes.size(), false)
                 : writeImageFile(file, mesh.textures[std::size_t(t)], ExportFormat::Png8, {});
        if (!s)
            return s;
        written.push_back(file);
    }
    for (const auto& [t, stem] : mats.channelFiles) {
        for (const auto& [channel, component] : {std::pair{"_roughness", 1}, {"_metallic", 2}}) {
            const std::string file = (path.parent_path() / (stem + channel + ".png")).string();
            if (Status s =
                    writeImageFile(file, channelImage(mesh.textures[std::size_t(t)], component),
                                   ExportFormat::Png8, {});
                !s)
                return s;
            written.push_back(file);
        }
    }
    return {};
}

Result<std::vector<std::string>> writeObj(const fs::path& path, const Mesh& mesh,
                                          const MaterialChannels& channels,
                                          const ProgressFn& progress) {
    ObjMaterials mats;
    mats.stem = token(path.stem().string());
    mats.channels = &channels;
    const fs::path mtlPath = path.parent_path() / (mats.stem + ".mtl");
    bakeObjMaterials(mesh, mats);
    const std::string mtl = mtlText(mesh, mats);
    const double geometryShare = mats.images.empty() ? 0.9 : 0.3;
    const std::string obj = objText(mesh, mats, mtlPath, geometryShare, progress);

    std::vector<std::string> written;
    if (Status s = writeObjImages(path, mats, geometryShare, progress, written); !s)
        return s.takeError();
    if (Status s = writeObjMaps(path, mesh, mats, written); !s)
        return s.takeError();
    if (Status s = writeBytes(mtlPath.string(), mtl); !s)
        return s.takeError();
    written.push_back(mtlPath.string());
    if (Status s = writeBytes(path.string(), obj); !s)
        return s.takeError();
    written.push_back(path.string());
    return written;
}

// ---------------------------------------------------------------------------------------------
// PLY

/** Per vertex: factor × vertex colour × texture, of the first triangle using it; linear RGBA. */
std::vector<glm::vec4> vertexColors(const Mesh& mesh, const ProgressFn& progress) {
    const std::size_t n = mesh.vertexCount();
    std::vector<std::uint32_t> material(n, ~0u);
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t)
        for (int c = 0; c < 3; ++c) {
            std::uint32_t& m = material[mesh.indices[3 * t + std::size_t(c)]];
            if (m == ~0u)
                m = mesh.triangleMaterial[t];
        }
    std::vector<glm::vec4> colors(n, glm::vec4(1.0f));
    for (std::size_t v = 0; v < n; ++v) {
        glm::vec4 c = mesh.hasColors() ? mesh.colors[v] : glm::vec4(1.0f);
        if (material[v] != ~0u) {
            const Material& mat = mesh.materials[material[v]];
            for (int k = 0; k < 4; ++k)
                c[k] *= std::isfinite(mat.baseColorFactor[k]) ? mat.baseColorFactor[k] : 1.0f;
            const int t = mat.baseColorTexture;
            if (t >= 0 && std::size_t(t) < mesh.textures.size() && mesh.hasUvs() &&
                !mesh.textures[std::size_t(t)].empty())
                c *= sampleTexture(mesh.textures[std::size_t(t)], mesh.uvs[v]);
        }
        colors[v] = c;
        if ((v & 0xFFFF) == 0)
            step(progress, 0.5 * double(v) / double(n));
    }
    return colors;
}

Result<std::vector<std::string>> writePly(const fs::path& path, const Mesh& mesh,
                                          const ProgressFn& progress) {
    const std::vector<glm::vec4> colors = vertexColors(mesh, part(progress, 0.0, 0.5));
    PlyContents contents;
    contents.colors = &colors;
    const std::string out = encodePly(mesh, contents);
    step(progress, 0.8);
    if (Status s = writeBytes(path.string(), out); !s)
        return s.takeError();
    return std::vector<std::string>{path.string()};
}

Result<std::vector<std::string>> exportModel(const std::string& path, ExportFormat format,
                                             const Mesh& mesh, const MaterialChannels& channels,
                                             const ProgressFn& progress,
                                             std::vector<std::string>* warnings) {
    if (isTextureFormat(format))
        return Error{path + ": " + exportFormatName(format) + " holds a texture, not a model"};
    if (const Status valid = mesh.validate(); !valid)
        return Error{path + ": the model cannot be exported (" + valid.error() + ")",
                     ErrorKind::BadInput};
    step(progress, 0.0);
    const fs::path target(path);
    Result<std::vector<std::string>> written = std::vector<std::string>{};
    switch (format) {
    case ExportFormat::Glb: {
        GlbAdditions additions;
        additions.warnings = warnings;
        additions.metallicRoughness = channels.metallicRoughness;
        for (const Material& m : mesh.materials)
            additions.materialMetallicRoughness.push_back(m.baseColorTexture);
        Result<Bytes> bytes = encodeGlbWith(mesh, additions, part(progress, 0.0, 0.9));
        if (!bytes) {
            if (bytes.cancelled())
                throw Cancelled{};
            return Error{path + ": " + bytes.error(), bytes.errorKind()};
        }
        if (Status s = writeFileAtomically(path, bytes->data(), bytes->size(), false); !s)
            return s.takeError();
        written = std::vector<std::string>{path};
        break;
    }
    case ExportFormat::Obj:
        written = writeObj(target, mesh, channels, progress);
        break;
    case ExportFormat::Ply:
        written = writePly(target, mesh, progress);
        break;
    default:
        break;
    }
    if (written)
        step(progress, 1.0);
    return written;
}

} // namespace

bool isTextureFormat(ExportFormat format) {
    return format != ExportFormat::Glb && format != ExportFormat::Obj &&
           format != ExportFormat::Ply;
}

const char* exportExtension(ExportFormat format) {
    switch (format) {
    case ExportFormat::Glb:
        return ".glb";
    case ExportFormat::Obj:
        return ".obj";
    case ExportFormat::Ply:
        return ".ply";
    case ExportFormat::Png8:
    case ExportFormat::Png16:
        return ".png";
    case ExportFormat::Tiff:
        return ".tif";
    case ExportFormat::Exr:
        return ".exr";
    }
    return "";
}

const char* exportFormatName(ExportFormat format) {
    switch (format) {
    case ExportFormat::Glb:
        return "glb";
    case ExportFormat::Obj:
        return "obj";
    case ExportFormat::Ply:
        return "ply";
    case ExportFormat::Png8:
        return "png";
    case ExportFormat::Png16:
        return "png16";
    case ExportFormat::Tiff:
        return "tiff";
    case ExportFormat::Exr:
        return "exr";
    }
    return "";
}

std::optional<ExportFormat> parseExportFormat(const std::string& name) {
    for (ExportFormat f :
         {ExportFormat::Glb, ExportFormat::Obj, ExportFormat::Ply, ExportFormat::Png8,
          ExportFormat::Png16, ExportFormat::Tiff, ExportFormat::Exr})
        if (name == exportFormatName(f))
            return f;
    return std::nullopt;
}

glm::vec4 sampleTexture(const Image& image, glm::vec2 uv) {
    if (image.empty())
        return glm::vec4(1.0f);
    const float u = std::isfinite(uv.x) ? uv.x : 0.0f, v = std::isfinite(uv.y) ? uv.y : 0.0f;
    const double x = double(u) * image.width - 0.5, y = double(v) * image.height - 0.5;
    const double fx = std::floor(x), fy = std::floor(y);
    const float ax = float(x - fx), ay = float(y - fy);
    auto wrap = [](double i, int size) {
        const double m = std::fmod(i, double(size));
        return int(m < 0 ? m + size : m);
    };
    const int x0 = wrap(fx, image.width), x1 = wrap(fx + 1, image.width);
    const int y0 = wrap(fy, image.height), y1 = wrap(fy + 1, image.height);
    auto texel = [&](int tx, int ty) {
        const std::uint8_t* p =
            &image.rgba[(std::size_t(ty) * std::size_t(image.width) + std::size_t(tx)) * 4];
        return glm::vec4(srgbToLinear(p[0]), srgbToLinear(p[1]), srgbToLinear(p[2]),
                         float(p[3]) / 255.0f);
    };
    const glm::vec4 top = texel(x0, y0) * (1.0f - ax) + texel(x1, y0) * ax;
    const glm::vec4 bottom = texel(x0, y1) * (1.0f - ax) + texel(x1, y1) * ax;
    return top * (1.0f - ay) + bottom * ay;
}

Result<std::vector<std::string>> exportMesh(const std::string& path, ExportFormat format,
                                            const Mesh& mesh, const ProgressFn& progress,
                                            std::vector<std::string>* warnings) {
    return exportMaterial(path, format, mesh, {}, progress, warnings);
}

Result<std::vector<std::string>> exportMaterial(const std::string& path, ExportFormat format,
                                                const Mesh& mesh, const MaterialChannels& channels,
                                                const ProgressFn& progress,
                                                std::vector<std::string>* warnings) {
    try {
        return exportModel(path, format, mesh, channels, progress, warnings);
    } catch (const Cancelled&) {
        return cancelledError(path + ": cancelled");
    } catch (const std::bad_alloc&) {
        return Error{path + ": not enough memory to export the model"};
    } catch (const std::exception& e) {
        return Error{path + ": cannot be exported (" + std::string(e.what()) + ")"};
    }
}

Status exportTexture(const std::string& path, ExportFormat format, const Image& image,
                     const ProgressFn& progress) {
    if (!isTextureFormat(format))
        return Error{path + ": " + exportFormatName(format) + " holds a model, not a texture"};
    try {
        step(progress, 0.0);
        return writeImageFile(path, image, format, progress);
    } catch (const Cancelled&) {
        return cancelledError(path + ": cancelled");
    } catch (const std::bad_alloc&) {
        return Error{path + ": not enough memory to export the texture"};
    } catch (const std::exception& e) {
        return Error{path + ": cannot be exported (" + std::string(e.what()) + ")"};
    }
}

Result<std::vector<std::string>> exportTextures(const std::string& path, ExportFormat format,
                                                const std::vector<Image>& pages,
                                                const ProgressFn& progress) {
    if (pages.empty())
        return Error{path + ": there is no paint texture to export (the model is painted with "
                            "vertex colours)"};
    std::vector<std::string> written;
    const fs::path first(path);
    for (std::size_t i = 0; i < pages.size(); ++i) {
        const std::string file =
            i == 0
                ? path
                : sibling(first, "_" + std::to_string(i + 1), first.extension().string()).string();
        const double n = double(pages.size());
        if (Status s = exportTexture(file, format, pages[i],
                                     part(progress, double(i) / n, double(i + 1) / n));
            !s)
            return s.takeError();
        written.push_back(file);
    }
    return written;
}

Image channelImage(const Image& metallicRoughness, int component) {
    Image out = metallicRoughness;
    for (std::size_t i = 0; i + 3 < out.rgba.size(); i += 4) {
        const std::uint8_t v = metallicRoughness.rgba[i + std::size_t(component)];
        out.rgba[i] = out.rgba[i + 1] = out.rgba[i + 2] = v;
        out.rgba[i + 3] = 255;
    }
    return out;
}

Result<std::vector<std::string>> exportChannelTextures(const std::string& path, ExportFormat format,
                                                       const std::vector<Image>& pages,
                                                       const std::vector<Image>& metallicRoughness,
                                                       const ProgressFn& progress) {
    Result<std::vector<std::string>> written =
        exportTextures(path, format, pages, part(progress, 0.0, 0.5));
    if (!written)
        return written;
    const fs::path first(path);
    const std::size_t n = std::min(pages.size(), metallicRoughness.size());
    for (std::size_t i = 0; i < n; ++i) {
        if (metallicRoughness[i].empty())
            continue;
        const std::string page = i == 0 ? std::string() : "_" + std::to_string(i + 1);
        for (const auto& [channel, component] : {std::pair{"_roughness", 1}, {"_metallic", 2}}) {
            Image image = channelImage(metallicRoughness[i], component);
            if (format == ExportFormat::Exr) {
                // The EXR writer decodes sRGB colour to linear; these values are linear already.
                for (std::size_t k = 0; k + 3 < image.rgba.size(); k += 4)
                    image.rgba[k] = image.rgba[k + 1] = image.rgba[k + 2] =
                        linearToSrgb(float(image.rgba[k]) / 255.0f);
            }
            const std::string file =
                sibling(first, page + channel, first.extension().string()).string();
            if (Status s = exportTexture(file, format, image,
                                         part(progress, 0.5 + 0.5 * double(i) / double(n),
                                              0.5 + 0.5 * double(i + 1) / double(n)));
                !s)
                return s.takeError();
            written->push_back(file);
        }
    }
    return written;
}

} // namespace core
