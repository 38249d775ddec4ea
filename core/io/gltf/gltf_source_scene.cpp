// SPDX-License-Identifier: GPL-3.0-or-later
// The scene a glTF file held, kept beside the flattened mesh (see gltf_source_scene.h).
#include "core/io/gltf/gltf_source_scene.h"

#include <cstdint>
#include <exception>
#include <new>
#include <string>

namespace core::detail::gltf {

using Json = nlohmann::json;

namespace {
using Bytes = std::vector<std::uint8_t>;

constexpr std::uint64_t kMaxBin = 0xFFFFFFFFu - (64u << 20); // a GLB's length is 32 bits
// Parsed JSON takes tens of times its text in memory; real scenes' JSON stays far below this.
constexpr std::uint64_t kMaxJson = 16u << 20;

/** Appends bytes to bin at a 4-byte boundary; returns where they start. */
std::uint64_t append(Bytes& bin, const std::uint8_t* bytes, std::size_t size) {
    bin.resize((bin.size() + 3) & ~std::size_t{3}, 0);
    const std::uint64_t at = bin.size();
    bin.insert(bin.end(), bytes, bytes + size);
    return at;
}

/** "image/png" or "image/jpeg" by the file's first bytes, else "". */
std::string sniffMimeType(const Bytes& bytes) {
    if (bytes.size() >= 8 && bytes[0] == 0x89 && bytes[1] == 'P' && bytes[2] == 'N' &&
        bytes[3] == 'G')
        return "image/png";
    if (bytes.size() >= 3 && bytes[0] == 0xFF && bytes[1] == 0xD8 && bytes[2] == 0xFF)
        return "image/jpeg";
    return {};
}

/**
 * The buffers' data, one after the other (taken from model: a single buffer, a binary glTF's
 * usual one, moves without a copy), and the views moved into it.
 */
void mergeBuffers(tinygltf::Model& model, Json& json, Bytes& bin) {
    std::vector<std::uint64_t> base;
    if (model.buffers.size() == 1) {
        bin = std::move(model.buffers[0].data);
        base.push_back(0);
    } else {
        for (const tinygltf::Buffer& buffer : model.buffers)
            base.push_back(append(bin, buffer.data.data(), buffer.data.size()));
    }
    Json& views = json["bufferViews"];
    if (views.is_null())
        views = Json::array();
    for (Json& view : views) {
        const auto buffer = view.at("buffer").get<std::size_t>();
        view["buffer"] = 0;
        view["byteOffset"] = base.at(buffer) + view.value("byteOffset", std::uint64_t{0});
    }
}

/** Images read from files or data: URIs stored in views of bin instead. */
void embedImages(const FileAccess& access, Json& json, Bytes& bin) {
    const auto images = json.find("images");
    if (images == json.end())
        return;
    Json& views = json["bufferViews"];
    for (std::size_t i = 0; i < images->size(); ++i) {
        Json& image = (*images)[i];
        const auto bytes = access.imageBytes.find(int(i));
        if (!image.contains("uri") || bytes == access.imageBytes.end() || bytes->second.empty())
            continue; // in a view already, or not read (the write-back warns)
        std::string mimeType = sniffMimeType(bytes->second);
        if (mimeType.empty())
            mimeType = image.value("mimeType", std::string());
        if (mimeType.empty())
            continue;
        const std::uint64_t at = append(bin, bytes->second.data(), bytes->second.size());
        views.push_back({{"buffer", 0}, {"byteOffset", at}, {"byteLength", bytes->second.size()}});
        image.erase("uri");
        image["bufferView"] = views.size() - 1;
        image["mimeType"] = mimeType;
    }
}

/** The scene's JSON and one buffer of its data; "" or why it cannot be. */
std::string copyScene(const Json& json, tinygltf::Model& model, const FileAccess& access,
                      SourceScene& scene) {
    try {
        scene.json = json;
        mergeBuffers(model, scene.json, scene.bin);
        embedImages(access, scene.json, scene.bin);
    } catch (const std::bad_alloc&) {
        return "there was not enough memory to keep it";
    } catch (const std::exception&) {
        return "its buffer views cannot be read";
    }
    if (scene.bin.size() > kMaxBin)
        return "its buffers and images are too large for one binary glTF file";
    if (scene.bin.empty())
        scene.json.erase("buffers");
    else
        scene.json["buffers"] = Json::array({{{"byteLength", scene.bin.size()}}});
    return {};
}

} // namespace

void keepScene(const Json& json, std::uint64_t jsonBytes, bool meshopt, tinygltf::Model& model,
               const FileAccess& access, const Mesh& mesh, SourceScene& scene) {
    scene.uvHash = hashValues(mesh.uvs);
    scene.colorHash = hashValues(mesh.colors);
    if (meshopt)
        scene.notKept = "its buffers are compressed with EXT_meshopt_compression";
    else if (jsonBytes > kMaxJson)
        scene.notKept = "its JSON is larger than 16 MiB";
    else
        scene.notKept = copyScene(json, model, access, scene);
    if (!scene.notKept.empty()) {
        scene.json = Json();
        scene.bin = {};
        scene.primitives = {};
        scene.usedVertices = {};
    }
}

} // namespace core::detail::gltf
