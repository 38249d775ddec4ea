// SPDX-License-Identifier: GPL-3.0-or-later
// Image decoding (through the image codecs module, image_codecs.h), from memory or from a file.
#include <algorithm>
#include <array>
#include <cctype>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <new>
#include <string>
#include <string_view>
#include <vector>

#include "core/base/text.h"
#include "core/io/gltf/gltf_export.h"
#include "core/io/image/image_codecs.h"
#include "core/io/importer/mesh_io_in_process.h"
#include "core/io/mesh_io.h"

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

} // namespace

Result<Image> decodeImage(const std::uint8_t* data, std::size_t size, const std::string& name,
                          const LoadLimits& limits) {
    const std::string label = name.empty() ? std::string("image") : name;
    if (data == nullptr || size == 0)
        return Error{label + ": the image is empty"};
    const std::string format = formatName(data, size, name);
    if (format.empty())
        return Error{label + ": unknown image format", ErrorKind::Unsupported};
    if (format == "png")
        if (Status checked = checkPngChunks(data, size); !checked)
            return Error{label + ": " + checked.error(), checked.errorKind()};
    Result<const ImageCodecs*> codecs = imageCodecs();
    if (!codecs)
        return Error{label + ": " + codecs.error()};
    return (*codecs)->decode(data, size, label, format, limits);
}

EncodedImage encodedImageOf(const std::uint8_t* data, std::size_t size) {
    if (data == nullptr || size == 0)
        return {};
    const std::string format = formatName(data, size, {});
    if (format != "png" && format != "jpeg")
        return {};
    return EncodedImage{"image/" + format, std::vector<std::uint8_t>(data, data + size)};
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
        return Error{
            path + ": too large for this machine's memory (an allocation failed while loading it)"};
    }
}

Result<std::vector<Image>> loadGlbImagesInProcess(const std::string& path,
                                                  const std::vector<GlbImageRequest>& requests,
                                                  const LoadLimits& limits) {
    try {
        std::vector<int> views;
        for (const GlbImageRequest& request : requests)
            views.push_back(request.view);
        Result<std::vector<std::vector<std::uint8_t>>> files =
            readGlbViews(path, views, limits.maxFileBytes);
        if (!files)
            return files.takeError();
        std::vector<Image> images;
        images.reserve(files->size());
        for (std::size_t k = 0; k < files->size(); ++k) {
            const GlbImageRequest& request = requests[k];
            const std::string label = "paint layer image " + std::to_string(k);
            // A header claiming more pixels than the request's is refused before decoding.
            LoadLimits within = limits;
            if (request.width > 0 && request.height > 0)
                within.maxImagePixels = std::min<std::uint64_t>(
                    limits.maxImagePixels, std::uint64_t(request.width) * request.height);
            Result<Image> image =
                decodeImage((*files)[k].data(), (*files)[k].size(), label, within);
            if (!image)
                return Error{path + ": " + image.error(), image.errorKind()};
            if (request.width > 0 && request.height > 0 &&
                (image->width != request.width || image->height != request.height))
                return Error{path + ": " + label + " is " + std::to_string(image->width) + " × " +
                                 std::to_string(image->height) + " pixels where " +
                                 std::to_string(request.width) + " × " +
                                 std::to_string(request.height) + " are expected",
                             ErrorKind::BadInput};
            images.push_back(std::move(image).value());
            (*files)[k] = {};
        }
        return images;
    } catch (const std::bad_alloc&) {
        return Error{
            path + ": too large for this machine's memory (an allocation failed while loading it)"};
    }
}

} // namespace core
