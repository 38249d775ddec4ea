// SPDX-License-Identifier: GPL-3.0-or-later
// Assimp's file access confined to the model's folder: Assimp opens files only inside it and
// within the size limit; a reference outside it (mtllib ../x.mtl) is not read and is remembered
// for a warning. Texture paths are resolved the same way.
#pragma once

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include <assimp/DefaultIOSystem.h>

namespace core::detail::assimp {

/**
 * A path inside `folder` (after resolving "..", relative paths and symbolic links), or empty.
 * `outside` is set when the path leads outside the folder.
 */
std::filesystem::path confine(const std::filesystem::path& requested,
                              const std::filesystem::path& folder, bool* outside = nullptr);

/** The whole file p, if it is not empty and at most maxBytes long. */
bool readFile(const std::filesystem::path& p, std::uint64_t maxBytes,
              std::vector<std::uint8_t>& out);

/** Assimp's file access, confined to the model's folder and to the size limit. */
class FolderIOSystem : public Assimp::DefaultIOSystem {
public:
    FolderIOSystem(std::filesystem::path folder, std::uint64_t maxBytes)
        : m_folder(std::move(folder)), m_maxBytes(maxBytes) {}

    bool Exists(const char* file) const override {
        const std::filesystem::path p = allowed(file);
        std::error_code ec;
        return !p.empty() && std::filesystem::is_regular_file(p, ec);
    }
    Assimp::IOStream* Open(const char* file, const char* mode) override {
        if (mode == nullptr || std::strchr(mode, 'w') || std::strchr(mode, 'a') ||
            std::strchr(mode, '+'))
            return nullptr; // loading never writes
        const std::filesystem::path p = allowed(file);
        std::error_code ec;
        if (p.empty() || !std::filesystem::is_regular_file(p, ec))
            return nullptr;
        const std::uintmax_t size = std::filesystem::file_size(p, ec);
        if (ec || size > m_maxBytes)
            return nullptr;
        return DefaultIOSystem::Open(p.string().c_str(), mode);
    }
    const std::string& rejected() const { return m_rejected; }

private:
    std::filesystem::path allowed(const char* file) const {
        if (file == nullptr || *file == '\0')
            return {};
        bool outside = false;
        std::filesystem::path p = confine(std::filesystem::path(file), m_folder, &outside);
        if (outside && m_rejected.empty())
            m_rejected = file;
        return p;
    }

    std::filesystem::path m_folder;
    std::uint64_t m_maxBytes;
    mutable std::string m_rejected; // the first file outside the folder Assimp asked for
};

} // namespace core::detail::assimp
