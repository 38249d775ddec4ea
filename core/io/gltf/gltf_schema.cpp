// SPDX-License-Identifier: GPL-3.0-or-later
// The glTF JSON checks made before tinygltf parses (see gltf_schema.h).
#include "core/io/gltf/gltf_schema.h"

#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <set>
#include <string_view>

#include "core/io/gltf/gltf_accessors.h"

namespace core::detail::gltf {

namespace {

using Json = nlohmann::json;

/** The types the glTF 2.0 schema gives the properties; the first violation is reported. */
class SchemaCheck {
public:
    Status run(const Json& root) {
        checkRoot(root);
        if (m_error.empty())
            return {};
        return Error{m_error, ErrorKind::BadInput};
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

    /** o's key, or nullptr where o has none (reported as missing when required). */
    const Json* find(const Json& o, const char* key, const std::string& where, bool required) {
        const auto it = o.find(key);
        if (it != o.end())
            return &*it;
        if (required)
            fail(at(where, key) + " is missing");
        return nullptr;
    }

    void uintProp(const Json& o, const char* key, const std::string& where, bool required,
                  std::uint64_t max = kMaxIndex, std::uint64_t min = 0) {
        const Json* it = find(o, key, where, required);
        if (!it)
            return;
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
        const Json* it = find(o, key, where, required);
        if (it && !it->is_string())
            fail(at(where, key) + " must be a string");
    }
    void boolProp(const Json& o, const char* key, const std::string& where) {
        const auto it = o.find(key);
        if (it != o.end() && !it->is_boolean())
            fail(at(where, key) + " must be true or false");
    }
    void numberArray(const Json& o, const char* key, const std::string& where, std::size_t minN,
                     std::size_t maxN) {
        const Json* it = find(o, key, where, false);
        if (!it)
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
        const Json* it = find(o, key, where, false);
        if (!it)
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
        const Json* it = find(o, key, where, required);
        if (!it)
            return;
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
        if (const Json* it = find(o, key, where, required))
            (this->*fn)(*it, at(where, key));
    }
    void arrayOf(const Json& o, const char* key, const std::string& where, Fn fn,
                 bool required = false) {
        const Json* it = find(o, key, where, required);
        if (!it)
            return;
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

} // namespace

Status checkSchema(const Json& root) {
    return SchemaCheck().run(root);
}

Status checkImageViews(const Json& root) {
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
            return Error{"image " + str(i) + " uses buffer view " + str(v) +
                             ", which does not exist",
                         ErrorKind::BadInput};
        const Json& view = (*views)[v];
        const auto b = view["buffer"].get<std::uint64_t>();
        if (b >= bufferCount)
            return Error{"buffer view " + str(v) + " uses buffer " + str(b) +
                             ", which does not exist",
                         ErrorKind::BadInput};
        const std::uint64_t offset = view.value("byteOffset", std::uint64_t{0});
        const auto length = view["byteLength"].get<std::uint64_t>();
        const auto bufferLength = (*buffers)[b]["byteLength"].get<std::uint64_t>();
        std::uint64_t end = 0;
        if (addOverflows(offset, length, end) || end > bufferLength)
            return Error{"buffer view " + str(v) + " reaches past the end of buffer " + str(b) +
                             " (" + str(bufferLength) + " bytes)",
                         ErrorKind::BadInput};
    }
    return {};
}

Result<Extensions> checkExtensions(const Json& root) {
    Extensions found;
    bool& quantized = found.quantized;
    std::vector<std::string>& warnings = found.warnings;
    static const std::set<std::string> ignorable = {"KHR_materials_pbrSpecularGlossiness",
                                                    "KHR_materials_unlit",
                                                    "KHR_technique_webgl",
                                                    "KHR_lights_punctual",
                                                    "KHR_materials_emissive_strength",
                                                    "KHR_materials_variants",
                                                    "KHR_xmp_json_ld"};
    static const std::set<std::string> decoded = {
        "KHR_draco_mesh_compression", "EXT_meshopt_compression", "KHR_meshopt_compression",
        "KHR_texture_transform"};
    quantized = false;
    for (const Json& e : root.value("extensionsUsed", Json::array())) {
        if (e.get<std::string>() == "KHR_mesh_quantization")
            quantized = true;
        if (e == "EXT_meshopt_compression" || e == "KHR_meshopt_compression")
            found.meshopt = true;
    }
    for (const Json& e : root.value("extensionsRequired", Json::array())) {
        const std::string ext = e.get<std::string>();
        if (ext == "KHR_mesh_quantization") {
            quantized = true;
        } else if (decoded.count(ext)) {
            // decoded while loading (gltf_meshopt, gltf_draco, gltf_texture_transform)
        } else if (ignorable.count(ext) || ext.rfind("KHR_materials_", 0) == 0) {
            warnings.push_back("the required extension " + ext + " is ignored");
        } else {
            return Error{"the file requires the unsupported glTF extension " + ext,
                         ErrorKind::Unsupported};
        }
    }
    return found;
}

} // namespace core::detail::gltf
