// SPDX-License-Identifier: GPL-3.0-or-later
// Images encoded in memory (see image_encode.h) by the image codecs module (image_codecs.h).
#include "core/io/image/image_encode.h"

#include <cstddef>
#include <string>

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
    request.format = format == ExportFormat::Tiff  ? "tiff"
                     : format == ExportFormat::Exr ? "openexr"
                                                   : "png";
    request.extension = exportExtension(format);
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
    // OIIO 2.4's TIFF writer produces an unreadable file through an I/O proxy when given a
    // colour space: TIFF goes without (8-bit TIFF is read as sRGB anyway).
    if (format != ExportFormat::Tiff)
        request.colorSpace = format == ExportFormat::Exr ? "Linear" : "sRGB";
    request.zip = format == ExportFormat::Tiff || format == ExportFormat::Exr;
    return (*codecs)->encode(request, progress);
}

} // namespace core
