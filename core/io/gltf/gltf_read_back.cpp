// SPDX-License-Identifier: GPL-3.0-or-later
// Reading back what the glTF writer stores beside the mesh: asset.extras and the bytes of buffer
// views of the BIN chunk (a project's paint-layer images), reading only the JSON and those bytes.
#include <algorithm>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <new>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include "core/io/gltf/glb_container.h"
#include "core/io/gltf/gltf_export.h"
#include "core/io/json_nesting.h"

namespace core {

namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;
using Bytes = std::vector<std::uint8_t>;

constexpr std::uint64_t kMaxJsonBytes = 256ull << 20;
/**
 * The most JSON values kept from the parts read (each costs tens of bytes in memory, whatever its
 * text): a project's largest legitimate state lists a few hundred thousand tiles, while 64 MiB of
 * small values would otherwise take gigabytes.
 */
constexpr std::uint64_t kMaxKeptJsonValues = 4u << 20;

/**
 * Parses text keeping only the root object's members named in keep (the rest is skipped as it
 * is read, so it costs no memory), and at most kMaxKeptJsonValues values of them.
 */
Result<Json> parseKeeping(const std::string& text, std::initializer_list<std::string_view> keep) {
    std::uint64_t kept = 0;
    bool tooMany = false;
    bool skipping = false; // inside a root member that is not kept
    const Json::parser_callback_t filter = [&](int depth, Json::parse_event_t event, Json& parsed) {
        if (event == Json::parse_event_t::key && depth == 1) {
            const std::string& key = parsed.get_ref<const std::string&>();
            skipping = std::find(keep.begin(), keep.end(), key) == keep.end();
            return !skipping;
        }
        if (skipping && depth >= 1)
            return false;
        if (event == Json::parse_event_t::value || event == Json::parse_event_t::object_start ||
            event == Json::parse_event_t::array_start) {
            tooMany = tooMany || ++kept > kMaxKeptJsonValues;
            return !tooMany;
        }
        return true;
    };
    Json root;
    try {
        root = Json::parse(text, filter);
    } catch (const Json::exception& e) {
        std::string what = e.what();
        if (const std::size_t p = what.find("] "); p != std::string::npos)
            what = what.substr(p + 2); // drop "[json.exception.parse_error.101] "
        return Error{"is not valid glTF JSON (" + what + ")"};
    }
    if (tooMany)
        return Error{"holds more than " + std::to_string(kMaxKeptJsonValues) +
                         " JSON values where LayerPaint reads its own",
                     ErrorKind::Unsupported};
    return root;
}

/** The glTF JSON of path and, for a binary file, where its BIN chunk's data is. */
struct GltfRoot {
    Json root;
    std::uint64_t binOffset = 0, binLength = 0; // 0, 0: no BIN chunk
};

/** keep: the members of the root object that are read (the others are skipped unread). */
Result<GltfRoot> readRoot(const std::string& path, std::initializer_list<std::string_view> keep) {
    std::error_code ec;
    if (!fs::is_regular_file(path, ec))
        return Error{fs::exists(path, ec) ? "is not a regular file" : "does not exist",
                     ErrorKind::Io};
    const std::uintmax_t size = fs::file_size(path, ec);
    if (ec)
        return Error{"cannot be read (" + ec.message() + ")", ErrorKind::Io};
    if (size == 0)
        return Error{"is empty"};
    std::ifstream in(path, std::ios::binary);
    if (!in)
        return Error{"cannot be read", ErrorKind::Io};
    std::uint8_t header[glb::kHeadBytes] = {};
    const auto headSize = std::min<std::uint64_t>(glb::kHeadBytes, size);
    in.read(reinterpret_cast<char*>(header), static_cast<std::streamsize>(headSize));
    const std::span<const std::uint8_t> head(header, static_cast<std::size_t>(headSize));
    std::uint64_t jsonOffset = 0, jsonLength = size;
    if (glb::hasMagic(head)) {
        Result<glb::Layout> layout = glb::readHead(head, size);
        if (!layout)
            return layout.takeError();
        jsonOffset = layout->jsonOffset;
        jsonLength = layout->jsonLength;
    }
    if (jsonLength > kMaxJsonBytes)
        return Error{"the glTF JSON is too large (" + std::to_string(jsonLength) + " bytes)"};
    std::string text(static_cast<std::size_t>(jsonLength), '\0');
    in.clear();
    in.seekg(static_cast<std::streamoff>(jsonOffset));
    if (!in.read(text.data(), static_cast<std::streamsize>(jsonLength)))
        return Error{"cannot be read", ErrorKind::Io};
    if (jsonNestingTooDeep(text))
        return Error{"the JSON is nested too deeply"};
    Result<Json> parsed = parseKeeping(text, keep);
    if (!parsed)
        return parsed.takeError();
    Json root = std::move(parsed).value();
    if (!root.is_object() || !root.contains("asset") || !root["asset"].is_object())
        return Error{"is not a glTF file (no asset)"};
    GltfRoot out;
    const std::uint64_t binHead = jsonOffset + jsonLength;
    if (glb::hasMagic(head) && binHead + 8 <= size) {
        std::uint8_t chunk[8] = {};
        in.seekg(static_cast<std::streamoff>(binHead));
        if (in.read(reinterpret_cast<char*>(chunk), 8)) {
            std::uint32_t length = 0, type = 0;
            std::memcpy(&length, chunk, 4);
            std::memcpy(&type, chunk + 4, 4);
            if (type == glb::kChunkBin && binHead + 8 + length <= size) {
                out.binOffset = binHead + 8;
                out.binLength = length;
            }
        }
    }
    out.root = std::move(root);
    return out;
}

Result<Json> readExtras(const std::string& path) {
    Result<GltfRoot> gltf = readRoot(path, {"asset"});
    if (!gltf)
        return gltf.takeError();
    const Json& asset = gltf->root["asset"];
    const auto it = asset.find("extras");
    if (it == asset.end())
        return Json::object();
    if (!it->is_object())
        return Error{"asset.extras is not a JSON object"};
    return *it;
}

} // namespace

