// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target for the model loaders as the importer process runs them
// (core::loadMeshInProcess: tinygltf + our checks for glTF, Assimp for the rest). The first byte
// picks the format, the rest is the file. Any crash, sanitizer report or abort is a bug: a bad
// file must give an Error, never more. Inputs of the regression corpus are skipped (see
// fuzz::isKnownCrasher): they crash third-party parsers, which the importer process contains.
#include <cstddef>
#include <cstdint>

#include "core/io/importer/mesh_io_in_process.h"
#include "tests/fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size < 1)
        return 0;
    static const char* const kExtensions[] = {".glb", ".gltf", ".obj", ".ply", ".stl", ".off"};
    const char* extension = kExtensions[data[0] % (sizeof kExtensions / sizeof *kExtensions)];
    if (fuzz::isKnownCrasher(extension, data + 1, size - 1))
        return 0;
    const std::string path = fuzz::writeInput(data + 1, size - 1, extension);
    core::Result<core::Mesh> mesh = core::loadMeshInProcess(path, {}, fuzz::limits());
    if (mesh && !mesh->validate().ok())
        __builtin_trap(); // the loader promises a valid mesh
    return 0;
}
