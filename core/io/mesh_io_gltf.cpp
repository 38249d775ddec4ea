// SPDX-License-Identifier: GPL-3.0-or-later
// glTF 2.0 loader. tinygltf parses; everything it hands over is checked here before use.
//
// Order of work and the decisions behind it:
// 1. The GLB container is checked first (glb_container.h): tinygltf 2.7 lets the BIN chunk run 8
//    bytes past the declared length.
// 2. The JSON is checked against the glTF schema's types (tinygltf silently ignores properties of
//    the wrong type, so "index": -1 or "primitives": {} would otherwise load as something else),
//    and for nesting depth (deep nesting costs stack in the JSON library).
// 3. tinygltf loads buffers and images through our file callbacks, which only open files inside
//    the model's folder; a URI that tries to leave it fails the whole load. Image bytes are only
//    collected there and decoded later with OpenImageIO, and only for base color textures.
// 4. The default scene (else scene 0) is flattened depth-first in document order. Without any
//    scene, the root nodes are used (or, without nodes, the meshes in order), with a warning.
//    Every node may be reached once: a cycle or a node with two parents is an error (sharing
//    would otherwise let a small file instance geometry exponentially).
// 5. Each primitive contributes the vertices its indices reference (in their original order), so
//    primitives sharing one big vertex accessor do not multiply it.
#include <algorithm>
#include <array>
#include <bit>
#include <cctype>
#include <cmath>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include "core/io/glb_container.h"
#include "core/io/json_depth.h"
#include "core/io/mesh_io.h"

static_assert(std::endian::native == std::endian::little,
              "glTF buffers are little-endian and are read with memcpy");

namespace core::detail {

Result<Mesh> loadGltf(const std::filesystem::path& file, const ProgressFn& progress,
                      const LoadLimits& limits);

namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

constexpr std::uint64_t kMaxIndex = std::numeric_limits<std::int32_t>::max();
constexpr std::uint64_t kMaxByteSize = std::numeric_limits<std::uint32_t>::max();

constexpr int kByte = TINYGLTF_COMPONENT_TYPE_BYTE;
constexpr int kUByte = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
constexpr int kShort = TINYGLTF_COMPONENT_TYPE_SHORT;
constexpr int kUShort = TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
constexpr int kUInt = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
constexpr int kFloat = TINYGLTF_COMPONENT_TYPE_FLOAT;

std::string str(std::uint64_t v) {
    return std::to_string(v);
}

bool addOverflows(std::uint64_t a, std::uint64_t b, std::uint64_t& out) {
    return __builtin_add_overflow(a, b, &out);
}
bool mulOverflows(std::uint64_t a, std::uint64_t b, std::uint64_t& out) {
    return __builtin_mul_overflow(a, b, &out);
}

// ---------------------------------------------------------------------------------------------
// JSON checks

/** The types the glTF 2.0 schema gives the properties; the first violation is reported. */
class SchemaCheck {
public:
    std::string run(const Json& root) {
        checkRoot(root);
        return m_error;
    }

private:
    using Fn = void (SchemaCheck::*)(const Json&, const std::string&);

    std::string m_error;

    static std::string at(const std::string& where, std::string_view key) {
        return where.empty() ? std::string(key) : where + "." + std::string(key);
    }
    static std::string at(const std::string& where, std::size_t i) {
        return where + "[" + std::to_string(i) + "]";
    }
    bool failed() const { return !m_error.empty(); }
    void fail(const std::string& msg) {
        if (m_error.empty())
            m_error = msg;
    }

    static bool isUInt(const Json& v, std::uint64_t max) {
        if (v.is_number_unsigned())
            return v.get<std::uint64_t>() <= max;
        if (v.is_number_integer())
            return v.get<std::int64_t>() >= 0 &&
                   static_cast<std::uint64_t>(v.get<std::int64_t>()) <= max;
        return false;
    }
    static bool isNumber(const Json& v) {
        return v.is_number() && (!v.is_number_float() || std::isfinite(v.get<double>()));
    }

    void uintProp(const Json& o, const char* key, const std::string& where, bool required,
                  std::uint64_t max = kMaxIndex, std::uint64_t min = 0) {
        const auto it = o.find(key);
        if (it == o.end()) {
            if (required)
                fail(at(where, key) + " is missing");
            return;
        }
        if (!isUInt(*it, max))
            fail(at(where, key) + " must be an integer from " + str(min) + " to " + str(max));
        else if (it->get<std::uint64_t>() < min)
            fail(at(where, key) + " must be an integer from " + str(min) + " to " + str(max));
    }
    void numberProp(const Json& o, const char* key, const std::string& where) {
        const auto it = o.find(key);
        if (it != o.end() && !isNumber(*it))
            fail(at(where, key) + " must be a number");
    }
    void stringProp(const Json& o, const char* key, const std::string& where,
                    bool required = false) {
        const auto it = o.find(key);
        if (it == o.end()) {
            if (required)
                fail(at(where, key) + " is missing");
        } else if (!it->is_string()) {
            fail(at(where, key) + " must be a string");
        }
    }
    void boolProp(const Json& o, const char* key, const std::string& where) {
        const auto it = o.find(key);
        if (it != o.end() && !it->is_boolean())
            fail(at(where, key) + " must be true or false");
    }
    void numberArray(const Json& o, const char* key, const std::string& where, std::size_t minN,
                     std::size_t maxN) {
        const auto it = o.find(key);
        if (it == o.end())
            return;
        if (!it->is_array() || it->size() < minN || it->size() > maxN) {
            fail(at(where, key) + (minN == maxN ? " must be an array of " + str(minN) + " numbers"
                                                : " must be an array of numbers"));
            return;
        }
        for (const Json& v : *it)
            if (!isNumber(v))
                return fail(at(where, key) + " must contain only numbers");
    }
    void uintArray(const Json& o, const char* key, const std::string& where, bool nonEmpty) {
        const auto it = o.find(key);
        if (it == o.end())
            return;
        if (!it->is_array() || (nonEmpty && it->empty()))
            return fail(at(where, key) +
                        (nonEmpty ? " must be a non-empty array" : " must be an array"));
        for (std::size_t i = 0; i < it->size(); ++i)
            if (!isUInt((*it)[i], kMaxIndex))
                return fail(at(at(where, key), i) + " must be a non-negative integer");
    }
    void enumProp(const Json& o, const char* key, const std::string& where,
                  std::initializer_list<std::int64_t> allowed, bool required) {
        const auto it = o.find(key);
        if (it == o.end()) {
            if (required)
                fail(at(where, key) + " is missing");
            return;
        }
        if (it->is_number_integer())
            for (std::int64_t a : allowed)
                if (it->get<std::int64_t>() == a)
                    return;
        fail(at(where, key) + " has an invalid value " + it->dump());
    }
    /** Every glTF object: it is an object; name, extensions, extras have their types. */
    bool object(const Json& o, const std::string& where) {
        if (!o.is_object()) {
            fail(where + " must be an object");
            return false;
        }
        stringProp(o, "name", where);
        const auto ext = o.find("extensions");
        if (ext != o.end()) {
            if (!ext->is_object()) {
                fail(at(where, "extensions") + " must be an object");
                return false;
            }
            for (auto e = ext->begin(); e != ext->end(); ++e)
                if (!e.value().is_object())
                    fail(at(at(where, "extensions"), e.key()) + " must be an object");
        }
        return !failed();
    }
    void objectProp(const Json& o, const char* key, const std::string& where, Fn fn,
                    bool required = false) {
        const auto it = o.find(key);
        if (it == o.end()) {
            if (required)
                fail(at(where, key) + " is missing");
            return;
        }
        (this->*fn)(*it, at(where, key));
    }
    void arrayOf(const Json& o, const char* key, const std::string& where, Fn fn,
                 bool required = false) {
        const auto it = o.find(key);
        if (it == o.end()) {
            if (required)
                fail(at(where, key) + " is missing");
            return;
        }
        if (!it->is_array() || (required && it->empty()))
            return fail(at(where, key) +
                        (required ? " must be a non-empty array" : " must be an array"));
        for (std::size_t i = 0; i < it->size() && !failed(); ++i)
            (this->*fn)((*it)[i], at(at(where, key), i));
    }

