// SPDX-License-Identifier: GPL-3.0-or-later
// Confined file access for tinygltf: its file callbacks open only files inside the model's folder
// (a URI that tries to leave it fails the whole load), never expand paths and never write; image
// bytes read from URIs are only collected, to be decoded when a material needs them.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <tiny_gltf.h>

namespace core::detail::gltf {

struct FileAccess {
    std::string folder; // canonical, no trailing slash
    std::uint64_t maxBytes = 0;
    std::string violation; // the first URI that tried to leave the folder
    std::map<int, std::vector<std::uint8_t>> imageBytes; // encoded images loaded from URIs
};

/** tinygltf's file callbacks confined to access.folder (access is their user data). */
tinygltf::FsCallbacks confinedFileCallbacks(FileAccess& access);

/**
 * tinygltf's image loader (user data: a FileAccess): collects the bytes of images read from URIs
 * (data: or files) into imageBytes; decoding waits until a material needs the image. Images in
 * buffer views are left alone: tinygltf computes their pointer before anything checked the
 * view's bounds.
 */
bool collectImage(tinygltf::Image* image, int index, std::string*, std::string*, int, int,
                  const unsigned char* bytes, int size, void* user);

} // namespace core::detail::gltf
