// SPDX-License-Identifier: GPL-3.0-or-later
// glTF 2.0 loader. tinygltf parses; everything it hands over is checked before use.
//
// Order of work and the files that do it:
// 1. The GLB container is checked first (glb_container.h): tinygltf 2.7 lets the BIN chunk run 8
//    bytes past the declared length.
// 2. The JSON is checked for nesting depth (deep nesting costs stack in the JSON library), then
//    against the glTF schema's types, image buffer views and required extensions
//    (gltf_schema.h).
// 3. tinygltf loads buffers and images through file callbacks that only open files inside the
//    model's folder (gltf_file_access.h); image bytes are only collected there and decoded later
//    with OpenImageIO, and only for base color textures.
// 4. Buffer views compressed with EXT_meshopt_compression are decoded (gltf_meshopt.h); their
//    fallback buffers, which may hold no data, are replaced in the JSON before step 3.
// 5. The scene is flattened into one Mesh (gltf_flatten.h), reading accessors through
//    gltf_accessors.h and decoding KHR_draco_mesh_compression primitives (gltf_draco.h).
//
// glTF 1.0 text files (asset.version "1.x") go to Assimp, which reads them; binary glTF 1.0
// (KHR_binary_glTF) is refused by the container check, as Assimp 5.2 cannot read it either.
#include <algorithm>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include "core/base/text.h"
#include "core/io/gltf/glb_container.h"
#include "core/io/gltf/gltf_accessors.h"
#include "core/io/gltf/gltf_draco.h"
#include "core/io/gltf/gltf_file_access.h"
#include "core/io/gltf/gltf_flatten.h"
#include "core/io/gltf/gltf_meshopt.h"
#include "core/io/gltf/gltf_schema.h"
#include "core/io/gltf/gltf_source_scene.h"
#include "core/io/importer/mesh_io_in_process.h"
#include "core/io/json_nesting.h"
#include "core/io/mesh_io.h"

namespace core::detail {

Result<Mesh> loadGltf(const std::filesystem::path& file, const ProgressFn& progress,
                      const LoadLimits& limits);
Result<Mesh> loadAssimp(const std::filesystem::path& file, const ProgressFn& progress,
                        const LoadLimits& limits);

namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;
using gltf::str;

/** The non-empty lines of a tinygltf message. */
std::vector<std::string> lines(const std::string& s) {
    std::vector<std::string> out;
    std::size_t start = 0;
    while (start < s.size()) {
        std::size_t end = s.find('\n', start);
        if (end == std::string::npos)
            end = s.size();
        std::string line = s.substr(start, end - start);
        while (!line.empty() && (line.back() == ' ' || line.back() == '\r'))
            line.pop_back();
        if (!line.empty())
            out.push_back(line);
        start = end + 1;
    }
    return out;
}

/** tinygltf's messages joined into one line. */
std::string oneLine(const std::string& s) {
    std::string out;
    for (const std::string& line : lines(s))
        out += (out.empty() ? "" : "; ") + line;
    return out;
}

bool isGlbName(const fs::path& file) {
    return lowerExtension(file) == ".glb";
}

/** Whether text starts (after white space and a UTF-8 byte order mark) with "{". */
bool startsLikeJsonObject(std::string_view text) {
    if (text.substr(0, 3) == "\xEF\xBB\xBF")
        text.remove_prefix(3);
    const std::size_t first = text.find_first_not_of(" \t\r\n");
    return first != std::string_view::npos && text[first] == '{';
}

/**
 * Where the glTF text breaks and how, in words: the line and column, and the parser's reason
 * without the bytes it last read (they may be anything).
 */
std::string describeParseError(const Json::parse_error& e, std::string_view text) {
    const std::size_t at = std::min<std::size_t>(e.byte > 0 ? e.byte - 1 : 0, text.size());
    std::size_t line = 1, column = 1;
    for (std::size_t i = 0; i < at; ++i) {
        if (text[i] == '\n') {
            ++line;
            column = 1;
        } else if ((static_cast<unsigned char>(text[i]) & 0xC0) != 0x80) {
            ++column; // characters, not the bytes of one
        }
    }
    std::string reason = e.what();
    if (const std::size_t p = reason.find(" - "); p != std::string::npos)
        reason = reason.substr(p + 3); // after "parse error at ...: syntax error while parsing X"
    if (const std::size_t p = reason.find("; last read"); p != std::string::npos)
        reason.resize(p);
    for (char& c : reason)
        if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7F)
            c = '?';
    if (at >= text.size())
        return "the text ends too early (" + reason + ")";
    return "the text is malformed at line " + str(line) + ", column " + str(column) + " (" +
           reason + ")";
}

