// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target for the model loaders (core::loadMesh: tinygltf + our checks for glTF, Assimp
// for the rest). The first byte picks the format, the rest is the file. Any crash, sanitizer
// report or abort is a bug: a bad file must give an Error, never more.
#include <cstddef>
#include <cstdint>

#include "tests/fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size < 1)
        return 0;
    static const char* const kExtensions[] = {".glb", ".gltf", ".obj", ".ply", ".stl", ".off"};
    const char* extension = kExtensions[data[0] % (sizeof kExtensions / sizeof *kExtensions)];
    const std::string path = fuzz::writeInput(data + 1, size - 1, extension);
    core::Result<core::Mesh> mesh = core::loadMesh(path, {}, fuzz::limits());
    if (mesh && !mesh->validate().empty())
        __builtin_trap(); // loadMesh promises a valid mesh
    return 0;
}