    void checkRoot(const Json& root) {
        if (!object(root, "the top level"))
            return;
        const auto asset = root.find("asset");
        if (asset == root.end())
            return fail("asset is missing");
        if (!object(*asset, "asset"))
            return;
        stringProp(*asset, "version", "asset", true);
        stringProp(*asset, "minVersion", "asset");
        if (failed())
            return;
        const std::string version = (*asset)["version"].get<std::string>();
        if (version.rfind("2.", 0) != 0)
            return fail("glTF version " + version + " is not supported (only 2.x)");
        for (const char* key : {"extensionsUsed", "extensionsRequired"}) {
            const auto it = root.find(key);
            if (it == root.end())
                continue;
            if (!it->is_array())
                return fail(std::string(key) + " must be an array of strings");
            for (const Json& v : *it)
                if (!v.is_string())
                    return fail(std::string(key) + " must be an array of strings");
        }
        uintProp(root, "scene", "", false);
        arrayOf(root, "accessors", "", &SchemaCheck::accessor);
        arrayOf(root, "animations", "", &SchemaCheck::plain);
        arrayOf(root, "buffers", "", &SchemaCheck::buffer);
        arrayOf(root, "bufferViews", "", &SchemaCheck::bufferView);
        arrayOf(root, "cameras", "", &SchemaCheck::plain);
        arrayOf(root, "images", "", &SchemaCheck::image);
        arrayOf(root, "materials", "", &SchemaCheck::material);
        arrayOf(root, "meshes", "", &SchemaCheck::mesh);
        arrayOf(root, "nodes", "", &SchemaCheck::node);
        arrayOf(root, "samplers", "", &SchemaCheck::sampler);
        arrayOf(root, "scenes", "", &SchemaCheck::scene);
        arrayOf(root, "skins", "", &SchemaCheck::plain);
        arrayOf(root, "textures", "", &SchemaCheck::texture);
    }
    void plain(const Json& o, const std::string& where) { object(o, where); }
    void accessor(const Json& o, const std::string& where) {
        if (!object(o, where))
            return;
        uintProp(o, "bufferView", where, false);
        uintProp(o, "byteOffset", where, false, kMaxByteSize);
        enumProp(o, "componentType", where, {kByte, kUByte, kShort, kUShort, kUInt, kFloat}, true);
        boolProp(o, "normalized", where);
        uintProp(o, "count", where, true, kMaxIndex, 1);
        stringProp(o, "type", where, true);
        if (failed())
            return;
        static const std::set<std::string> types = {"SCALAR", "VEC2", "VEC3", "VEC4",
                                                    "MAT2",   "MAT3", "MAT4"};
        if (!types.count(o["type"].get<std::string>()))
            return fail(at(where, "type") + " has an invalid value " + o["type"].dump());
        numberArray(o, "max", where, 1, 16);
        numberArray(o, "min", where, 1, 16);
        objectProp(o, "sparse", where, &SchemaCheck::sparse);
    }
    void sparse(const Json& o, const std::string& where) {
        if (!object(o, where))
            return;
        uintProp(o, "count", where, true, kMaxIndex, 1);
        objectProp(o, "indices", where, &SchemaCheck::sparseIndices, true);
        objectProp(o, "values", where, &SchemaCheck::sparseValues, true);
    }
    void sparseIndices(const Json& o, const std::string& where) {
        if (!object(o, where))
            return;
        uintProp(o, "bufferView", where, true);
        uintProp(o, "byteOffset", where, false);
        enumProp(o, "componentType", where, {kUByte, kUShort, kUInt}, true);
    }
    void sparseValues(const Json& o, const std::string& where) {
        if (!object(o, where))
            return;
        uintProp(o, "bufferView", where, true);
        uintProp(o, "byteOffset", where, false);
    }
    void buffer(const Json& o, const std::string& where) {
        if (!object(o, where))
            return;
        stringProp(o, "uri", where);
        uintProp(o, "byteLength", where, true, kMaxByteSize, 1);
    }
    void bufferView(const Json& o, const std::string& where) {
        if (!object(o, where))
            return;
        uintProp(o, "buffer", where, true);
        uintProp(o, "byteOffset", where, false, kMaxByteSize);
        uintProp(o, "byteLength", where, true, kMaxByteSize, 1);
        uintProp(o, "byteStride", where, false, 252, 4);
        uintProp(o, "target", where, false, 65535);
    }
    void image(const Json& o, const std::string& where) {
        if (!object(o, where))
            return;
        stringProp(o, "uri", where);
        stringProp(o, "mimeType", where);
        uintProp(o, "bufferView", where, false);
    }
    void textureInfo(const Json& o, const std::string& where) {
        if (!object(o, where))
            return;
        uintProp(o, "index", where, true);
        uintProp(o, "texCoord", where, false);
        numberProp(o, "scale", where);    // normalTexture
        numberProp(o, "strength", where); // occlusionTexture
    }
    void pbr(const Json& o, const std::string& where) {
        if (!object(o, where))
            return;
        numberArray(o, "baseColorFactor", where, 4, 4);
        objectProp(o, "baseColorTexture", where, &SchemaCheck::textureInfo);
        numberProp(o, "metallicFactor", where);
        numberProp(o, "roughnessFactor", where);
        objectProp(o, "metallicRoughnessTexture", where, &SchemaCheck::textureInfo);
    }
    void material(const Json& o, const std::string& where) {
        if (!object(o, where))
            return;
        objectProp(o, "pbrMetallicRoughness", where, &SchemaCheck::pbr);
        objectProp(o, "normalTexture", where, &SchemaCheck::textureInfo);
        objectProp(o, "occlusionTexture", where, &SchemaCheck::textureInfo);
        objectProp(o, "emissiveTexture", where, &SchemaCheck::textureInfo);
        numberArray(o, "emissiveFactor", where, 3, 3);
        stringProp(o, "alphaMode", where);
        numberProp(o, "alphaCutoff", where);
        boolProp(o, "doubleSided", where);
    }
    void attributes(const Json& o, const std::string& where) {
        if (!o.is_object())
            return fail(where + " must be an object");
        for (auto it = o.begin(); it != o.end(); ++it)
            if (!isUInt(it.value(), kMaxIndex))
                return fail(at(where, it.key()) + " must be a non-negative integer");
    }
    void primitive(const Json& o, const std::string& where) {
        if (!object(o, where))
            return;
        objectProp(o, "attributes", where, &SchemaCheck::attributes, true);
        uintProp(o, "indices", where, false);
        uintProp(o, "material", where, false);
        uintProp(o, "mode", where, false, 6);
        arrayOf(o, "targets", where, &SchemaCheck::attributes);
    }
    void mesh(const Json& o, const std::string& where) {
        if (!object(o, where))
            return;
        arrayOf(o, "primitives", where, &SchemaCheck::primitive, true);
        numberArray(o, "weights", where, 0, kMaxIndex);
    }
    void node(const Json& o, const std::string& where) {
        if (!object(o, where))
            return;
        uintProp(o, "camera", where, false);
        uintArray(o, "children", where, false); // the schema wants >= 1; [] is harmless
        uintProp(o, "skin", where, false);
        numberArray(o, "matrix", where, 16, 16);
        uintProp(o, "mesh", where, false);
        numberArray(o, "rotation", where, 4, 4);
        numberArray(o, "scale", where, 3, 3);
        numberArray(o, "translation", where, 3, 3);
        numberArray(o, "weights", where, 0, kMaxIndex);
    }
    void sampler(const Json& o, const std::string& where) {
        if (!object(o, where))
            return;
        for (const char* key : {"magFilter", "minFilter", "wrapS", "wrapT"})
            uintProp(o, key, where, false, 65535);
    }
    void scene(const Json& o, const std::string& where) {
        if (!object(o, where))
            return;
        uintArray(o, "nodes", where, false);
    }
    void texture(const Json& o, const std::string& where) {
        if (!object(o, where))
            return;
        uintProp(o, "sampler", where, false);
        uintProp(o, "source", where, false);
    }
};

/**
 * Buffer views that images use, against the buffers' declared lengths. tinygltf makes every
 * buffer exactly that long (or refuses) but computes image pointers from these views before
 * anything else could check them. Other views are checked when an accessor uses them.
 */
std::string checkImageViews(const Json& root) {
    const auto images = root.find("images");
    if (images == root.end())
        return {};
    const auto views = root.find("bufferViews");
    const auto buffers = root.find("buffers");
    const std::size_t viewCount = views == root.end() ? 0 : views->size();
    const std::size_t bufferCount = buffers == root.end() ? 0 : buffers->size();
    for (std::size_t i = 0; i < images->size(); ++i) {
        const Json& img = (*images)[i];
        if (!img.contains("bufferView"))
            continue;
        const auto v = img["bufferView"].get<std::uint64_t>();
        if (v >= viewCount)
            return "image " + str(i) + " uses buffer view " + str(v) + ", which does not exist";
        const Json& view = (*views)[v];
        const auto b = view["buffer"].get<std::uint64_t>();
        if (b >= bufferCount)
            return "buffer view " + str(v) + " uses buffer " + str(b) + ", which does not exist";
        const std::uint64_t offset = view.value("byteOffset", std::uint64_t{0});
        const auto length = view["byteLength"].get<std::uint64_t>();
        const auto bufferLength = (*buffers)[b]["byteLength"].get<std::uint64_t>();
        std::uint64_t end = 0;
        if (addOverflows(offset, length, end) || end > bufferLength)
            return "buffer view " + str(v) + " reaches past the end of buffer " + str(b) + " (" +
                   str(bufferLength) + " bytes)";
    }
    return {};
}

/**
 * extensionsRequired: KHR_mesh_quantization is supported; shading-only extensions cannot change
 * what is painted on, so they are ignored with a warning; anything else (Draco, meshopt, ...)
 * fails the load, as glTF requires.
 */
std::string checkExtensions(const Json& root, bool& quantized, std::vector<std::string>& warnings) {
    static const std::set<std::string> ignorable = {"KHR_materials_pbrSpecularGlossiness",
                                                    "KHR_materials_unlit",
                                                    "KHR_technique_webgl",
                                                    "KHR_lights_punctual",
                                                    "KHR_texture_transform",
                                                    "KHR_materials_emissive_strength",
                                                    "KHR_materials_variants",
                                                    "KHR_xmp_json_ld"};
    quantized = false;
    for (const Json& e : root.value("extensionsUsed", Json::array()))
        if (e.get<std::string>() == "KHR_mesh_quantization")
            quantized = true;
    for (const Json& e : root.value("extensionsRequired", Json::array())) {
        const std::string ext = e.get<std::string>();
        if (ext == "KHR_mesh_quantization") {
            quantized = true;
        } else if (ignorable.count(ext) || ext.rfind("KHR_materials_", 0) == 0) {
            warnings.push_back("the required extension " + ext + " is ignored");
        } else {
            return "the file requires the unsupported glTF extension " + ext;
        }
    }
    return {};
}

// ---------------------------------------------------------------------------------------------
// File access for tinygltf: only inside the model's folder

struct FileAccess {
    std::string folder; // canonical, no trailing slash
    std::uint64_t maxBytes = 0;
    std::string violation; // the first URI that tried to leave the folder
    std::map<int, std::vector<std::uint8_t>> imageBytes; // encoded images loaded from URIs
};

/** The real file for a path tinygltf built as folder + "/" + uri, or empty if not allowed. */
fs::path resolveInside(const std::string& joined, FileAccess& access) {
    const std::string prefix = access.folder == "/" ? "/" : access.folder + "/";
    // tinygltf also tries "./" + uri (the working directory): never allowed, not reported.
    if (joined.size() <= prefix.size() || joined.compare(0, prefix.size(), prefix) != 0)
        return {};
    const std::string uri = joined.substr(prefix.size());
    auto reject = [&](const std::string& why) {
        if (access.violation.empty())
            access.violation = "the URI \"" + uri + "\" " + why;
        return fs::path();
    };
    if (uri.find('\0') != std::string::npos)
        return reject("contains a NUL character");
    if (uri.front() == '/')
        return reject("is an absolute path; only files inside the model's folder are read");
    fs::path rel(uri);
    for (const fs::path& part : rel)
        if (part == "..")
            return reject("points outside the model's folder");
    const fs::path full = fs::path(access.folder) / rel;
    std::error_code ec;
    const fs::path real = fs::canonical(full, ec);
    if (ec)
        return {}; // missing: tinygltf reports it
    const std::string realStr = real.string();
    if (realStr.size() <= prefix.size() || realStr.compare(0, prefix.size(), prefix) != 0)
        return reject("leads outside the model's folder through a symbolic link");
    return real;
}

bool fileExists(const std::string& path, void* user) {
    auto& access = *static_cast<FileAccess*>(user);
    const fs::path real = resolveInside(path, access);
    std::error_code ec;
    return !real.empty() && fs::is_regular_file(real, ec);
}

std::string expandFilePath(const std::string& path, void*) {
    return path; // no shell-style expansion, ever
}

bool readWholeFile(std::vector<unsigned char>* out, std::string* err, const std::string& path,
                   void* user) {
    auto& access = *static_cast<FileAccess*>(user);
    const fs::path real = resolveInside(path, access);
    std::error_code ec;
    if (real.empty() || !fs::is_regular_file(real, ec)) {
        if (err)
            *err += "not a readable file inside the model's folder";
        return false;
    }
    const std::uintmax_t size = fs::file_size(real, ec);
    if (ec || size > access.maxBytes) {
        if (err)
            *err += ec ? "cannot read the file" : "the file is too large";
        return false;
    }
    std::ifstream in(real, std::ios::binary);
    out->resize(static_cast<std::size_t>(size));
    if (!in || (size > 0 && !in.read(reinterpret_cast<char*>(out->data()),
                                     static_cast<std::streamsize>(size)))) {
        if (err)
            *err += "cannot read the file";
        return false;
    }
    return true;
}

bool writeWholeFile(std::string* err, const std::string&, const std::vector<unsigned char>&,
                    void*) {
    if (err)
        *err += "writing is not allowed while loading";
    return false;
}

/**
 * Collects the bytes of images read from URIs (data: or files); decoding waits until a material
 * needs the image. Images in buffer views are left alone: tinygltf computes their pointer before
 * anything checked the view's bounds.
 */
bool collectImage(tinygltf::Image* image, const int index, std::string*, std::string*, int, int,
                  const unsigned char* bytes, int size, void* user) {
    auto& access = *static_cast<FileAccess*>(user);
    if (image->bufferView < 0 && bytes != nullptr && size > 0)
        access.imageBytes[index].assign(bytes, bytes + size);
    return true;
}

// ---------------------------------------------------------------------------------------------
// Flattening

int componentSize(int componentType) {
    switch (componentType) {
    case kByte:
    case kUByte:
        return 1;
    case kShort:
    case kUShort:
        return 2;
    case kUInt:
    case kFloat:
        return 4;
    default:
        return 0;
    }
}

int componentCount(int type) {
    switch (type) {
    case TINYGLTF_TYPE_SCALAR:
        return 1;
    case TINYGLTF_TYPE_VEC2:
        return 2;
    case TINYGLTF_TYPE_VEC3:
        return 3;
    case TINYGLTF_TYPE_VEC4:
    case TINYGLTF_TYPE_MAT2:
        return 4;
    case TINYGLTF_TYPE_MAT3:
        return 9;
    case TINYGLTF_TYPE_MAT4:
        return 16;
    default:
        return 0;
    }
}

const char* typeName(int type) {
    switch (type) {
    case TINYGLTF_TYPE_SCALAR:
        return "SCALAR";
    case TINYGLTF_TYPE_VEC2:
        return "VEC2";
    case TINYGLTF_TYPE_VEC3:
        return "VEC3";
    case TINYGLTF_TYPE_VEC4:
        return "VEC4";
    default:
        return "a matrix type";
    }
}

std::string componentName(int componentType, bool normalized) {
    std::string n;
    switch (componentType) {
    case kByte:
        n = "byte";
        break;
    case kUByte:
        n = "unsigned byte";
        break;
    case kShort:
        n = "short";
        break;
    case kUShort:
        n = "unsigned short";
        break;
    case kUInt:
        n = "unsigned int";
        break;
    case kFloat:
        return "float";
    default:
        return "type " + std::to_string(componentType);
    }
    return normalized ? "normalized " + n : n;
}

/** One component as a number; normalized integers map to [0, 1] or [-1, 1] (glTF 2.0 §3.11). */
double readComponent(const std::uint8_t* p, int componentType, bool normalized) {
    switch (componentType) {
    case kByte: {
        std::int8_t v;
        std::memcpy(&v, p, 1);
        return normalized ? std::max(v / 127.0, -1.0) : v;
    }
    case kUByte:
        return normalized ? *p / 255.0 : *p;
    case kShort: {
        std::int16_t v;
        std::memcpy(&v, p, 2);
        return normalized ? std::max(v / 32767.0, -1.0) : v;
    }
    case kUShort: {
        std::uint16_t v;
        std::memcpy(&v, p, 2);
        return normalized ? v / 65535.0 : v;
    }
    case kUInt: {
        std::uint32_t v;
        std::memcpy(&v, p, 4);
        return v;
    }
    case kFloat: {
        float v;
        std::memcpy(&v, p, 4);
        return v;
    }
    default:
        return 0.0;
    }
}

/** p as floats, or false if it does not fit (a double beyond float range is not castable). */
bool toFloat(const glm::dvec3& p, glm::vec3& out) {
    constexpr double kMax = std::numeric_limits<float>::max();
    for (int k = 0; k < 3; ++k)
        if (!std::isfinite(p[k]) || std::abs(p[k]) > kMax)
            return false;
    out = glm::vec3(p);
    return true;
}

/** n normalized in double precision; zero (recomputed later) when it has no direction. */
glm::vec3 unitNormal(const glm::dvec3& n) {
    const double len = glm::length(n);
    return std::isfinite(len) && len > 0.0 ? glm::vec3(n / len) : glm::vec3(0.0f);
}

enum class Semantic { Position, Normal, TexCoord, Color, Indices };

const char* semanticName(Semantic s) {
    switch (s) {
    case Semantic::Position:
        return "POSITION";
    case Semantic::Normal:
        return "NORMAL";
    case Semantic::TexCoord:
        return "TEXCOORD_0";
    case Semantic::Color:
        return "COLOR_0";
    case Semantic::Indices:
        return "indices";
    }
    return "";
}

/** The accessor types glTF 2.0 allows per semantic, widened by KHR_mesh_quantization. */
bool typeAllowed(Semantic s, int type) {
    switch (s) {
    case Semantic::Position:
    case Semantic::Normal:
        return type == TINYGLTF_TYPE_VEC3;
    case Semantic::TexCoord:
        return type == TINYGLTF_TYPE_VEC2;
    case Semantic::Color:
        return type == TINYGLTF_TYPE_VEC3 || type == TINYGLTF_TYPE_VEC4;
    case Semantic::Indices:
        return type == TINYGLTF_TYPE_SCALAR;
    }
    return false;
}

bool componentAllowed(Semantic s, int ct, bool normalized, bool quantized) {
    switch (s) {
    case Semantic::Position:
        return ct == kFloat ||
               (quantized && (ct == kByte || ct == kUByte || ct == kShort || ct == kUShort));
    case Semantic::Normal:
        return ct == kFloat || (quantized && normalized && (ct == kByte || ct == kShort));
    case Semantic::TexCoord:
        if (ct == kFloat || (normalized && (ct == kUByte || ct == kUShort)))
            return true;
        return quantized && (ct == kByte || ct == kShort || ct == kUByte || ct == kUShort);
    case Semantic::Color:
        return ct == kFloat || (normalized && (ct == kUByte || ct == kUShort));
    case Semantic::Indices:
        return !normalized && (ct == kUByte || ct == kUShort || ct == kUInt);
    }
    return false;
}

struct Instance {
    int mesh = -1;
    int node = -1;
    glm::dmat4 transform{1.0};
};

class GltfFlattener {
public:
    GltfFlattener(const tinygltf::Model& model, const Json& json, const FileAccess& access,
                  bool quantized, const ProgressFn& progress, const LoadLimits& limits)
        : m_model(model), m_json(json), m_access(access), m_progress(progress), m_limits(limits),
          m_quantized(quantized) {}