/** Whether json is glTF 1.0: asset.version "1" or "1.x", or meshes as a dictionary. */
bool isGltf1(const Json& json) {
    if (!json.is_object())
        return false;
    const auto asset = json.find("asset");
    if (asset != json.end() && asset->is_object()) {
        const auto version = asset->find("version");
        if (version != asset->end() && version->is_string()) {
            const std::string v = version->get<std::string>();
            return v == "1" || v.rfind("1.", 0) == 0;
        }
    }
    const auto meshes = json.find("meshes");
    return meshes != json.end() && meshes->is_object();
}

/** A glTF file as it is read: its bytes, where its chunks are, and its JSON parsed. */
struct GltfSource {
    std::vector<std::uint8_t> bytes;
    bool binary = false;
    glb::Layout parts; // for a text file, the JSON is all of it
    Json json;
};

Status readGltfBytes(const fs::path& file, const LoadLimits& limits,
                     std::vector<std::uint8_t>& bytes) {
    std::error_code ec;
    const std::uintmax_t size = fs::file_size(file, ec);
    if (ec)
        return Error{"cannot be read (" + ec.message() + ")"};
    if (size == 0)
        return Error{"is empty"};
    if (size > limits.maxFileBytes || size > std::numeric_limits<std::uint32_t>::max())
        return Error{"is too large (" + str(size) + " bytes)"};
    std::ifstream in(file, std::ios::binary);
    bytes.resize(static_cast<std::size_t>(size));
    if (!in || !in.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(size)))
        return Error{"cannot be read"};
    return {};
}

/** The GLB container checked (a text file is all JSON), then its JSON text parsed. */
Status parseGltfText(const fs::path& file, GltfSource& src) {
    src.binary = glb::hasMagic(src.bytes);
    if (src.binary) {
        Result<glb::Layout> layout = glb::readContainer(src.bytes);
        if (!layout)
            return layout.takeError();
        src.parts = *layout;
    } else {
        src.parts.jsonLength = src.bytes.size();
        src.parts.length = src.bytes.size();
    }
    const std::string_view jsonText(reinterpret_cast<const char*>(src.bytes.data()) +
                                        src.parts.jsonOffset,
                                    static_cast<std::size_t>(src.parts.jsonLength));
    // Neither the binary header nor text that starts like glTF's: another kind of file.
    if (!src.binary && !startsLikeJsonObject(jsonText))
        return Error{isGlbName(file)
                         ? "is not a glTF binary file (it does not start with the glTF header); "
                           "it may be damaged or another kind of file"
                         : "is not a glTF file (glTF text starts with “{”); it may be damaged or "
                           "another kind of file"};
    if (jsonNestingTooDeep(jsonText))
        return Error{"the glTF text is nested too deeply"};
    try {
        src.json = Json::parse(jsonText.begin(), jsonText.end());
    } catch (const Json::parse_error& e) {
        return Error{"is not a valid glTF file: " + describeParseError(e, jsonText)};
    } catch (const Json::exception&) {
        return Error{"is not a valid glTF file: its text cannot be read"};
    }
    return {};
}

/** The glTF schema's types, the image buffer views, then the required extensions. */
Result<gltf::Extensions> checkGltfJson(const Json& json) {
    if (Status valid = gltf::checkSchema(json); !valid)
        return valid.takeError();
    if (Status valid = gltf::checkImageViews(json); !valid)
        return valid.takeError();
    return gltf::checkExtensions(json);
}

/**
 * What tinygltf would refuse in compressed files is taken out of a copy of the JSON it parses
 * instead (src.bytes rewritten); the flattener reads the file's own (src.json). Only files that
 * declare a compression extension (as glTF requires them to) pay for the copy.
 */
