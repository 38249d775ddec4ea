// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/io/gltf/gltf_write_back_geometry.h"

#include <algorithm>
#include <cstring>
#include <limits>
#include <string>

namespace core::detail::gltf {

using Json = nlohmann::json;

namespace {

constexpr int kFloat = 5126;

std::size_t componentBytes(int componentType) {
    switch (componentType) {
    case 5120:
    case 5121:
        return 1;
    case 5122:
    case 5123:
        return 2;
    case 5125:
    case kFloat:
        return 4;
    default:
        return 0;
    }
}

std::size_t componentCount(const std::string& type) {
    if (type == "SCALAR")
        return 1;
    if (type == "VEC2")
        return 2;
    if (type == "VEC3")
        return 3;
    if (type == "VEC4" || type == "MAT2")
        return 4;
    if (type == "MAT3")
        return 9;
    if (type == "MAT4")
        return 16;
    return 0;
}

/** Component c of element i as stored. */
double componentAt(const GatheredAccessor& g, int componentType, std::size_t i, std::size_t c) {
    const std::uint8_t* p =
        g.bytes.data() + i * std::size_t(g.stride) + c * componentBytes(componentType);
    switch (componentType) {
    case 5120:
        return double(std::int8_t(*p));
    case 5121:
        return double(*p);
    case 5122: {
        std::int16_t v;
        std::memcpy(&v, p, 2);
        return v;
    }
    case 5123: {
        std::uint16_t v;
        std::memcpy(&v, p, 2);
        return v;
    }
    case 5125: {
        std::uint32_t v;
        std::memcpy(&v, p, 4);
        return v;
    }
    default: {
        float v;
        std::memcpy(&v, p, 4);
        return v;
    }
    }
}

/** The min and max of the gathered elements, per component, as stored. */
void bounds(const GatheredAccessor& g, int componentType, std::size_t count, std::size_t components,
            Json& accessor) {
    Json lo = Json::array(), hi = Json::array();
    for (std::size_t c = 0; c < components; ++c) {
        double a = std::numeric_limits<double>::max(), b = std::numeric_limits<double>::lowest();
        for (std::size_t i = 0; i < count; ++i) {
            a = std::min(a, componentAt(g, componentType, i, c));
            b = std::max(b, componentAt(g, componentType, i, c));
        }
        if (componentType == kFloat) {
            lo.push_back(float(a));
            hi.push_back(float(b));
        } else {
            lo.push_back(std::int64_t(a));
            hi.push_back(std::int64_t(b));
        }
    }
    accessor["min"] = std::move(lo);
    accessor["max"] = std::move(hi);
}

} // namespace

Result<GatheredAccessor> gatherAccessor(const Json& root, std::span<const std::uint8_t> bin,
                                        std::size_t accessor,
                                        std::span<const std::uint32_t> elements) {
    const Json& a = root.at("accessors").at(accessor);
    if (a.contains("sparse"))
        return Error{"accessor " + std::to_string(accessor) + " is sparse"};
    const int componentType = a.at("componentType").get<int>();
    const std::size_t components = componentCount(a.at("type").get<std::string>());
    const std::size_t element = componentBytes(componentType) * components;
    if (element == 0)
        return Error{"accessor " + std::to_string(accessor) + " has an unknown type"};
    const auto count = a.at("count").get<std::uint64_t>();

    GatheredAccessor g;
    g.stride = int((element + 3) & ~std::size_t{3});
    g.bytes.assign(elements.size() * std::size_t(g.stride), 0);
    if (a.contains("bufferView")) {
        const Json& view = root.at("bufferViews").at(a["bufferView"].get<std::size_t>());
        const auto viewStart = view.value("byteOffset", std::uint64_t{0});
        const auto viewEnd = viewStart + view.at("byteLength").get<std::uint64_t>();
        const auto stride = view.value("byteStride", std::uint64_t{element});
        const auto base = viewStart + a.value("byteOffset", std::uint64_t{0});
        for (std::size_t i = 0; i < elements.size(); ++i) {
            const std::uint64_t at = base + std::uint64_t(elements[i]) * stride;
            if (elements[i] >= count || at + element > viewEnd || at + element > bin.size())
                return Error{"accessor " + std::to_string(accessor) + " is read out of range"};
            std::memcpy(g.bytes.data() + i * std::size_t(g.stride), bin.data() + at, element);
        }
    }
    g.accessor = a;
    for (const char* key : {"bufferView", "byteOffset", "min", "max", "name"})
        g.accessor.erase(key);
    g.accessor["count"] = elements.size();
    if ((a.contains("min") || a.contains("max")) && !elements.empty())
        bounds(g, componentType, elements.size(), components, g.accessor);
    return g;
}

} // namespace core::detail::gltf