    /** Flattens into out; false with error() on failure. */
    bool run(Mesh& out);
    const Error& error() const { return m_error; }

private:
    const tinygltf::Model& m_model;
    const Json& m_json;
    const FileAccess& m_access;
    const ProgressFn& m_progress;
    const LoadLimits& m_limits;
    Error m_error;
    bool m_quantized;
    std::set<std::string> m_warned;
    Mesh m_mesh;
    std::vector<char> m_hasNormal;
    bool m_anyUv = false, m_anyColor = false;
    std::size_t m_skippedPrimitives = 0;
    std::map<int, int> m_imageToTexture; // glTF image -> Mesh::textures index (-1: failed)

    bool fail(std::string msg, ErrorKind kind = ErrorKind::BadInput) {
        if (m_error.message.empty())
            m_error = Error{std::move(msg), kind};
        return false;
    }
    void warnOnce(const std::string& msg) {
        if (m_warned.insert(msg).second)
            m_mesh.warnings.push_back(msg);
    }

    bool collectInstances(std::vector<Instance>& instances);
    bool localTransform(int nodeIndex, glm::dmat4& out);
    bool viewBytes(int viewIndex, const std::string& user, const std::uint8_t*& data,
                   std::uint64_t& length);
    /** Float attributes or uint32 indices; normalized integers are converted (§3.11). */
    template <typename T>
    bool readAccessor(int accessorIndex, Semantic semantic, int& components, std::vector<T>& out);
    bool addPrimitive(const Instance& inst, std::size_t primIndex);
    bool addMaterials();
    int textureFor(int textureIndex, int texCoord, const std::string& materialName);
};

bool GltfFlattener::localTransform(int nodeIndex, glm::dmat4& out) {
    const tinygltf::Node& node = m_model.nodes[static_cast<std::size_t>(nodeIndex)];
    if (node.matrix.size() == 16) {
        out = glm::make_mat4(node.matrix.data()); // column-major, as glTF stores it
    } else {
        glm::dmat4 t(1.0), r(1.0), s(1.0);
        if (node.translation.size() == 3)
            t = glm::translate(glm::dmat4(1.0), glm::make_vec3(node.translation.data()));
        if (node.rotation.size() == 4) {
            glm::dquat q(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);
            const double len = glm::length(q);
            if (!(len > 1e-12) || !std::isfinite(len))
                return fail("node " + str(nodeIndex) + " has an invalid rotation");
            r = glm::mat4_cast(q / len);
        }
        if (node.scale.size() == 3)
            s = glm::scale(glm::dmat4(1.0), glm::make_vec3(node.scale.data()));
        out = t * r * s;
    }
    for (int c = 0; c < 4; ++c)
        for (int k = 0; k < 4; ++k)
            if (!std::isfinite(out[c][k]))
                return fail("node " + str(nodeIndex) + " has a transform that is not finite");
    return true;
}

bool GltfFlattener::collectInstances(std::vector<Instance>& instances) {
    const std::size_t nodeCount = m_model.nodes.size();
    std::vector<int> roots;
    if (m_model.defaultScene >= 0) {
        if (static_cast<std::size_t>(m_model.defaultScene) >= m_model.scenes.size())
            return fail("the default scene " + str(m_model.defaultScene) + " does not exist");
        roots = m_model.scenes[static_cast<std::size_t>(m_model.defaultScene)].nodes;
    } else if (!m_model.scenes.empty()) {
        roots = m_model.scenes[0].nodes;
    } else if (nodeCount > 0) {
        std::vector<char> isChild(nodeCount, 0);
        for (const tinygltf::Node& n : m_model.nodes)
            for (int c : n.children)
                if (c >= 0 && static_cast<std::size_t>(c) < nodeCount)
                    isChild[static_cast<std::size_t>(c)] = 1;
        for (std::size_t i = 0; i < nodeCount; ++i)
            if (!isChild[i])
                roots.push_back(static_cast<int>(i));
        warnOnce("the file has no scene: all root nodes are shown");
    } else {
        for (std::size_t m = 0; m < m_model.meshes.size(); ++m)
            instances.push_back(Instance{static_cast<int>(m), -1, glm::dmat4(1.0)});
        if (!instances.empty())
            warnOnce("the file has no scene and no nodes: all meshes are shown untransformed");
        return true;
    }

    // Iterative depth-first walk in document order; each node may be reached only once.
    std::vector<char> reached(nodeCount, 0);
    struct Item {
        int node;
        glm::dmat4 parent;
    };
    std::vector<Item> stack;
    for (auto it = roots.rbegin(); it != roots.rend(); ++it)
        stack.push_back(Item{*it, glm::dmat4(1.0)});
    while (!stack.empty()) {
        const Item item = stack.back();
        stack.pop_back();
        if (item.node < 0 || static_cast<std::size_t>(item.node) >= nodeCount)
            return fail("node " + str(item.node) + " does not exist");
        const auto idx = static_cast<std::size_t>(item.node);
        if (reached[idx])
            return fail("node " + str(item.node) +
                        " is reached more than once (the node hierarchy has a cycle or a node "
                        "with two parents)");
        reached[idx] = 1;
        glm::dmat4 local;
        if (!localTransform(item.node, local))
            return false;
        const glm::dmat4 global = item.parent * local;
        const tinygltf::Node& node = m_model.nodes[idx];
        if (node.mesh >= 0) {
            if (static_cast<std::size_t>(node.mesh) >= m_model.meshes.size())
                return fail("node " + str(item.node) + " uses mesh " + str(node.mesh) +
                            ", which does not exist");
            if (node.skin >= 0)
                warnOnce("skinning is ignored: skinned meshes are shown in their bind pose");
            instances.push_back(Instance{node.mesh, item.node, global});
        }
        for (auto c = node.children.rbegin(); c != node.children.rend(); ++c)
            stack.push_back(Item{*c, global});
    }
    return true;
}

bool GltfFlattener::viewBytes(int viewIndex, const std::string& user, const std::uint8_t*& data,
                              std::uint64_t& length) {
    if (viewIndex < 0 || static_cast<std::size_t>(viewIndex) >= m_model.bufferViews.size())
        return fail(user + " uses buffer view " + str(viewIndex) + ", which does not exist");
    const tinygltf::BufferView& view = m_model.bufferViews[static_cast<std::size_t>(viewIndex)];
    if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= m_model.buffers.size())
        return fail("buffer view " + str(viewIndex) + " uses buffer " + str(view.buffer) +
                    ", which does not exist");
    const tinygltf::Buffer& buffer = m_model.buffers[static_cast<std::size_t>(view.buffer)];
    std::uint64_t end = 0;
    if (addOverflows(view.byteOffset, view.byteLength, end) || end > buffer.data.size())
        return fail("buffer view " + str(viewIndex) + " reaches past the end of buffer " +
                    str(view.buffer) + " (" + str(buffer.data.size()) + " bytes)");
    data = buffer.data.data() + view.byteOffset;
    length = view.byteLength;
    return true;
}