void patchCompressedJson(GltfSource& src) {
    bool compressed = false;
    for (const Json& e : src.json.value("extensionsUsed", Json::array()))
        compressed = compressed || e == "KHR_draco_mesh_compression" ||
                     e == "EXT_meshopt_compression" || e == "KHR_meshopt_compression";
    if (!compressed)
        return;
    Json patched = src.json;
    // Both edits run on every compressed file, whether or not the first changed anything.
    const bool replaced = gltf::replaceFallbackBuffers(patched);
    const bool dropped = gltf::dropDracoIndices(patched);
    if (!replaced && !dropped)
        return;
    if (src.binary) {
        src.bytes = glb::replaceJson(src.bytes, src.parts, patched.dump());
        src.parts.length = src.bytes.size();
    } else {
        const std::string text = patched.dump();
        src.bytes.assign(text.begin(), text.end());
    }
}

/** tinygltf's model of src.bytes, every file it opens confined by access; its messages in err
 *  and warn. */
Status parseModel(const GltfSource& src, gltf::FileAccess& access, tinygltf::Model& model,
                  std::string& err, std::string& warn) {
    tinygltf::TinyGLTF loader;
    loader.SetFsCallbacks(gltf::confinedFileCallbacks(access));
    loader.SetImageLoader(&gltf::collectImage, &access);
    bool ok = false;
    if (src.binary)
        ok =
            loader.LoadBinaryFromMemory(&model, &err, &warn, src.bytes.data(),
                                        static_cast<unsigned int>(src.parts.length), access.folder);
    else
        ok = loader.LoadASCIIFromString(&model, &err, &warn,
                                        reinterpret_cast<const char*>(src.bytes.data()),
                                        static_cast<unsigned int>(src.bytes.size()), access.folder);
    if (!access.violation.empty())
        return Error{access.violation};
    if (!ok)
        return Error{err.empty() ? std::string("is not a valid glTF file") : oneLine(err)};
    return {};
}

Result<Mesh> load(const fs::path& file, const ProgressFn& progress, const LoadLimits& limits) {
    GltfSource src;
    if (Status read = readGltfBytes(file, limits, src.bytes); !read)
        return read.takeError();
    if (!reportProgress(progress, 0.05))
        return cancelledError();
    if (Status parsed = parseGltfText(file, src); !parsed)
        return parsed.takeError();
    if (isGltf1(src.json))
        return loadAssimp(file, progress, limits);
    Result<gltf::Extensions> extensions = checkGltfJson(src.json);
    if (!extensions)
        return extensions.takeError();
    std::vector<std::string> warnings = std::move(extensions->warnings);

    gltf::FileAccess access;
    access.folder = file.parent_path().string();
    access.maxBytes = limits.maxFileBytes;
    patchCompressedJson(src);
    tinygltf::Model model;
    std::string err, warn;
    if (Status parsed = parseModel(src, access, model, err, warn); !parsed)
        return parsed.takeError();
    src.bytes.clear();
    src.bytes.shrink_to_fit();
    if (Status decoded = gltf::decodeMeshoptViews(model, src.json, limits); !decoded)
        return decoded.takeError();
    if (!reportProgress(progress, 0.5))
        return cancelledError();

    auto scene = std::make_shared<SourceScene>();
    Result<Mesh> flattened = gltf::flattenGltf(model, src.json, access, extensions->quantized,
                                               progress, limits, scene.get());
    if (!flattened)
        return flattened.takeError();
    Mesh mesh = std::move(flattened).value();
    gltf::keepScene(src.json, src.parts.jsonLength, extensions->meshopt, model, access, mesh,
                    *scene);
    mesh.source = std::move(scene);
    // Then tinygltf's own warnings (missing images, ...), then the flattener's.
    for (const std::string& w : lines(warn))
        warnings.push_back(w);
    for (const std::string& e : lines(err))
        warnings.push_back(e);
    warnings.insert(warnings.end(), mesh.warnings.begin(), mesh.warnings.end());
    mesh.warnings = std::move(warnings);
    return mesh;
}

} // namespace

Result<Mesh> loadGltf(const std::filesystem::path& file, const ProgressFn& progress,
                      const LoadLimits& limits) {
    return catchLoadErrors([&] { return load(file, progress, limits); });
}

} // namespace core::detail
