// SPDX-License-Identifier: GPL-3.0-or-later
// Accessors of a kept glTF scene gathered anew, for primitives whose vertices an automatic UV
// layout copied along its seams (gltf_write_back.cpp).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/base/result.h"

namespace core::detail::gltf {

/** An accessor's elements at some indices: its JSON (no buffer view yet) and bytes. */
struct GatheredAccessor {
    nlohmann::json accessor;
    std::vector<std::uint8_t> bytes;
    int stride = 0; // bytes per element, a multiple of 4 as vertex attributes need
};

/**
 * Accessor `accessor` of root (a SourceScene's JSON, its views into bin) at elements, in that
 * order, packed with a 4-byte aligned stride; a POSITION's min and max are those of the elements.
 * An Error for a sparse accessor, a type glTF does not know, or elements or views out of range.
 */
Result<GatheredAccessor> gatherAccessor(const nlohmann::json& root,
                                        std::span<const std::uint8_t> bin, std::size_t accessor,
                                        std::span<const std::uint32_t> elements);

} // namespace core::detail::gltf
