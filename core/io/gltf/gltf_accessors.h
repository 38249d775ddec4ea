// SPDX-License-Identifier: GPL-3.0-or-later
// glTF accessor data: the component types and their sizes and names, the types and components
// glTF 2.0 (and KHR_mesh_quantization) allows per attribute, reading one component, and the
// overflow-checked arithmetic every count, offset and stride of a glTF file goes through.
#pragma once

#include <cstdint>
#include <limits>
#include <string>

#include <glm/vec3.hpp>
#include <tiny_gltf.h>

namespace core::detail::gltf {

constexpr std::uint64_t kMaxIndex = std::numeric_limits<std::int32_t>::max();
constexpr std::uint64_t kMaxByteSize = std::numeric_limits<std::uint32_t>::max();

constexpr int kByte = TINYGLTF_COMPONENT_TYPE_BYTE;
constexpr int kUByte = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
constexpr int kShort = TINYGLTF_COMPONENT_TYPE_SHORT;
constexpr int kUShort = TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
constexpr int kUInt = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
constexpr int kFloat = TINYGLTF_COMPONENT_TYPE_FLOAT;

inline std::string str(std::uint64_t v) {
    return std::to_string(v);
}

inline bool addOverflows(std::uint64_t a, std::uint64_t b, std::uint64_t& out) {
    return __builtin_add_overflow(a, b, &out);
}
inline bool mulOverflows(std::uint64_t a, std::uint64_t b, std::uint64_t& out) {
    return __builtin_mul_overflow(a, b, &out);
}

/** Bytes of one component of componentType; 0 for an unknown type. */
int componentSize(int componentType);
/** Components of an accessor type (SCALAR 1 ... MAT4 16); 0 for an unknown type. */
int componentCount(int type);
/** "SCALAR", "VEC2", ... for messages. */
const char* typeName(int type);
/** "unsigned short", "normalized byte", ... for messages. */
std::string componentName(int componentType, bool normalized);
/** One component as a number; normalized integers map to [0, 1] or [-1, 1] (glTF 2.0 §3.11). */
double readComponent(const std::uint8_t* p, int componentType, bool normalized);

/** What an accessor is read for. */
enum class Semantic { Position, Normal, Tangent, TexCoord, Color, Indices };

const char* semanticName(Semantic s);
/** The accessor types glTF 2.0 allows per semantic, widened by KHR_mesh_quantization. */
bool typeAllowed(Semantic s, int type);
/** The component types glTF 2.0 allows per semantic (quantized: KHR_mesh_quantization). */
bool componentAllowed(Semantic s, int ct, bool normalized, bool quantized);

} // namespace core::detail::gltf