Result<nlohmann::json> readGlbExtras(const std::string& path) {
    try {
        Result<Json> extras = readExtras(path);
        if (!extras)
            return Error{path + ": " + extras.error(), extras.errorKind()};
        return extras;
    } catch (const std::bad_alloc&) {
        return Error{path + ": too large for this machine's memory (an allocation failed while "
                            "reading it)"};
    } catch (const std::exception& e) {
        return Error{path + ": cannot be read (" + std::string(e.what()) + ")"};
    }
}

namespace {

Result<std::vector<Bytes>> readViews(const std::string& path, const std::vector<int>& wanted,
                                     std::uint64_t maxBytes) {
    Result<GltfRoot> gltf = readRoot(path, {"asset", "bufferViews"});
    if (!gltf)
        return gltf.takeError();
    const Json& root = gltf->root;
    const auto views = root.find("bufferViews");
    std::vector<Bytes> out;
    std::uint64_t total = 0;
    std::ifstream in(path, std::ios::binary);
    for (const int v : wanted) {
        const std::string name = "buffer view " + std::to_string(v);
        if (views == root.end() || !views->is_array() || v < 0 || std::size_t(v) >= views->size() ||
            !(*views)[std::size_t(v)].is_object())
            return Error{name + " is missing"};
        const Json& view = (*views)[std::size_t(v)];
        const auto number = [&](const char* key) -> std::optional<std::uint64_t> {
            const auto it = view.find(key);
            if (it == view.end())
                return std::uint64_t{0};
            if (!it->is_number_unsigned())
                return std::nullopt;
            return it->get<std::uint64_t>();
        };
        const std::optional<std::uint64_t> offset = number("byteOffset"),
                                           length = number("byteLength");
        if (!offset || !length || view.value("buffer", Json(-1)) != Json(0) ||
            *offset > gltf->binLength || *length > gltf->binLength - *offset)
            return Error{name + " lies outside the binary chunk"};
        total += *length;
        if (total > maxBytes)
            return Error{"the paint layer images are too large (over " + std::to_string(maxBytes) +
                         " bytes)"};
        Bytes bytes(static_cast<std::size_t>(*length));
        in.seekg(static_cast<std::streamoff>(gltf->binOffset + *offset));
        if (!in.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(*length)))
            return Error{"cannot be read", ErrorKind::Io};
        out.push_back(std::move(bytes));
    }
    return out;
}

} // namespace

Result<std::vector<std::vector<std::uint8_t>>>
readGlbViews(const std::string& path, const std::vector<int>& views, std::uint64_t maxBytes) {
    try {
        Result<std::vector<Bytes>> out = readViews(path, views, maxBytes);
        if (!out)
            return Error{path + ": " + out.error(), out.errorKind()};
        return out;
    } catch (const std::bad_alloc&) {
        return Error{path + ": not enough memory to read the file"};
    } catch (const std::exception& e) {
        return Error{path + ": cannot be read (" + std::string(e.what()) + ")"};
    }
}

} // namespace core
