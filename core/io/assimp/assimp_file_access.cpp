// SPDX-License-Identifier: GPL-3.0-or-later
// Assimp's file access confined to the model's folder (see assimp_file_access.h).
#include "core/io/assimp/assimp_file_access.h"

#include <fstream>
#include <system_error>

namespace core::detail::assimp {

namespace fs = std::filesystem;

namespace {

bool isInside(const fs::path& p, const fs::path& folder) {
    const std::string s = p.string(), f = folder.string();
    const std::string prefix = f == "/" ? f : f + "/";
    return s.size() > prefix.size() && s.compare(0, prefix.size(), prefix) == 0;
}

} // namespace

fs::path confine(const fs::path& requested, const fs::path& folder, bool* outside) {
    const fs::path abs =
        (requested.is_absolute() ? requested : folder / requested).lexically_normal();
    if (!isInside(abs, folder)) {
        if (outside)
            *outside = true;
        return {};
    }
    std::error_code ec;
    const fs::path real = fs::weakly_canonical(abs, ec);
    if (ec)
        return {};
    if (!isInside(real, folder)) {
        if (outside)
            *outside = true;
        return {};
    }
    return real;
}

bool readFile(const fs::path& p, std::uint64_t maxBytes, std::vector<std::uint8_t>& out) {
    std::error_code ec;
    const std::uintmax_t size = fs::file_size(p, ec);
    if (ec || size == 0 || size > maxBytes)
        return false;
    std::ifstream in(p, std::ios::binary);
    out.resize(static_cast<std::size_t>(size));
    return in && in.read(reinterpret_cast<char*>(out.data()), static_cast<std::streamsize>(size));
}

} // namespace core::detail::assimp
