// SPDX-License-Identifier: GPL-3.0-or-later
// How much processor time the importer may spend on a file: scaled with what the load reads, so
// that a parser hanging on a few hundred bytes is stopped within seconds while a large or
// texture-heavy model has the time it needs (docs/security.md, "The importer's sandbox").
#pragma once

#include <cstdint>
#include <filesystem>

namespace core::detail {

/** What the importer is asked to read. */
enum class ImportKind {
    Model, // a model (and what it names beside it)
    Image, // one image file
};

/** What a load reads, roughly: bytes of the file and of the companion files found beside it. */
struct ImportInput {
    std::uint64_t bytes = 0;  // the file and its companion files
    std::uint32_t images = 0; // images among them, and images a glTF keeps in its buffers
};

/**
 * The file's bytes plus, for formats that name other files, those that exist inside the model's
 * folder: an OBJ's MTL files and their texture maps, a glTF's external buffers and images (a
 * .glb's JSON is read for the images in its buffers). A rough estimate that reads at most a few
 * MiB of text and counts at most a few hundred files; a file that cannot be read counts 0 bytes.
 */
ImportInput estimateImportInput(const std::filesystem::path& file,
                                ImportKind kind = ImportKind::Model);

/**
 * Processor seconds for input: kImportBaseSeconds, plus kImportSecondsPerMiB for every MiB and
 * kImportSecondsPerImage for every image (a decoder's time follows the pixels, not the bytes).
 */
double importProcessorSeconds(const ImportInput& input);

/**
 * The wall-clock deadline for a processor-time limit: a multiple with a margin, so that a parser
 * that spins is stopped by its processor time (the clearer message) even on a busy machine,
 * while one that blocks still meets the deadline.
 */
double importWallSeconds(double processorSeconds);

// Measured on the importer (docs/security.md, "The importer's sandbox"): a tiny model with one
// texture (the image codecs' first load) takes 0.6 s, the slowest reader 0.11 s per MiB
// (a binary PLY through Assimp), an 8192² PNG 3.6 s to decode whatever its compressed size.
inline constexpr double kImportBaseSeconds = 2.0;
inline constexpr double kImportSecondsPerMiB = 0.5;
inline constexpr double kImportSecondsPerImage = 5.0;

} // namespace core::detail
