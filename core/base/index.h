// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstdint>

namespace core {

/** No index: no fragment, connection, region, neighbouring triangle or chart. */
inline constexpr std::uint32_t kNone = 0xffffffffu;

} // namespace core
