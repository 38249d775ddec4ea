// SPDX-License-Identifier: GPL-3.0-or-later
// The importer's processor-time budget from what a load reads (see import_budget.h). Finding the
// companion files reads names out of the model's text only: nothing is parsed beyond a line or
// a quoted string, and every name is confined to the model's folder as the loaders confine it.
#include "core/io/importer/import_budget.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <fstream>
#include <set>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include "core/base/text.h"
#include "core/io/assimp/assimp_file_access.h"

namespace core::detail {

namespace {

namespace fs = std::filesystem;

constexpr std::size_t kMaxScanBytes = std::size_t(4) << 20; // of a model's or MTL's text
constexpr std::size_t kMaxCompanions = 256;
constexpr double kMiB = 1024.0 * 1024.0;

/** At most maxBytes from the start of p (less if it is shorter or cannot be read). */
std::string readPrefix(const fs::path& p, std::size_t maxBytes) {
    std::ifstream in(p, std::ios::binary);
    std::string text(maxBytes, '\0');
    in.read(text.data(), std::streamsize(maxBytes));
    text.resize(in ? maxBytes : std::size_t(std::max<std::streamsize>(0, in.gcount())));
    return text;
}

std::uint64_t fileBytes(const fs::path& p) {
    std::error_code ec;
    const std::uintmax_t bytes = fs::file_size(p, ec);
    return ec ? 0 : std::uint64_t(bytes);
}

bool isImageName(const fs::path& name) {
    static constexpr std::array<std::string_view, 14> kImages = {
        ".png",  ".jpg", ".jpeg", ".tga", ".bmp", ".gif",  ".tif",
        ".tiff", ".exr", ".hdr",  ".psd", ".dds", ".webp", ".ktx2"};
    const std::string ext = lowerExtension(name);
    return std::find(kImages.begin(), kImages.end(), ext) != kImages.end();
}

/** The companion files found so far, each counted once, inside the model's folder only. */
class Companions {
public:
    explicit Companions(const fs::path& file) {
        std::error_code ec;
        m_folder = fs::weakly_canonical(file, ec).parent_path();
    }

    /** Counts the file `name` names (as the loaders resolve it); its path, or empty. */
    fs::path add(std::string name) {
        if (name.empty() || m_seen.size() >= kMaxCompanions)
            return {};
        std::replace(name.begin(), name.end(), '\\', '/');
        fs::path real = assimp::confine(fs::path(name), m_folder);
        std::error_code ec;
        if (real.empty() || !fs::is_regular_file(real, ec)) {
            // As the loaders do for a path written elsewhere: the bare name in the folder.
            const fs::path bare = fs::path(name).filename();
            real = bare.empty() ? fs::path() : assimp::confine(bare, m_folder);
        }
        if (real.empty() || !fs::is_regular_file(real, ec) || !m_seen.insert(real).second)
            return {};
        input.bytes += fileBytes(real);
        input.images += isImageName(real) ? 1u : 0u;
        return real;
    }

