// SPDX-License-Identifier: GPL-3.0-or-later
// Writes the committed compressed glTF files that GltfCompression.CommittedFilesLoadOrFail
// (tests/core/io/gltf_compression_test.cpp) checks and that scripts/fuzz.sh seeds from: the 5 × 5
// grid with Draco and with meshoptimizer, a truncated Draco file and a meshoptimizer file whose
// index view claims 6 indices too many. Usage: make_gltf_compression_data DATA_FOLDER (tests/data);
// scripts/make-gltf-compression-data.sh builds and runs it.
#include <cstdio>
#include <filesystem>

#include "tests/core/io/gltf_files.h"

namespace gf = core_test::gltf_files;

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: make_gltf_compression_data DATA_FOLDER\n");
        return 2;
    }
    const std::filesystem::path data = argv[1];
    const gf::Grid g = gf::makeGrid(5);
    const bool written = gf::writeDraco(g, data / "gltf/grid-draco.glb") &&
                         gf::writeMeshopt(g, data / "gltf/grid-meshopt.glb") &&
                         gf::writeDraco(g, data / "crashers/glb-draco-truncated.glb", 30) &&
                         gf::writeMeshopt(g, data / "crashers/glb-meshopt-wrong-count.glb", 6);
    if (!written) {
        std::fprintf(stderr, "make_gltf_compression_data: could not write into %s\n", argv[1]);
        return 1;
    }
    return 0;
}