template <typename T>
bool GltfFlattener::readAccessor(int accessorIndex, Semantic semantic, int& components,
                                 std::vector<T>& out) {
    const std::string name = "accessor " + str(accessorIndex);
    if (accessorIndex < 0 || static_cast<std::size_t>(accessorIndex) >= m_model.accessors.size())
        return fail(std::string(semanticName(semantic)) + " uses accessor " + str(accessorIndex) +
                    ", which does not exist");
    const tinygltf::Accessor& acc = m_model.accessors[static_cast<std::size_t>(accessorIndex)];
    if (!typeAllowed(semantic, acc.type))
        return fail(name + " (" + semanticName(semantic) + ") has type " + typeName(acc.type) +
                    ", which glTF does not allow there");
    if (!componentAllowed(semantic, acc.componentType, acc.normalized, m_quantized))
        return fail(name + " (" + semanticName(semantic) + ") has component type " +
                    componentName(acc.componentType, acc.normalized) +
                    ", which glTF does not allow there");
    const std::uint64_t count = acc.count;
    const std::uint64_t cap =
        semantic == Semantic::Indices ? m_limits.maxTriangles * 3 + 2 : m_limits.maxVertices;
    if (count == 0)
        return fail(name + " has no elements");
    if (count > cap)
        return fail(name + " has too many elements (" + str(count) + ")");
    components = componentCount(acc.type);
    const std::uint64_t compSize = static_cast<std::uint64_t>(componentSize(acc.componentType));
    const std::uint64_t elemSize = compSize * static_cast<std::uint64_t>(components);
    const auto nc = static_cast<std::size_t>(components);
    out.assign(static_cast<std::size_t>(count) * nc, T(0));

    if (acc.bufferView >= 0) {
        const std::uint8_t* data = nullptr;
        std::uint64_t length = 0;
        if (!viewBytes(acc.bufferView, name, data, length))
            return false;
        const tinygltf::BufferView& view =
            m_model.bufferViews[static_cast<std::size_t>(acc.bufferView)];
        const std::uint64_t stride = view.byteStride != 0 ? view.byteStride : elemSize;
        if (stride < elemSize)
            return fail("buffer view " + str(acc.bufferView) + " has a byte stride of " +
                        str(stride) + ", smaller than the " + str(elemSize) + "-byte elements of " +
                        name);
        std::uint64_t span = 0, end = 0;
        if (mulOverflows(stride, count - 1, span) || addOverflows(span, elemSize, span) ||
            addOverflows(span, acc.byteOffset, end) || end > length)
            return fail(name + " reads past the end of buffer view " + str(acc.bufferView));
        for (std::size_t i = 0; i < count; ++i) {
            const std::uint8_t* e = data + acc.byteOffset + i * stride;
            for (std::size_t c = 0; c < nc; ++c)
                out[i * nc + c] =
                    readComponent(e + c * compSize, acc.componentType, acc.normalized);
        }
    } else if (semantic == Semantic::Indices && !acc.sparse.isSparse) {
        return fail(name + " (indices) has no buffer view");
    }

    if (acc.sparse.isSparse) {
        const auto& sp = acc.sparse;
        const std::uint64_t n = static_cast<std::uint64_t>(std::max(sp.count, 0));
        if (n == 0 || n > count)
            return fail(name + " has an invalid sparse count " + str(n));
        const int idxType = sp.indices.componentType;
        if (idxType != kUByte && idxType != kUShort && idxType != kUInt)
            return fail(name + " has sparse indices of an invalid component type");
        const std::uint8_t *idxData = nullptr, *valData = nullptr;
        std::uint64_t idxLen = 0, valLen = 0, end = 0;
        const std::string sparseName = name + " (sparse)";
        if (!viewBytes(sp.indices.bufferView, sparseName, idxData, idxLen) ||
            !viewBytes(sp.values.bufferView, sparseName, valData, valLen))
            return false;
        const auto idxSize = static_cast<std::uint64_t>(componentSize(idxType));
        const auto idxOffset = static_cast<std::uint64_t>(std::max(sp.indices.byteOffset, 0));
        const auto valOffset = static_cast<std::uint64_t>(std::max(sp.values.byteOffset, 0));
        if (addOverflows(idxOffset, n * idxSize, end) || end > idxLen)
            return fail(name + " has sparse indices past the end of buffer view " +
                        str(sp.indices.bufferView));
        if (addOverflows(valOffset, n * elemSize, end) || end > valLen)
            return fail(name + " has sparse values past the end of buffer view " +
                        str(sp.values.bufferView));
        for (std::size_t i = 0; i < n; ++i) {
            const auto target = static_cast<std::uint64_t>(
                readComponent(idxData + idxOffset + i * idxSize, idxType, false));
            if (target >= count)
                return fail(name + " has a sparse index " + str(target) + " out of range");
            const std::uint8_t* e = valData + valOffset + i * elemSize;
            for (std::size_t c = 0; c < nc; ++c)
                out[static_cast<std::size_t>(target) * nc + c] = static_cast<T>(
                    readComponent(e + c * compSize, acc.componentType, acc.normalized));
        }
    }

    if (semantic == Semantic::Position)
        for (T v : out)
            if (!std::isfinite(static_cast<double>(v)))
                return fail(name + " (POSITION) holds a value that is not a finite number");
    return true;
}

