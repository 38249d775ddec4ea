// SPDX-License-Identifier: GPL-3.0-or-later
// The module layerpaint-image-codecs.so (image_codecs.h): decoding, encoding and writing images
// through OpenImageIO. It uses only header code of core/ (no symbols of the programs).
#include <algorithm>
#include <cstdint>
#include <exception>
#include <string>
#include <vector>

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include "core/io/image/image_codecs.h"

namespace core {

namespace {

std::string oneLine(std::string s) {
    std::replace(s.begin(), s.end(), '\n', ' ');
    std::replace(s.begin(), s.end(), '\r', ' ');
    while (!s.empty() && s.back() == ' ')
        s.pop_back();
    return s;
}

Result<Image> decodeOiio(const std::uint8_t* data, std::size_t size, const std::string& label,
                         const std::string& format, const LoadLimits& limits) {
    OIIO::Filesystem::IOMemReader proxy(data, size);
    OIIO::ImageSpec config;
    // PNG and TGA alpha stays straight (not premultiplied), as glTF expects.
    config.attribute("oiio:UnassociatedAlpha", 1);
    auto in = OIIO::ImageInput::create(format, false, &config, &proxy);
    if (!in) {
        OIIO::geterror(); // clear the pending message
        return Error{label + ": no decoder for " + format + " images"};
    }
    if (!in->supports("ioproxy"))
        return Error{label + ": the " + format + " decoder cannot read from memory"};
    // Both ways of handing over the proxy: create() only keeps it when it opens the file itself.
    in->set_ioproxy(&proxy);
    void* proxyPtr = &proxy;
    config.attribute("oiio:ioproxy", OIIO::TypeDesc::PTR, &proxyPtr);
    // The reader reads through the proxy; the name only appears in its messages.
    OIIO::ImageSpec spec;
    if (!in->open("memory." + format, spec, config)) {
        const std::string why = oneLine(in->geterror());
        return Error{label + ": cannot decode the " + format + " image" +
                     (why.empty() ? std::string() : " (" + why + ")")};
    }
    const std::int64_t w = spec.width, h = spec.height;
    // Only the first four channels matter (RGBA or grey + alpha); reading fewer saves memory.
    const std::int64_t channels = std::min(spec.nchannels, 4);
    if (w <= 0 || h <= 0 || channels <= 0 || spec.depth > 1) {
        in->close();
        return Error{label + ": the image has an invalid size"};
    }
    // Check before allocating: a hostile header can claim any size.
    if (static_cast<std::uint64_t>(w) * static_cast<std::uint64_t>(h) > limits.maxImagePixels ||
        w > 65536 || h > 65536) {
        in->close();
        return Error{label + ": the image is too large (" + std::to_string(w) + " x " +
                     std::to_string(h) + " pixels)"};
    }
    std::vector<std::uint8_t> pixels(static_cast<std::size_t>(w * h * channels));
    if (!in->read_image(0, 0, 0, static_cast<int>(channels), OIIO::TypeDesc::UINT8,
                        pixels.data())) {
        const std::string why = oneLine(in->geterror());
        in->close();
        return Error{label + ": cannot decode the " + format + " image" +
                     (why.empty() ? std::string() : " (" + why + ")")};
    }
    in->close();

    // Grey(+alpha) expands to RGB(+alpha); missing alpha becomes opaque.
    Image img;
    img.width = static_cast<int>(w);
    img.height = static_cast<int>(h);
    img.rgba.resize(static_cast<std::size_t>(w * h * 4));
    // Alpha is the channel the reader names so; a fourth channel of another name is not alpha.
    std::int64_t alphaChannel = spec.alpha_channel;
    if (alphaChannel < 0 || alphaChannel >= channels) {
        alphaChannel = -1;
        for (std::int64_t c = 0; c < channels && c < std::ssize(spec.channelnames); ++c)
            if (spec.channelnames[static_cast<std::size_t>(c)] == "A")
                alphaChannel = c;
    }
    const std::size_t n = static_cast<std::size_t>(w * h);
    for (std::size_t i = 0; i < n; ++i) {
        const std::uint8_t* src = &pixels[i * static_cast<std::size_t>(channels)];
        std::uint8_t* dst = &img.rgba[i * 4];
        if (channels >= 3) {
            dst[0] = src[0];
            dst[1] = src[1];
            dst[2] = src[2];
        } else {
            dst[0] = dst[1] = dst[2] = src[0];
        }
        dst[3] = alphaChannel >= 0 ? src[alphaChannel] : 255;
    }
    return img;
}

Result<Image> decode(const std::uint8_t* data, std::size_t size, const std::string& label,
                     const std::string& format, const LoadLimits& limits) {
    try {
        return decodeOiio(data, size, label, format, limits);
    } catch (const std::exception& e) {
        return Error{label + ": cannot decode the image (" + oneLine(e.what()) + ")"};
    } catch (...) {
        return Error{label + ": cannot decode the image"};
    }
}

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

Result<std::vector<std::uint8_t>> encode(const EncodeRequest& r, const ProgressFn& progress) {
    std::vector<std::uint8_t> bytes;
    OIIO::Filesystem::IOVecOutput proxy(bytes);
    auto out = OIIO::ImageOutput::create(r.format, &proxy);
    if (!out)
        return Error{std::string("no ") + r.format + " encoder (" + OIIO::geterror() + ")"};
    if (!out->supports("ioproxy") || !out->set_ioproxy(&proxy))
        return Error{std::string("the ") + r.format + " encoder cannot write to memory"};
    const OIIO::TypeDesc dataType = typeDesc(r.type);
    const OIIO::TypeDesc fileType = r.halfFloat ? OIIO::TypeDesc::HALF : dataType;
    OIIO::ImageSpec spec(r.width, r.height, r.channels, fileType);
    if (r.straightAlpha)
        spec.attribute("oiio:UnassociatedAlpha", 1);
    if (r.colorSpace != nullptr)
        spec.attribute("oiio:ColorSpace", r.colorSpace);
    spec.attribute("Software", "LayerPaint");
    if (r.zip)
        spec.attribute("compression", "zip");
    // The name only tells the encoder the format (TIFF needs it even with a proxy).
    if (!out->open(std::string("memory") + r.extension, spec))
        return Error{out->geterror()};
    const OIIO::stride_t pixelStride = OIIO::stride_t(dataType.size() * 4);
    OiioProgress state{&progress};
    const bool ok = out->write_image(dataType, r.pixels, pixelStride, OIIO::AutoStride,
                                     OIIO::AutoStride, &oiioProgress, &state) &&
                    out->close();
    if (state.cancelled)
        return cancelledError();
    if (!ok || bytes.empty())
        return Error{out->geterror().empty() ? std::string("the image cannot be encoded")
                                             : out->geterror()};
    return bytes;
}

Status write(const std::string& path, int width, int height, int channels, PixelType type,
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

} // namespace

extern "C" __attribute__((visibility("default"))) const ImageCodecs* layerpaint_image_codecs() {
    static const ImageCodecs codecs{&decode, &encode, &write};
    return &codecs;
}

} // namespace core
