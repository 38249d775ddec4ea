// SPDX-License-Identifier: GPL-3.0-or-later
// Images encoded in memory through OpenImageIO's I/O proxy (see image_encode.h).
#include "core/io/image_encode.h"

#include <cstddef>
#include <string>

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include "core/base/color.h"

namespace core {

namespace {

struct OiioProgress {
    const ProgressFn* progress = nullptr;
    bool cancelled = false;
};

bool oiioProgress(void* opaque, float done) {
    auto* p = static_cast<OiioProgress*>(opaque);
    if (p->progress && !reportProgress(*p->progress, double(done)))
        p->cancelled = true;
    return p->cancelled; // true asks OIIO to stop
}

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
    const char* formatName = format == ExportFormat::Tiff  ? "tiff"
                             : format == ExportFormat::Exr ? "openexr"
                                                           : "png";
    std::vector<std::uint8_t> bytes;
    OIIO::Filesystem::IOVecOutput proxy(bytes);
    auto out = OIIO::ImageOutput::create(formatName, &proxy);
    if (!out)
        return Error{std::string("no ") + formatName + " encoder (" + OIIO::geterror() + ")"};
    if (!out->supports("ioproxy") || !out->set_ioproxy(&proxy))
        return Error{std::string("the ") + formatName + " encoder cannot write to memory"};
    const int channels = opaque(image) ? 3 : 4;
    const std::size_t pixels = std::size_t(image.width) * std::size_t(image.height);
    OIIO::TypeDesc fileType = OIIO::TypeDesc::UINT8;
    OIIO::TypeDesc dataType = OIIO::TypeDesc::UINT8;
    const void* data = image.rgba.data();
    std::vector<std::uint16_t> wide;
    std::vector<float> linear;
    if (format == ExportFormat::Png16) {
        fileType = dataType = OIIO::TypeDesc::UINT16;
        wide.resize(pixels * 4);
        for (std::size_t i = 0; i < wide.size(); ++i)
            wide[i] = std::uint16_t(image.rgba[i] * 257u);
        data = wide.data();
    } else if (format == ExportFormat::Exr) {
        fileType = OIIO::TypeDesc::HALF;
        dataType = OIIO::TypeDesc::FLOAT;
        // EXR holds linear colour associated with (multiplied by) alpha.
        linear.resize(pixels * 4);
        for (std::size_t i = 0; i < linear.size(); i += 4) {
            const float alpha = float(image.rgba[i + 3]) / 255.0f;
            for (std::size_t k = 0; k < 3; ++k)
                linear[i + k] = srgbToLinear(image.rgba[i + k]) * alpha;
            linear[i + 3] = alpha;
        }
        data = linear.data();
    }
    OIIO::ImageSpec spec(image.width, image.height, channels, fileType);
    if (format != ExportFormat::Exr)
        spec.attribute("oiio:UnassociatedAlpha", 1); // PNG and TIFF: straight alpha, as given
    // OIIO 2.4's TIFF writer produces an unreadable file through an I/O proxy when given a
    // colour space: TIFF goes without (8-bit TIFF is read as sRGB anyway).
    if (format != ExportFormat::Tiff)
        spec.attribute("oiio:ColorSpace", format == ExportFormat::Exr ? "Linear" : "sRGB");
    spec.attribute("Software", "LayerPaint");
    if (format == ExportFormat::Tiff || format == ExportFormat::Exr)
        spec.attribute("compression", "zip");
    // The name only tells the encoder the format (TIFF needs it even with a proxy).
    if (!out->open(std::string("memory") + exportExtension(format), spec))
        return Error{out->geterror()};
    const OIIO::stride_t pixelStride = OIIO::stride_t(dataType.size() * 4);
    OiioProgress state{&progress};
    const bool ok = out->write_image(dataType, data, pixelStride, OIIO::AutoStride,
                                     OIIO::AutoStride, &oiioProgress, &state) &&
                    out->close();
    if (state.cancelled)
        return cancelledError();
    if (!ok || bytes.empty())
        return Error{out->geterror().empty() ? std::string("the image cannot be encoded")
                                             : out->geterror()};
    return bytes;
}

} // namespace core