bool GltfFlattener::addPrimitive(const Instance& inst, std::size_t primIndex) {
    const tinygltf::Mesh& gm = m_model.meshes[static_cast<std::size_t>(inst.mesh)];
    const tinygltf::Primitive& prim = gm.primitives[primIndex];
    const std::string where = "mesh " + str(inst.mesh) + " primitive " + str(primIndex);

    int mode = prim.mode;
    if (mode == TINYGLTF_MODE_POINTS || mode == TINYGLTF_MODE_LINE ||
        mode == TINYGLTF_MODE_LINE_LOOP || mode == TINYGLTF_MODE_LINE_STRIP) {
        ++m_skippedPrimitives;
        return true;
    }
    if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
        mode != TINYGLTF_MODE_TRIANGLE_FAN)
        return fail(where + " has an invalid mode " + str(mode));
    const auto posIt = prim.attributes.find("POSITION");
    if (posIt == prim.attributes.end()) {
        warnOnce("primitives without POSITION were skipped");
        return true;
    }
    if (!prim.targets.empty())
        warnOnce("morph targets are ignored: meshes are shown without them");

    int nc = 0;
    std::vector<float> pos;
    if (!readAccessor(posIt->second, Semantic::Position, nc, pos))
        return false;
    const std::size_t vertexCount = pos.size() / 3;

    auto readMatching = [&](const char* attr, Semantic sem, int& comps,
                            std::vector<float>& values) -> int {
        const auto it = prim.attributes.find(attr);
        if (it == prim.attributes.end())
            return 0;
        if (!readAccessor(it->second, sem, comps, values))
            return -1;
        if (values.size() / static_cast<std::size_t>(comps) != vertexCount) {
            fail(where + ": " + attr + " has " +
                 str(values.size() / static_cast<std::size_t>(comps)) + " elements but POSITION " +
                 str(vertexCount));
            return -1;
        }
        return 1;
    };
    int nrmComps = 0, uvComps = 0, colComps = 0;
    std::vector<float> nrm, uv, col;
    const int hasNormal = readMatching("NORMAL", Semantic::Normal, nrmComps, nrm);
    const int hasUv = readMatching("TEXCOORD_0", Semantic::TexCoord, uvComps, uv);
    const int hasColor = readMatching("COLOR_0", Semantic::Color, colComps, col);
    if (hasNormal < 0 || hasUv < 0 || hasColor < 0)
        return false;

    // Vertex order of the primitive's triangles, before triangulating strips and fans.
    std::vector<std::uint32_t> order;
    if (prim.indices >= 0) {
        int one = 0;
        if (!readAccessor(prim.indices, Semantic::Indices, one, order))
            return false;
        for (std::uint32_t i : order)
            if (i >= vertexCount)
                return fail(where + ": index " + str(i) + " is out of range (the primitive has " +
                            str(vertexCount) + " vertices)");
    } else {
        order.resize(vertexCount);
        for (std::size_t i = 0; i < vertexCount; ++i)
            order[i] = static_cast<std::uint32_t>(i);
    }

    std::vector<std::uint32_t> tris; // local vertex indices, 3 per triangle
    const std::size_t n = order.size();
    if (mode == TINYGLTF_MODE_TRIANGLES) {
        if (n % 3 != 0)
            warnOnce("incomplete triangles at the end of a primitive were dropped");
        tris.assign(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(n - n % 3));
    } else if (n >= 3) {
        tris.reserve((n - 2) * 3);
        for (std::size_t i = 0; i + 2 < n; ++i) {
            if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) // glTF 2.0 §3.7.2.1: keeps the winding
                tris.insert(tris.end(), {order[i], order[i + 1 + i % 2], order[i + 2 - i % 2]});
            else
                tris.insert(tris.end(), {order[i + 1], order[i + 2], order[0]});
        }
    }
    if (tris.empty()) {
        warnOnce("primitives with fewer than 3 vertices were skipped");
        return true;
    }

    // Only the vertices the triangles use, in their original order.
    std::vector<std::uint32_t> remap(vertexCount, std::numeric_limits<std::uint32_t>::max());
    for (std::uint32_t v : tris)
        remap[v] = 0;
    std::uint64_t used = 0;
    for (std::uint32_t& r : remap)
        if (r == 0)
            r = static_cast<std::uint32_t>(used++);
    if (m_mesh.positions.size() + used > m_limits.maxVertices)
        return fail("too many vertices (more than " + str(m_limits.maxVertices) + ")");
    if (m_mesh.triangleCount() + tris.size() / 3 > m_limits.maxTriangles)
        return fail("too many triangles (more than " + str(m_limits.maxTriangles) + ")");

    const glm::dmat3 normalMatrix = glm::inverseTranspose(glm::dmat3(inst.transform));
    const bool mirrored = glm::determinant(glm::dmat3(inst.transform)) < 0.0;
    const auto base = static_cast<std::uint32_t>(m_mesh.positions.size());
    for (std::size_t v = 0; v < vertexCount; ++v) {
        if (remap[v] == std::numeric_limits<std::uint32_t>::max())
            continue;
        glm::vec3 pf;
        if (!toFloat(glm::dvec3(inst.transform *
                                glm::dvec4(pos[v * 3], pos[v * 3 + 1], pos[v * 3 + 2], 1.0)),
                     pf))
            return fail(where + ": a vertex position is not finite after the node transform");
        m_mesh.positions.push_back(pf);
        m_mesh.normals.push_back(
            hasNormal
                ? unitNormal(normalMatrix * glm::dvec3(nrm[v * 3], nrm[v * 3 + 1], nrm[v * 3 + 2]))
                : glm::vec3(0.0f));
        m_hasNormal.push_back(hasNormal ? 1 : 0);
        m_mesh.uvs.push_back(hasUv ? glm::vec2(uv[v * 2], uv[v * 2 + 1]) : glm::vec2(0.0f));
        glm::vec4 c(1.0f);
        if (hasColor)
            for (int k = 0; k < colComps; ++k)
                c[k] = col[v * static_cast<std::size_t>(colComps) + static_cast<std::size_t>(k)];
        m_mesh.colors.push_back(c);
    }
    m_anyUv = m_anyUv || hasUv;
    m_anyColor = m_anyColor || hasColor;

    int material = prim.material;
    if (material >= 0 && static_cast<std::size_t>(material) >= m_model.materials.size())
        return fail(where + " uses material " + str(material) + ", which does not exist");
    // Primitives without a material get the default one, appended after the file's.
    const auto matIndex =
        static_cast<std::uint32_t>(material >= 0 ? material : m_model.materials.size());
    for (std::size_t t = 0; t < tris.size(); t += 3) {
        const std::uint32_t a = base + remap[tris[t]];
        const std::uint32_t b = base + remap[tris[t + 1]];
        const std::uint32_t c = base + remap[tris[t + 2]];
        if (mirrored) // a mirroring transform flips the winding (glTF 2.0 §3.5.3)
            m_mesh.indices.insert(m_mesh.indices.end(), {a, c, b});
        else
            m_mesh.indices.insert(m_mesh.indices.end(), {a, b, c});
        m_mesh.triangleMaterial.push_back(matIndex);
    }
    return true;
}

