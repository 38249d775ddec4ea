// SPDX-License-Identifier: GPL-3.0-or-later
// core/io/image/: images decoded, encoded and written (OpenImageIO, in a module).
//
// The image codecs (decoding, encoding, writing through OpenImageIO) are a module of their own,
// layerpaint-image-codecs.so, that a program loads on its first use of an image: OpenImageIO
// brings some 260 shared libraries, and linking them took about half a second of every start of
// every program that was linked with it. Found like the importer program: the path in
// LAYERPAINT_IMAGE_CODECS, else beside the running program, else in ../libexec/layerpaint/.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "core/base/progress.h"
#include "core/base/result.h"
#include "core/io/image/image_write.h"
#include "core/io/mesh_io.h"
#include "core/model/mesh.h"

namespace core {

/** Pixels to encode in memory, as the encoder takes them (see encodeImage()). */
struct EncodeRequest {
    const void* pixels = nullptr; // width × height × 4 values of `type`, rows top first
    int width = 0, height = 0;
    int channels = 4;                  // the first 3 or all 4 of each pixel's values go in
    PixelType type = PixelType::UInt8; // UInt8, UInt16 or Float32
    bool halfFloat = false;            // Float32 stored as 16-bit floats
    const char* format = "png";        // OpenImageIO's name: png, tiff, openexr
    const char* extension = ".png";
    const char* colorSpace = nullptr; // the oiio:ColorSpace attribute, if any
    bool straightAlpha = true;        // alpha not multiplied into the colour
    bool zip = false;                 // zip compression (TIFF, EXR)
};

/** What the module offers; built with the same compiler and library as its callers. */
struct ImageCodecs {
    /** Bytes of a `format` image ("png", "jpeg", ...; see image_io.cpp) to RGBA8. */
    Result<Image> (*decode)(const std::uint8_t* data, std::size_t size, const std::string& label,
                            const std::string& format, const LoadLimits& limits);
    Result<std::vector<std::uint8_t>> (*encode)(const EncodeRequest& request,
                                                const ProgressFn& progress);
    Status (*write)(const std::string& path, int width, int height, int channels, PixelType type,
                    const void* pixels);
};

/** The module's entry point. */
extern "C" const ImageCodecs* layerpaint_image_codecs();

/** Where the module is, or where it was looked for. */
Result<std::string> findImageCodecs();

/** The codecs, loaded on the first call (thread-safe); or why they cannot be loaded. */
Result<const ImageCodecs*> imageCodecs();

} // namespace core
