// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/io/image_write.h"

#include <OpenImageIO/imageio.h>

namespace core {

namespace {
OIIO::TypeDesc typeDesc(PixelType type) {
    switch (type) {
    case PixelType::UInt8:
        return OIIO::TypeDesc::UINT8;
    case PixelType::UInt16:
        return OIIO::TypeDesc::UINT16;
    case PixelType::UInt32:
        return OIIO::TypeDesc::UINT32;
    case PixelType::Float32:
        return OIIO::TypeDesc::FLOAT;
    }
    return OIIO::TypeDesc::UNKNOWN;
}
} // namespace

Status writeImage(const std::string& path, int width, int height, int channels, PixelType type,
                  const void* pixels) {
    auto out = OIIO::ImageOutput::create(path);
    if (!out)
        return Error{path + ": cannot write this image format (" + OIIO::geterror() + ")"};
    OIIO::ImageSpec spec(width, height, channels, typeDesc(type));
    if (path.ends_with(".tif") || path.ends_with(".tiff"))
        spec.attribute("compression", "zip");
    if (!out->open(path, spec))
        return Error{path + ": " + out->geterror()};
    // Formats that cannot hold the type (e.g. 32-bit integers in PNG) would silently convert.
    if (out->spec().format != spec.format) {
        out->close();
        return Error{path + ": the format cannot store " + std::string(spec.format.c_str()) +
                     " pixels"};
    }
    const bool ok = out->write_image(typeDesc(type), pixels) && out->close();
    if (!ok)
        return Error{path + ": " + out->geterror()};
    return {};
}

} // namespace core