int GltfFlattener::textureFor(int textureIndex, int texCoord, const std::string& materialName) {
    if (textureIndex < 0)
        return -1;
    if (static_cast<std::size_t>(textureIndex) >= m_model.textures.size()) {
        fail("material \"" + materialName + "\" uses texture " + str(textureIndex) +
             ", which does not exist");
        return -1;
    }
    if (texCoord != 0) {
        warnOnce("base color textures on texture coordinate sets other than 0 are ignored");
        return -1;
    }
    const int source = m_model.textures[static_cast<std::size_t>(textureIndex)].source;
    if (source < 0) {
        warnOnce("textures without a source image (or only an extension's image) are ignored");
        return -1;
    }
    if (static_cast<std::size_t>(source) >= m_model.images.size()) {
        fail("texture " + str(textureIndex) + " uses image " + str(source) +
             ", which does not exist");
        return -1;
    }
    if (const auto it = m_imageToTexture.find(source); it != m_imageToTexture.end())
        return it->second;

    const tinygltf::Image& img = m_model.images[static_cast<std::size_t>(source)];
    const std::string label = img.uri.empty() || img.uri.rfind("data:", 0) == 0
                                  ? "image " + str(source)
                                  : "image " + str(source) + " (" + img.uri + ")";
    const std::uint8_t* data = nullptr;
    std::uint64_t length = 0;
    if (img.bufferView >= 0) {
        if (!viewBytes(img.bufferView, label, data, length))
            return -1;
    } else if (const auto it = m_access.imageBytes.find(source); it != m_access.imageBytes.end()) {
        data = it->second.data();
        length = it->second.size();
    }
    int result = -1;
    if (data == nullptr || length == 0) {
        if (m_limits.requireTextures) {
            fail(label + " could not be read");
            return -1;
        }
        m_mesh.warnings.push_back(label + " could not be read; the material has no texture");
    } else {
        Result<Image> decoded =
            decodeImage(data, static_cast<std::size_t>(length), label, m_limits);
        if (decoded) {
            result = static_cast<int>(m_mesh.textures.size());
            m_mesh.textures.push_back(std::move(decoded).value());
        } else if (m_limits.requireTextures) {
            fail(decoded.error());
            return -1;
        } else {
            m_mesh.warnings.push_back(decoded.error() + "; the material has no texture");
        }
    }
    m_imageToTexture[source] = result;
    return result;
}

