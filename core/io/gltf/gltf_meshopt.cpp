// SPDX-License-Identifier: GPL-3.0-or-later
// EXT_meshopt_compression decoding (see gltf_meshopt.h).
#include "core/io/gltf/gltf_meshopt.h"

#include <cstdint>
#include <string>
#include <vector>

#include <meshoptimizer.h>

#include "core/io/gltf/gltf_accessors.h"

namespace core::detail::gltf {

namespace {

using Json = nlohmann::json;

constexpr const char* kExtensions[] = {"EXT_meshopt_compression", "KHR_meshopt_compression"};

/** The view's or buffer's meshopt extension object, or nullptr. */
const Json* meshoptExtension(const Json& object, const char*& name) {
    const auto ext = object.find("extensions");
    if (ext == object.end() || !ext->is_object())
        return nullptr;
    for (const char* n : kExtensions)
        if (const auto it = ext->find(n); it != ext->end() && it->is_object()) {
            name = n;
            return &*it;
        }
    return nullptr;
}

bool uintField(const Json& o, const char* key, std::uint64_t& out, bool required,
               std::uint64_t fallback = 0) {
    const auto it = o.find(key);
    if (it == o.end()) {
        out = fallback;
        return !required;
    }
    if (!it->is_number_unsigned() && !(it->is_number_integer() && it->get<std::int64_t>() >= 0))
        return false;
    out = it->get<std::uint64_t>();
    return out <= kMaxByteSize;
}

} // namespace

bool replaceFallbackBuffers(Json& json) {
    const auto buffers = json.find("buffers");
    if (buffers == json.end() || !buffers->is_array())
        return false;
    bool changed = false;
    for (Json& buffer : *buffers) {
        const char* name = nullptr;
        const Json* ext = buffer.is_object() ? meshoptExtension(buffer, name) : nullptr;
        if (ext == nullptr || !ext->value("fallback", false) || buffer.contains("uri"))
            continue;
        buffer["byteLength"] = 1;
        buffer["uri"] = "data:application/octet-stream;base64,AA==";
        changed = true;
    }
    return changed;
}

Status decodeMeshoptViews(tinygltf::Model& model, const Json& json, const LoadLimits& limits) {
    const auto views = json.find("bufferViews");
    if (views == json.end())
        return {};
    for (std::size_t i = 0; i < views->size() && i < model.bufferViews.size(); ++i) {
        const char* name = nullptr;
        const Json* ext = meshoptExtension((*views)[i], name);
        if (ext == nullptr)
            continue;
        const std::string where = "buffer view " + str(i) + " (" + name + ")";
        std::uint64_t buffer = 0, offset = 0, length = 0, stride = 0, count = 0;
        if (!uintField(*ext, "buffer", buffer, true) ||
            !uintField(*ext, "byteOffset", offset, false) ||
            !uintField(*ext, "byteLength", length, true) ||
            !uintField(*ext, "byteStride", stride, true) || !uintField(*ext, "count", count, true))
            return badInput(where +
                            " needs buffer, byteLength, byteStride and count as non-negative "
                            "integers");
        const std::string mode = ext->value("mode", Json()).is_string()
                                     ? (*ext)["mode"].get<std::string>()
                                     : std::string();
        const Json filterJson = ext->value("filter", Json("NONE"));
        const std::string filter =
            filterJson.is_string() ? filterJson.get<std::string>() : std::string("?");

        if (buffer >= model.buffers.size())
            return badInput(where + " uses buffer " + str(buffer) + ", which does not exist");
        const std::vector<unsigned char>& source = model.buffers[buffer].data;
        std::uint64_t end = 0;
        if (addOverflows(offset, length, end) || end > source.size())
            return badInput(where + " reaches past the end of buffer " + str(buffer) + " (" +
                            str(source.size()) + " bytes)");

        const bool attributes = mode == "ATTRIBUTES";
        if (!attributes && mode != "TRIANGLES" && mode != "INDICES")
            return badInput(where + " has an invalid mode");
        if (attributes ? (stride == 0 || stride > 256 || stride % 4 != 0)
                       : (stride != 2 && stride != 4))
            return badInput(where + " has an invalid byteStride " + str(stride) + " for mode " +
                            mode);
        const std::uint64_t cap = attributes ? limits.maxVertices : limits.maxTriangles * 3 + 2;
        if (count == 0 || count > cap)
            return badInput(where + " has an invalid count " + str(count));
        if (mode == "TRIANGLES" && count % 3 != 0)
            return badInput(where + " has a count " + str(count) + " that is not a multiple of 3");
        if (filter != "NONE" && !attributes)
            return badInput(where + " has a filter on indices");
        if ((filter == "OCTAHEDRAL" && stride != 4 && stride != 8) ||
            (filter == "QUATERNION" && stride != 8) || (filter == "EXPONENTIAL" && stride % 4))
            return badInput(where + " has a byteStride " + str(stride) + " the filter " + filter +
                            " does not allow");
        if (filter != "NONE" && filter != "OCTAHEDRAL" && filter != "QUATERNION" &&
            filter != "EXPONENTIAL")
            return badInput(where + " has an unsupported filter");

        tinygltf::BufferView& view = model.bufferViews[i];
        std::uint64_t decodedSize = 0;
        if (mulOverflows(count, stride, decodedSize) || decodedSize != view.byteLength)
            return badInput(where + " decodes to " + str(count) + " × " + str(stride) +
                            " bytes, but the view's byteLength is " + str(view.byteLength));
        if (view.byteStride != 0 && attributes && view.byteStride != stride)
            return badInput(where + " has a byteStride other than the view's");

        tinygltf::Buffer decoded;
        decoded.data.resize(static_cast<std::size_t>(decodedSize));
        const unsigned char* src = source.data() + offset;
        const auto n = static_cast<std::size_t>(count);
        const auto s = static_cast<std::size_t>(stride);
        const auto len = static_cast<std::size_t>(length);
        int rc = 0;
        if (attributes)
            rc = meshopt_decodeVertexBuffer(decoded.data.data(), n, s, src, len);
        else if (mode == "TRIANGLES")
            rc = meshopt_decodeIndexBuffer(decoded.data.data(), n, s, src, len);
        else
            rc = meshopt_decodeIndexSequence(decoded.data.data(), n, s, src, len);
        if (rc != 0)
            return badInput(where +
                            " cannot be decoded (the compressed data is malformed or cut off)");
        if (filter == "OCTAHEDRAL")
            meshopt_decodeFilterOct(decoded.data.data(), n, s);
        else if (filter == "QUATERNION")
            meshopt_decodeFilterQuat(decoded.data.data(), n, s);
        else if (filter == "EXPONENTIAL")
            meshopt_decodeFilterExp(decoded.data.data(), n, s);

        model.buffers.push_back(std::move(decoded));
        view.buffer = static_cast<int>(model.buffers.size() - 1);
        view.byteOffset = 0;
    }
    return {};
}

} // namespace core::detail::gltf
