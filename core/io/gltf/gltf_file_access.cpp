// SPDX-License-Identifier: GPL-3.0-or-later
// tinygltf's file callbacks, confined to the model's folder (see gltf_file_access.h).
#include "core/io/gltf/gltf_file_access.h"

#include <filesystem>
#include <fstream>
#include <system_error>

namespace core::detail::gltf {

namespace {

namespace fs = std::filesystem;

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

} // namespace

tinygltf::FsCallbacks confinedFileCallbacks(FileAccess& access) {
    return tinygltf::FsCallbacks{&fileExists, &expandFilePath, &readWholeFile, &writeWholeFile,
                                 &access};
}

bool collectImage(tinygltf::Image* image, int index, std::string*, std::string*, int, int,
                  const unsigned char* bytes, int size, void* user) {
    auto& access = *static_cast<FileAccess*>(user);
    if (image->bufferView < 0 && bytes != nullptr && size > 0)
        access.imageBytes[index].assign(bytes, bytes + size);
    return true;
}

} // namespace core::detail::gltf