bool GltfFlattener::addMaterials() {
    const Json* jsonMaterials = nullptr;
    if (const auto it = m_json.find("materials"); it != m_json.end())
        jsonMaterials = &*it;
    for (std::size_t i = 0; i < m_model.materials.size(); ++i) {
        const tinygltf::Material& gm = m_model.materials[i];
        Material mat;
        mat.name = gm.name.empty() ? "material " + str(i) : gm.name;
        const auto& pbr = gm.pbrMetallicRoughness;
        if (pbr.baseColorFactor.size() == 4)
            for (int k = 0; k < 4; ++k)
                mat.baseColorFactor[k] =
                    static_cast<float>(pbr.baseColorFactor[static_cast<std::size_t>(k)]);
        int texIndex = pbr.baseColorTexture.index;
        int texCoord = pbr.baseColorTexture.texCoord;
        // KHR_materials_pbrSpecularGlossiness: its diffuse is the base color when the
        // metallic-roughness one is absent.
        if (jsonMaterials && i < jsonMaterials->size()) {
            const Json& jm = (*jsonMaterials)[i];
            const Json sg = jm.value("extensions", Json::object())
                                .value("KHR_materials_pbrSpecularGlossiness", Json::object());
            if (!jm.contains("pbrMetallicRoughness") && sg.is_object() && !sg.empty()) {
                const Json factor = sg.value("diffuseFactor", Json());
                if (factor.is_array() && factor.size() == 4)
                    for (int k = 0; k < 4; ++k)
                        if (factor[static_cast<std::size_t>(k)].is_number())
                            mat.baseColorFactor[k] =
                                factor[static_cast<std::size_t>(k)].get<float>();
                const Json tex = sg.value("diffuseTexture", Json());
                if (tex.is_object() && tex.contains("index") && tex["index"].is_number_unsigned() &&
                    tex["index"].get<std::uint64_t>() <= kMaxIndex) {
                    texIndex = tex["index"].get<int>();
                    const Json coord = tex.value("texCoord", Json(0));
                    texCoord = coord.is_number_unsigned() && coord.get<std::uint64_t>() <= kMaxIndex
                                   ? coord.get<int>()
                                   : -1;
                }
            }
            const Json bct = jm.value("pbrMetallicRoughness", Json::object())
                                 .value("baseColorTexture", Json::object());
            if (bct.is_object() && bct.contains("extensions") &&
                bct["extensions"].contains("KHR_texture_transform"))
                warnOnce("texture transforms (KHR_texture_transform) are ignored");
        }
        for (int k = 0; k < 4; ++k)
            if (!std::isfinite(mat.baseColorFactor[k]))
                mat.baseColorFactor[k] = 1.0f;
        mat.baseColorTexture = textureFor(texIndex, texCoord, mat.name);
        if (!m_error.message.empty())
            return false;
        m_mesh.materials.push_back(std::move(mat));
    }
    // The default material, for primitives without one.
    m_mesh.materials.push_back(Material{"default", glm::vec4(1.0f), -1});
    return true;
}