    ImportInput input;

private:
    fs::path m_folder;
    std::set<fs::path> m_seen;
};

std::string_view trimmed(std::string_view s) {
    const auto space = [](char c) { return c == ' ' || c == '\t' || c == '\r'; };
    while (!s.empty() && space(s.front()))
        s.remove_prefix(1);
    while (!s.empty() && space(s.back()))
        s.remove_suffix(1);
    return s;
}

/** The lines of text, each without its line break. */
template <typename Visit> void forEachLine(std::string_view text, Visit&& visit) {
    while (!text.empty()) {
        const std::size_t end = std::min(text.find('\n'), text.size());
        visit(trimmed(text.substr(0, end)));
        text.remove_prefix(std::min(end + 1, text.size()));
    }
}

/** The first word of line (ASCII lower case), and what follows it, trimmed. */
std::pair<std::string, std::string_view> keyword(std::string_view line) {
    const std::size_t end = std::min(line.find_first_of(" \t"), line.size());
    return {asciiLower(line.substr(0, end)), trimmed(line.substr(end))};
}

/** An MTL's texture maps: the last word of map_Kd, bump, norm, ... lines. */
void addMtlMaps(const fs::path& mtl, Companions& companions) {
    forEachLine(readPrefix(mtl, kMaxScanBytes), [&companions](std::string_view line) {
        const auto [key, rest] = keyword(line);
        const bool map = key.rfind("map_", 0) == 0 || key == "bump" || key == "norm" ||
                         key == "disp" || key == "decal" || key == "refl";
        if (!map || rest.empty())
            return;
        const std::size_t last = rest.find_last_of(" \t");
        companions.add(std::string(last == std::string_view::npos ? rest : rest.substr(last + 1)));
    });
}

/** An OBJ's mtllib files (a name with spaces, or several names) and their maps. */
void addObjCompanions(const fs::path& file, Companions& companions) {
    forEachLine(readPrefix(file, kMaxScanBytes), [&companions](std::string_view line) {
        const auto [key, rest] = keyword(line);
        if (key != "mtllib" || rest.empty())
            return;
        std::vector<fs::path> mtls;
        if (fs::path whole = companions.add(std::string(rest)); !whole.empty()) {
            mtls.push_back(whole);
        } else {
            std::string_view names = rest;
            while (!names.empty()) {
                const std::size_t end = std::min(names.find_first_of(" \t"), names.size());
                if (fs::path one = companions.add(std::string(names.substr(0, end))); !one.empty())
                    mtls.push_back(one);
                names = trimmed(names.substr(end));
            }
        }
        for (const fs::path& mtl : mtls)
            addMtlMaps(mtl, companions);
    });
}

int hexValue(char c) {
    if (c >= '0' && c <= '9')
        return c - '0';
    c = char(c | 0x20);
    return c >= 'a' && c <= 'f' ? c - 'a' + 10 : -1;
}

/** A glTF URI as a file name: JSON's \/ and the URI's %XX undone. */
std::string uriFileName(std::string_view uri) {
    std::string name;
    for (std::size_t i = 0; i < uri.size(); ++i) {
        if (uri[i] == '\\' && i + 1 < uri.size()) {
            name.push_back(uri[++i]);
        } else if (uri[i] == '%' && i + 2 < uri.size() && hexValue(uri[i + 1]) >= 0 &&
                   hexValue(uri[i + 2]) >= 0) {
            name.push_back(char(hexValue(uri[i + 1]) * 16 + hexValue(uri[i + 2])));
            i += 2;
        } else {
            name.push_back(uri[i]);
        }
    }
    return name;
}

/**
 * A glTF's JSON: every "uri" string (a file beside it, or data: held in the JSON already
 * counted) and every "mimeType" (an image in a buffer view).
 */
void addGltfCompanions(std::string_view json, Companions& companions) {
    for (std::size_t at = json.find("\"mimeType\""); at != std::string_view::npos;
         at = json.find("\"mimeType\"", at + 1))
        ++companions.input.images;
    for (std::size_t at = json.find("\"uri\""); at != std::string_view::npos;
         at = json.find("\"uri\"", at + 1)) {
        std::size_t open = json.find_first_not_of(" \t\r\n", at + 5);
        if (open == std::string_view::npos || json[open] != ':')
            continue;
        open = json.find_first_not_of(" \t\r\n", open + 1);
        if (open == std::string_view::npos || json[open] != '"')
            continue;
        std::size_t close = open + 1;
        while (close < json.size() && json[close] != '"')
            close += json[close] == '\\' ? 2 : 1;
        const std::string_view uri = json.substr(open + 1, std::min(close, json.size()) - open - 1);
        if (uri.rfind("data:", 0) == 0)
            companions.input.images += uri.rfind("data:image/", 0) == 0 ? 1u : 0u;
        else
            companions.add(uriFileName(uri));
    }
}

/** A .glb's JSON chunk (its first), at most kMaxScanBytes of it; empty if it has none. */
std::string glbJson(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::array<std::uint32_t, 5> head{}; // magic, version, length, chunk length, chunk type
    if (!in.read(reinterpret_cast<char*>(head.data()), sizeof head) || head[0] != 0x46546C67u ||
        head[4] != 0x4E4F534Au)
        return {};
    std::string json(std::min<std::size_t>(head[3], kMaxScanBytes), '\0');
    in.read(json.data(), std::streamsize(json.size()));
    json.resize(std::size_t(std::max<std::streamsize>(0, in.gcount())));
    return json;
}

} // namespace

ImportInput estimateImportInput(const fs::path& file, ImportKind kind) {
    Companions companions(file);
    companions.input.bytes = fileBytes(file);
    if (kind == ImportKind::Image) {
        companions.input.images = 1;
        return companions.input;
    }
    const std::string ext = lowerExtension(file);
    if (ext == ".obj")
        addObjCompanions(file, companions);
    else if (ext == ".gltf")
        addGltfCompanions(readPrefix(file, kMaxScanBytes), companions);
    else if (ext == ".glb")
        addGltfCompanions(glbJson(file), companions);
    return companions.input;
}

double importProcessorSeconds(const ImportInput& input) {
    return kImportBaseSeconds + kImportSecondsPerMiB * (double(input.bytes) / kMiB) +
           kImportSecondsPerImage * double(input.images);
}

double importWallSeconds(double processorSeconds) {
    return 3.0 * processorSeconds + 10.0;
}

} // namespace core::detail
