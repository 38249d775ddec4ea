// SPDX-License-Identifier: GPL-3.0-or-later
// Images encoded in memory (see image_encode.h) by the image codecs module (image_codecs.h).
#include "core/io/image/image_encode.h"

#include <algorithm>
#include <cstddef>
#include <string>
#include <string_view>

#include "core/base/color.h"
#include "core/io/image/image_codecs.h"

namespace core {

namespace {

bool opaque(const Image& image) {
    for (std::size_t i = 3; i < image.rgba.size(); i += 4)
        if (image.rgba[i] != 255)
            return false;
    return true;
}

/** Names the encoder and its compression (zip for TIFF and EXR); the pixels are set apart. */
void setFormat(EncodeRequest& request, const char* oiioFormat, const char* extension) {
    request.format = oiioFormat;
    request.extension = extension;
    request.zip =
        std::string_view(oiioFormat) == "tiff" || std::string_view(oiioFormat) == "openexr";
}

/**
 * The colour space the file is marked with: EXR linear, other colour sRGB. OIIO 2.4's TIFF
 * writer produces an unreadable file through an I/O proxy when given a colour space: TIFF goes
 * without (8-bit TIFF is read as sRGB anyway).
 */
const char* colorSpaceOf(const EncodeRequest& request, bool colour) {
    const std::string_view format = request.format;
    if (format == "tiff")
        return nullptr;
    if (format == "openexr")
        return "Linear";
    return colour ? "sRGB" : nullptr;
}

} // namespace

Result<std::vector<std::uint8_t>> encodeImage(const Image& image, ExportFormat format,
                                              const ProgressFn& progress) {
    if (image.empty() || image.rgba.size() != std::size_t(image.width) * image.height * 4)
        return Error{"the texture is empty", ErrorKind::BadInput};
    Result<const ImageCodecs*> codecs = imageCodecs();
    if (!codecs)
        return codecs.takeError();
    EncodeRequest request;
    request.pixels = image.rgba.data();
    request.width = image.width;
    request.height = image.height;
    request.channels = opaque(image) ? 3 : 4;
    setFormat(request,
              format == ExportFormat::Tiff  ? "tiff"
              : format == ExportFormat::Exr ? "openexr"
                                            : "png",
              exportExtension(format));
    const std::size_t pixels = std::size_t(image.width) * std::size_t(image.height);
    std::vector<std::uint16_t> wide;
    std::vector<float> linear;
    if (format == ExportFormat::Png16) {
        request.type = PixelType::UInt16;
        wide.resize(pixels * 4);
        for (std::size_t i = 0; i < wide.size(); ++i)
            wide[i] = std::uint16_t(image.rgba[i] * 257u);
        request.pixels = wide.data();
    } else if (format == ExportFormat::Exr) {
        request.type = PixelType::Float32;
        request.halfFloat = true;
        // EXR holds linear colour associated with (multiplied by) alpha.
        linear.resize(pixels * 4);
        for (std::size_t i = 0; i < linear.size(); i += 4) {
            const float alpha = float(image.rgba[i + 3]) / 255.0f;
            for (std::size_t k = 0; k < 3; ++k)
                linear[i + k] = srgbToLinear(image.rgba[i + k]) * alpha;
            linear[i + 3] = alpha;
        }
        request.pixels = linear.data();
    }
    request.straightAlpha = format != ExportFormat::Exr; // PNG and TIFF: straight, as given
    request.colorSpace = colorSpaceOf(request, true);
    return (*codecs)->encode(request, progress);
}

Result<std::vector<std::uint8_t>> encodeValues(const std::uint16_t* values, int width, int height,
                                               int components, const std::array<bool, 4>& colour,
                                               MapFileFormat format, int bitDepth,
                                               const ProgressFn& progress) {
    if (width <= 0 || height <= 0 || components < 1 || components > 4)
        return Error{"the map is empty", ErrorKind::BadInput};
    Result<const ImageCodecs*> codecs = imageCodecs();
    if (!codecs)
        return codecs.takeError();
    EncodeRequest request;
    request.width = width;
    request.height = height;
    request.channels = components;
    setFormat(request,
              format == MapFileFormat::Tiff  ? "tiff"
              : format == MapFileFormat::Exr ? "openexr"
              : format == MapFileFormat::Tga ? "targa"
                                             : "png",
              mapFileExtension(format));
    request.colorSpace = colorSpaceOf(request, colour[0]);
    // Values go in 4 to a pixel, as the encoder takes them; the first `components` are written.
    const std::size_t pixels = std::size_t(width) * std::size_t(height);
    const std::size_t n = std::size_t(components);
    std::vector<std::uint8_t> bytes;
    std::vector<std::uint16_t> wide;
    std::vector<float> floats;
    if (format == MapFileFormat::Exr) {
        request.type = PixelType::Float32;
        request.halfFloat = bitDepth == 16;
        floats.assign(pixels * 4, 0.0f);
        for (std::size_t i = 0; i < pixels; ++i)
            for (std::size_t k = 0; k < n; ++k) {
                const float v = float(values[i * n + k]) / 65535.0f;
                floats[i * 4 + k] = colour[k] ? srgbToLinear(v) : v;
            }
        request.pixels = floats.data();
    } else if (bitDepth == 16) {
        request.type = PixelType::UInt16;
        wide.assign(pixels * 4, 0);
        for (std::size_t i = 0; i < pixels; ++i)
            std::copy_n(values + i * n, n, &wide[i * 4]);
        request.pixels = wide.data();
    } else {
        bytes.assign(pixels * 4, 0);
        for (std::size_t i = 0; i < pixels; ++i)
            for (std::size_t k = 0; k < n; ++k)
                bytes[i * 4 + k] =
                    std::uint8_t((std::uint32_t(values[i * n + k]) * 255u + 32767u) / 65535u);
        request.pixels = bytes.data();
    }
    return (*codecs)->encode(request, progress);
}

} // namespace core