bool GltfFlattener::run(Mesh& out) {
    std::vector<Instance> instances;
    if (!collectInstances(instances))
        return false;
    std::size_t primTotal = 0, primDone = 0;
    for (const Instance& inst : instances)
        primTotal += m_model.meshes[static_cast<std::size_t>(inst.mesh)].primitives.size();
    for (const Instance& inst : instances) {
        const auto& prims = m_model.meshes[static_cast<std::size_t>(inst.mesh)].primitives;
        for (std::size_t p = 0; p < prims.size(); ++p) {
            if (!addPrimitive(inst, p))
                return false;
            ++primDone;
            if (!reportProgress(m_progress, 0.5 + 0.4 * static_cast<double>(primDone) /
                                                      static_cast<double>(primTotal)))
                return fail("cancelled", ErrorKind::Cancelled);
        }
    }
    if (m_skippedPrimitives > 0)
        m_mesh.warnings.push_back(str(m_skippedPrimitives) +
                                  " primitives of points or lines were skipped");
    if (m_mesh.indices.empty())
        return fail("the file contains no triangles");
    if (!addMaterials())
        return false;

    // The default material is only kept if used.
    const auto defaultIndex = static_cast<std::uint32_t>(m_mesh.materials.size() - 1);
    if (m_mesh.materials.size() > 1 &&
        std::find(m_mesh.triangleMaterial.begin(), m_mesh.triangleMaterial.end(), defaultIndex) ==
            m_mesh.triangleMaterial.end())
        m_mesh.materials.pop_back();

    if (!m_anyUv)
        m_mesh.uvs.clear();
    if (!m_anyColor)
        m_mesh.colors.clear();
    // Vertices of primitives without normals get normals computed from the triangles.
    const auto withNormal =
        static_cast<std::size_t>(std::count(m_hasNormal.begin(), m_hasNormal.end(), 1));
    if (withNormal == 0) {
        m_mesh.normals.clear(); // loadMesh computes them all
    } else if (withNormal < m_hasNormal.size()) {
        Mesh computed;
        computed.positions = m_mesh.positions;
        computed.indices = m_mesh.indices;
        computed.computeNormals();
        for (std::size_t i = 0; i < m_hasNormal.size(); ++i)
            if (!m_hasNormal[i])
                m_mesh.normals[i] = computed.normals[i];
    }
    out = std::move(m_mesh);
    return true;
}

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
    std::string ext = file.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext == ".glb";
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

Result<Mesh> load(const fs::path& file, const ProgressFn& progress, const LoadLimits& limits) {
    std::vector<std::uint8_t> bytes;
    {
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
        if (!in ||
            !in.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(size)))
            return Error{"cannot be read"};
    }
    if (!reportProgress(progress, 0.05))
        return cancelledError();

    const bool binary = glb::hasMagic(bytes);
    glb::Layout parts;
    if (binary) {
        Result<glb::Layout> layout = glb::readContainer(bytes);
        if (!layout)
            return layout.takeError();
        parts = *layout;
    } else {
        parts.jsonLength = bytes.size();
        parts.length = bytes.size();
    }
    const std::string_view jsonText(reinterpret_cast<const char*>(bytes.data()) + parts.jsonOffset,
                                    static_cast<std::size_t>(parts.jsonLength));
    // Neither the binary header nor text that starts like glTF's: another kind of file.
    if (!binary && !startsLikeJsonObject(jsonText))
        return Error{isGlbName(file)
                         ? "is not a glTF binary file (it does not start with the glTF header); "
                           "it may be damaged or another kind of file"
                         : "is not a glTF file (glTF text starts with “{”); it may be damaged or "
                           "another kind of file"};
    if (jsonNestingTooDeep(jsonText))
        return Error{"the glTF text is nested too deeply"};
    Json json;
    try {
        json = Json::parse(jsonText.begin(), jsonText.end());
    } catch (const Json::parse_error& e) {
        return Error{"is not a valid glTF file: " + describeParseError(e, jsonText)};
    } catch (const Json::exception&) {
        return Error{"is not a valid glTF file: its text cannot be read"};
    }
    if (std::string problem = SchemaCheck().run(json); !problem.empty())
        return Error{problem};
    if (std::string problem = checkImageViews(json); !problem.empty())
        return Error{problem};
    bool quantized = false;
    std::vector<std::string> warnings;
    if (std::string problem = checkExtensions(json, quantized, warnings); !problem.empty())
        return Error{problem};

    FileAccess access;
    access.folder = file.parent_path().string();
    access.maxBytes = limits.maxFileBytes;
    tinygltf::TinyGLTF loader;
    loader.SetFsCallbacks(tinygltf::FsCallbacks{&fileExists, &expandFilePath, &readWholeFile,
                                                &writeWholeFile, &access});
    loader.SetImageLoader(&collectImage, &access);
    tinygltf::Model model;
    std::string err, warn;
    bool ok = false;
    if (binary)
        ok = loader.LoadBinaryFromMemory(&model, &err, &warn, bytes.data(),
                                         static_cast<unsigned int>(parts.length), access.folder);
    else
        ok = loader.LoadASCIIFromString(&model, &err, &warn,
                                        reinterpret_cast<const char*>(bytes.data()),
                                        static_cast<unsigned int>(bytes.size()), access.folder);
    if (!access.violation.empty())
        return Error{access.violation};
    if (!ok)
        return Error{err.empty() ? std::string("is not a valid glTF file") : oneLine(err)};
    bytes.clear();
    bytes.shrink_to_fit();
    if (!reportProgress(progress, 0.5))
        return cancelledError();

    Mesh mesh;
    GltfFlattener flattener(model, json, access, quantized, progress, limits);
    if (!flattener.run(mesh))
        return flattener.error();
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
    try {
        return load(file, progress, limits);
    } catch (const std::bad_alloc&) {
        return Error{"not enough memory to load the file"};
    } catch (const std::exception& e) {
        return Error{std::string("cannot be loaded (") + e.what() + ")"};
    } catch (...) {
        return Error{"cannot be loaded (unexpected error)"};
    }
}

} // namespace core::detail
