// SPDX-License-Identifier: GPL-3.0-or-later
// Image decoding through OpenImageIO, from memory or from a file.
#include <algorithm>
#include <array>
#include <cctype>
#include <cstdint>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <string_view>
#include <vector>

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include "core/base/text.h"
#include "core/io/gltf_export.h"
#include "core/io/mesh_io.h"
#include "core/io/mesh_io_in_process.h"

namespace core {

namespace {

bool startsWith(const std::uint8_t* data, std::size_t size, std::string_view magic) {
    return size >= magic.size() && std::memcmp(data, magic.data(), magic.size()) == 0;
}

/**
 * The OIIO format name from the data's signature, else from the name's extension. Creating the
 * reader by format name (not by file name) keeps OIIO from probing the disk for a file of that
 * name.
 */
std::string formatName(const std::uint8_t* data, std::size_t size, const std::string& name) {
    using namespace std::string_view_literals;
    struct Signature {
        std::string_view magic;
        const char* format;
        std::string_view at8 = {}; // what follows at byte 8, if anything
    };
    static constexpr Signature kSignatures[] = {
        {"\x89PNG\r\n\x1a\n"sv, "png"},
        {"\xff\xd8\xff"sv, "jpeg"},
        {"GIF8"sv, "gif"},
        {"BM"sv, "bmp"},
        {"II*\0"sv, "tiff"},
        {"MM\0*"sv, "tiff"},
        {"RIFF"sv, "webp", "WEBP"sv},
        {"\x76\x2f\x31\x01"sv, "openexr"},
        {"#?"sv, "hdr"},
        {"DDS "sv, "dds"},
        {"8BPS"sv, "psd"},
    };
    for (const Signature& s : kSignatures)
        if (startsWith(data, size, s.magic) &&
            (s.at8.empty() || (size >= 8 && startsWith(data + 8, size - 8, s.at8))))
            return s.format;
    const std::size_t dot = name.find_last_of('.');
    if (dot == std::string::npos || dot + 1 >= name.size())
        return {};
    const std::string ext = asciiLower(std::string_view(name).substr(dot + 1));
    // Only formats without a signature are worth trying by extension.
    if (ext == "tga" || ext == "targa")
        return "targa";
    return {};
}

std::uint32_t crc32(const std::uint8_t* data, std::size_t size) {
    static const auto table = [] {
        std::array<std::uint32_t, 256> t{};
        for (std::uint32_t i = 0; i < 256; ++i) {
            std::uint32_t c = i;
            for (int k = 0; k < 8; ++k)
                c = (c & 1) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
            t[i] = c;
        }
        return t;
    }();
    std::uint32_t c = 0xFFFFFFFFu;
    for (std::size_t i = 0; i < size; ++i)
        c = table[(c ^ data[i]) & 0xFFu] ^ (c >> 8);
    return c ^ 0xFFFFFFFFu;
}

std::uint32_t bigEndian32(const std::uint8_t* p) {
    return std::uint32_t(p[0]) << 24 | std::uint32_t(p[1]) << 16 | std::uint32_t(p[2]) << 8 | p[3];
}

/**
 * Walks the PNG chunks (lengths, CRCs, IHDR first, IEND last). libpng reports broken data by
 * longjmp through OpenImageIO's reader, which leaks and prints to stderr; most damage (truncated
 * or garbled files) is caught here first instead.
 */
Status checkPngChunks(const std::uint8_t* data, std::size_t size) {
    std::size_t pos = 8;
    bool first = true, haveData = false;
    while (true) {
        if (size - pos < 12)
            return Error{"the PNG data is truncated", ErrorKind::BadInput};
        const std::uint32_t length = bigEndian32(data + pos);
        const std::uint8_t* type = data + pos + 4;
        if (length > 0x7FFFFFFFu || size - pos - 12 < length)
            return Error{"the PNG data is truncated", ErrorKind::BadInput};
        for (int k = 0; k < 4; ++k)
            if (!std::isalpha(type[k]))
                return Error{"the PNG data is corrupt (invalid chunk type)", ErrorKind::BadInput};
        if (crc32(type, length + 4u) != bigEndian32(type + 4 + length))
            return Error{"the PNG data is corrupt (a chunk checksum does not match)",
                         ErrorKind::BadInput};
        const std::string_view name(reinterpret_cast<const char*>(type), 4);
        if (first && (name != "IHDR" || length != 13))
            return Error{"the PNG data is corrupt (no header chunk)", ErrorKind::BadInput};
        first = false;
        haveData = haveData || name == "IDAT";
        pos += 12 + length;
        if (name == "IEND")
            return haveData ? Status()
                            : Status(Error{"the PNG data has no image data", ErrorKind::BadInput});
    }
}

std::string oneLine(std::string s) {
    std::replace(s.begin(), s.end(), '\n', ' ');
    std::replace(s.begin(), s.end(), '\r', ' ');
    while (!s.empty() && s.back() == ' ')
        s.pop_back();
    return s;
}

Result<Image> decode(const std::uint8_t* data, std::size_t size, const std::string& label,
                     const std::string& name, const LoadLimits& limits) {
    const std::string format = formatName(data, size, name);
    if (format.empty())
        return Error{label + ": unknown image format", ErrorKind::Unsupported};
    if (format == "png")
        if (Status checked = checkPngChunks(data, size); !checked)
            return Error{label + ": " + checked.error(), checked.errorKind()};

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

} // namespace

Result<Image> decodeImage(const std::uint8_t* data, std::size_t size, const std::string& name,
                          const LoadLimits& limits) {
    const std::string label = name.empty() ? std::string("image") : name;
    if (data == nullptr || size == 0)
        return Error{label + ": the image is empty"};
    try {
        return decode(data, size, label, name, limits);
    } catch (const std::exception& e) {
        return Error{label + ": cannot decode the image (" + oneLine(e.what()) + ")"};
    } catch (...) {
        return Error{label + ": cannot decode the image"};
    }
}

Result<Image> loadImageFileInProcess(const std::string& path, const LoadLimits& limits) {
    namespace fs = std::filesystem;
    if (path.empty())
        return Error{"(no file name): no file was given"};
    std::error_code ec;
    const fs::file_status st = fs::status(path, ec);
    if (!fs::exists(st))
        return Error{path + ": does not exist"};
    if (!fs::is_regular_file(st))
        return Error{path + ": is not a regular file"};
    const std::uintmax_t size = fs::file_size(path, ec);
    if (ec)
        return Error{path + ": cannot be read (" + ec.message() + ")"};
    if (size == 0)
        return Error{path + ": is empty"};
    if (size > limits.maxFileBytes)
        return Error{path + ": is too large (" + std::to_string(size) + " bytes; the limit is " +
                     std::to_string(limits.maxFileBytes) + ")"};
    try {
        std::vector<std::uint8_t> bytes(static_cast<std::size_t>(size));
        std::ifstream in(path, std::ios::binary);
        if (!in.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(size)))
            return Error{path + ": cannot be read"};
        return decodeImage(bytes.data(), bytes.size(), path, limits);
    } catch (const std::bad_alloc&) {
        return Error{path + ": not enough memory to load the file"};
    }
}

Result<std::vector<Image>> loadGlbImagesInProcess(const std::string& path,
                                                  const std::vector<int>& views,
                                                  const LoadLimits& limits) {
    try {
        Result<std::vector<std::vector<std::uint8_t>>> files =
            readGlbViews(path, views, limits.maxFileBytes);
        if (!files)
            return files.takeError();
        std::vector<Image> images;
        images.reserve(files->size());
        for (std::size_t k = 0; k < files->size(); ++k) {
            Result<Image> image = decodeImage((*files)[k].data(), (*files)[k].size(),
                                              "paint layer image " + std::to_string(k), limits);
            if (!image)
                return Error{path + ": " + image.error(), image.errorKind()};
            images.push_back(std::move(image).value());
            (*files)[k] = {};
        }
        return images;
    } catch (const std::bad_alloc&) {
        return Error{path + ": not enough memory to load the file"};
    }
}

} // namespace core
