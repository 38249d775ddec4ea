// SPDX-License-Identifier: GPL-3.0-or-later
// glTF component types and attribute rules (see gltf_accessors.h).
#include "core/io/gltf/gltf_accessors.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include <glm/geometric.hpp>

namespace core::detail::gltf {

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

const char* semanticName(Semantic s) {
    switch (s) {
    case Semantic::Position:
        return "POSITION";
    case Semantic::Normal:
        return "NORMAL";
    case Semantic::Tangent:
        return "TANGENT";
    case Semantic::TexCoord:
        return "TEXCOORD_0";
    case Semantic::Color:
        return "COLOR_0";
    case Semantic::Indices:
        return "indices";
    }
    return "";
}

bool typeAllowed(Semantic s, int type) {
    switch (s) {
    case Semantic::Position:
    case Semantic::Normal:
        return type == TINYGLTF_TYPE_VEC3;
    case Semantic::Tangent:
        return type == TINYGLTF_TYPE_VEC4;
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
    case Semantic::Tangent:
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

} // namespace core::detail::gltf
