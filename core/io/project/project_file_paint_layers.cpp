// SPDX-License-Identifier: GPL-3.0-or-later
// The paint layers' images inside a project file. A plane is saved per page as one PNG of the
// bounding region of its written tiles, with the list of those tiles, so reading it back gives
// the same tiles with the same bytes. Texels map to RGBA as: base colour RGBA as is; roughness
// and metallic (value, coverage) as grey with alpha; a mask as grey.
#include "core/io/project/project_file_paint_layers.h"

#include "core/base/text.h"

#include <algorithm>
#include <array>
#include <cstring>

#include <unistd.h>

#include "core/io/gltf/gltf_export.h"
#include "core/io/image/image_encode.h"

namespace core {

namespace {

using Json = nlohmann::json;
using Bytes = std::vector<std::uint8_t>;

constexpr std::array<const char*, kPaintChannels> kChannelNames = {"base_color", "roughness",
                                                                   "metallic"};

void toRgba(const std::uint8_t* texel, int texelBytes, std::uint8_t* rgba) {
    if (texelBytes == 4) {
        std::memcpy(rgba, texel, 4);
    } else {
        rgba[0] = rgba[1] = rgba[2] = texel[0];
        rgba[3] = texelBytes == 2 ? texel[1] : 255;
    }
}

void fromRgba(const std::uint8_t* rgba, int texelBytes, std::uint8_t* texel) {
    if (texelBytes == 4) {
        std::memcpy(texel, rgba, 4);
    } else {
        texel[0] = rgba[0];
        if (texelBytes == 2)
            texel[1] = rgba[3];
    }
}

Result<Json> encodePlane(const TiledPlane& plane, std::vector<Bytes>& attachments) {
    const int tb = plane.texelBytes();
    Json pages = Json::array();
    for (std::uint32_t p = 0; p < plane.pages().size(); ++p) {
        std::vector<std::uint32_t> tiles;
        int x0 = plane.pages()[p].width, y0 = plane.pages()[p].height, x1 = 0, y1 = 0;
        for (std::uint32_t t = 0; t < plane.tileCount(p); ++t) {
            if (!plane.tile(p, t))
                continue;
            tiles.push_back(t);
            const TileRect r = plane.tileRect(p, t);
            x0 = std::min(x0, r.x);
            y0 = std::min(y0, r.y);
            x1 = std::max(x1, r.x + r.width);
            y1 = std::max(y1, r.y + r.height);
        }
        if (tiles.empty())
            continue;
        Image image{x1 - x0, y1 - y0, {}};
        image.rgba.resize(std::size_t(image.width) * std::size_t(image.height) * 4);
        for (int y = y0; y < y1; ++y)
            for (int x = x0; x < x1; ++x)
                toRgba(plane.texel(p, x, y), tb,
                       &image.rgba[(std::size_t(y - y0) * std::size_t(image.width) +
                                    std::size_t(x - x0)) *
                                   4]);
        Result<Bytes> png = encodeImage(image, ExportFormat::Png8);
        if (!png)
            return Error{"a paint layer's image cannot be encoded as PNG (" + png.error() + ")",
                         png.errorKind()};
        attachments.push_back(std::move(png).value());
        pages.push_back({{"page", p},
                         {"x", x0},
                         {"y", y0},
                         {"width", image.width},
                         {"height", image.height},
                         {"tiles", tiles},
                         {"image", attachments.size() - 1}});
    }
    Json fill = Json::array();
    for (const std::uint8_t v : plane.fill())
        fill.push_back(v);
    return Json{{"texel_bytes", tb}, {"fill", std::move(fill)}, {"pages", std::move(pages)}};
}

/** A whole number j in [lo, hi], or nothing. */
std::optional<long long> whole(const Json& j, const char* key, long long lo, long long hi) {
    const auto it = j.find(key);
    if (it == j.end() || !it->is_number_integer())
        return std::nullopt;
    const long long v = it->get<long long>();
    if (v < lo || v > hi)
        return std::nullopt;
    return v;
}

class PlaneReader {
public:
    PlaneReader(const std::vector<PageSize>& pages, const std::vector<Image>& images)
        : m_pages(pages), m_images(images) {}

    /** The plane j describes, with its texels from the images; expected: its texel size. */
    Result<std::shared_ptr<const TiledPlane>> read(const Json& j, int expected) const {
        if (!j.is_object())
            return Error{"is not a JSON object"};
        const auto tb = whole(j, "texel_bytes", 1, 4);
        if (!tb || *tb != expected)
            return Error{"has texel_bytes other than " + std::to_string(expected)};
        std::array<std::uint8_t, 4> fill{};
        const auto f = j.find("fill");
        if (f == j.end() || !f->is_array() || f->size() != fill.size())
            return Error{"has no fill value of 4 bytes"};
        for (std::size_t k = 0; k < f->size(); ++k) {
            if (!(*f)[k].is_number_unsigned() || (*f)[k].get<std::uint64_t>() > 255)
                return Error{"has a fill value that is not bytes"};
            fill[k] = static_cast<std::uint8_t>((*f)[k].get<std::uint64_t>());
        }
        auto plane = std::make_shared<TiledPlane>(m_pages, int(*tb), fill);
        const auto pages = j.find("pages");
        if (pages == j.end() || !pages->is_array())
            return Error{"has no pages"};
        for (const Json& page : *pages) {
            if (!page.is_object())
                return Error{"has a page that is not a JSON object"};
            const auto p = whole(page, "page", 0, (long long)m_pages.size() - 1);
            if (!p)
                return Error{"names a page the model does not have"};
            const PageSize size = m_pages[std::size_t(*p)];
            long long x = -1, y = -1, w = 0, h = 0, img = -1;
            if (const auto v = whole(page, "x", 0, size.width - 1))
                x = *v;
            if (const auto v = whole(page, "y", 0, size.height - 1))
                y = *v;
            if (const auto v = whole(page, "width", 1, size.width))
                w = *v;
            if (const auto v = whole(page, "height", 1, size.height))
                h = *v;
            if (const auto v = whole(page, "image", 0, (long long)m_images.size() - 1))
                img = *v;
            if (x < 0 || y < 0 || w < 1 || h < 1 || img < 0 || x + w > size.width ||
                y + h > size.height)
                return Error{"has a region outside its page or a missing image"};
            const Image& image = m_images[std::size_t(img)];
            if (image.width != w || image.height != h)
                return Error{"has an image of " + std::to_string(image.width) + "×" +
                             std::to_string(image.height) + " for a region of " +
                             std::to_string(w) + "×" + std::to_string(h)};
            const auto tiles = page.find("tiles");
            if (tiles == page.end() || !tiles->is_array())
                return Error{"has no list of tiles"};
            const auto pi = std::uint32_t(*p);
            for (const Json& t : *tiles) {
                if (!t.is_number_unsigned() || t.get<std::uint64_t>() >= plane->tileCount(pi))
                    return Error{"names a tile its page does not have"};
                const auto tile = t.get<std::uint32_t>();
                const TileRect r = plane->tileRect(pi, tile);
                if (r.x < x || r.y < y || r.x + r.width > x + w || r.y + r.height > y + h)
                    return Error{"has a tile outside its image"};
                std::uint8_t* out = plane->writableTile(pi, tile);
                for (int ty = 0; ty < r.height; ++ty)
                    for (int tx = 0; tx < r.width; ++tx) {
                        const std::size_t at =
                            std::size_t(r.y + ty - y) * std::size_t(w) + std::size_t(r.x + tx - x);
                        fromRgba(&image.rgba[at * 4], int(*tb),
                                 out + (std::size_t(ty) * std::size_t(r.width) + std::size_t(tx)) *
                                           std::size_t(*tb));
                    }
            }
        }
        return std::shared_ptr<const TiledPlane>(std::move(plane));
    }

private:
    const std::vector<PageSize>& m_pages;
    const std::vector<Image>& m_images;
};

/**
 * The roughness and metallic base of saved's pages where it differs from the composite. A
 * project written before they were kept has none: its base was flat (rough, not metallic).
 */
Status readBaseMetallicRoughness(const Json& paintLayers, const std::vector<PageSize>& pages,
                                 const std::vector<Image>& images, SavedPaintLayers& saved) {
    saved.baseMetallicRoughness.assign(pages.size(), Image{});
    const auto entries = paintLayers.find("base_metallic_roughness");
    if (entries == paintLayers.end()) {
        for (std::size_t p = 0; p < pages.size(); ++p) {
            Image& flat = saved.baseMetallicRoughness[p];
            flat = Image{pages[p].width, pages[p].height, {}};
            flat.rgba.resize(std::size_t(flat.width) * std::size_t(flat.height) * 4);
            for (std::size_t i = 0; i < flat.rgba.size(); i += 4) {
                flat.rgba[i] = flat.rgba[i + 2] = 0;
                flat.rgba[i + 1] = flat.rgba[i + 3] = 255;
            }
        }
        return {};
    }
    if (!entries->is_array())
        return Error{"extras.layerpaint.paint_layers.base_metallic_roughness is not an array"};
    const std::string misfit = "the roughness and metallic under the paint layers do not fit the "
                               "model's textures";
    for (const Json& entry : *entries) {
        if (!entry.is_object())
            return Error{misfit};
        const auto p = whole(entry, "page", 0, (long long)pages.size() - 1);
        const auto img = whole(entry, "image", 0, (long long)images.size() - 1);
        if (!p || !img || images[std::size_t(*img)].width != pages[std::size_t(*p)].width ||
            images[std::size_t(*img)].height != pages[std::size_t(*p)].height)
            return Error{misfit};
        saved.baseMetallicRoughness[std::size_t(*p)] = images[std::size_t(*img)];
    }
    return {};
}

} // namespace

Status addPaintLayerImages(const SavedPaintLayers& saved, const std::vector<PageSize>& pages,
                           Json& paintLayers, std::vector<Bytes>& attachments) {
    Json sizes = Json::array();
    for (const PageSize& page : pages)
        sizes.push_back({page.width, page.height});
    paintLayers["pages"] = std::move(sizes);
    Json& layers = paintLayers["layers"];
    for (std::size_t i = 0; i < saved.layers.size() && i < layers.size(); ++i) {
        const SavedPaintLayer& layer = saved.layers[i];
        Json channels = Json::object();
        for (std::size_t c = 0; c < kPaintChannels; ++c) {
            if (!layer.channels[c])
                continue;
            Result<Json> plane = encodePlane(*layer.channels[c], attachments);
            if (!plane)
                return plane.takeError();
            channels[kChannelNames[c]] = std::move(plane).value();
        }
        layers[i]["channels"] = std::move(channels);
        if (layer.mask) {
            Result<Json> plane = encodePlane(*layer.mask, attachments);
            if (!plane)
                return plane.takeError();
            layers[i]["mask"] = std::move(plane).value();
        }
    }
    Json base = Json::array();
    for (std::size_t p = 0; p < saved.base.size(); ++p) {
        if (saved.base[p].empty())
            continue;
        Result<Bytes> png = encodeImage(saved.base[p], ExportFormat::Png8);
        if (!png)
            return Error{"the base of texture " + std::to_string(p) +
                             " cannot be encoded as PNG (" + png.error() + ")",
                         png.errorKind()};
        attachments.push_back(std::move(png).value());
        base.push_back({{"page", p}, {"image", attachments.size() - 1}});
    }
    paintLayers["base"] = std::move(base);
    Json baseMr = Json::array();
    for (std::size_t p = 0; p < saved.baseMetallicRoughness.size(); ++p) {
        if (saved.baseMetallicRoughness[p].empty())
            continue;
        Result<Bytes> png = encodeImage(saved.baseMetallicRoughness[p], ExportFormat::Png8);
        if (!png)
            return Error{"the roughness and metallic base of texture " + std::to_string(p) +
                             " cannot be encoded as PNG (" + png.error() + ")",
                         png.errorKind()};
        attachments.push_back(std::move(png).value());
        baseMr.push_back({{"page", p}, {"image", attachments.size() - 1}});
    }
    paintLayers["base_metallic_roughness"] = std::move(baseMr);
    return {};
}

namespace {

/** The machine's physical memory in bytes (0 if unknown). */
std::uint64_t physicalMemory() {
    const long pages = ::sysconf(_SC_PHYS_PAGES), size = ::sysconf(_SC_PAGE_SIZE);
    return pages > 0 && size > 0 ? std::uint64_t(pages) * std::uint64_t(size) : 0;
}

std::string mebibytes(std::uint64_t bytes) {
    return std::to_string((bytes + (1u << 20) - 1) >> 20) + " MiB";
}

/**
 * What the paint layers ask of their images and memory, read from the JSON before any image is
 * decoded: per image the size its uses give it (none: unused), and the bytes of the tiles the
 * planes list. Entries the plane reader would refuse are left to it.
 */
class ImagePlan {
public:
    ImagePlan(const std::vector<PageSize>& pages, std::size_t images)
        : m_pages(pages), m_sizes(images) {}

    /** A plane's pages: each region's image is asked for at the region's size. */
    Status addPlane(const Json& plane) {
        if (!plane.is_object())
            return {};
        const auto texelBytes = whole(plane, "texel_bytes", 1, 4);
        const auto pages = plane.find("pages");
        if (!texelBytes || pages == plane.end() || !pages->is_array())
            return {};
        for (const Json& page : *pages) {
            if (!page.is_object())
                continue;
            const auto p = whole(page, "page", 0, (long long)m_pages.size() - 1);
            if (!p)
                continue;
            const PageSize size = m_pages[std::size_t(*p)];
            const auto w = whole(page, "width", 1, size.width);
            const auto h = whole(page, "height", 1, size.height);
            if (Status used = use(page, w.value_or(0), h.value_or(0)); !used)
                return used;
            if (const auto tiles = page.find("tiles"); tiles != page.end() && tiles->is_array())
                m_tileBytes += std::uint64_t(tiles->size()) * TiledPlane::kPlaneTile *
                               TiledPlane::kPlaneTile * std::uint64_t(*texelBytes);
        }
        return {};
    }

    /** A base entry: its image is asked for at its page's size. */
    Status addPage(const Json& entry) {
        if (!entry.is_object())
            return {};
        const auto p = whole(entry, "page", 0, (long long)m_pages.size() - 1);
        if (!p)
            return {};
        return use(entry, m_pages[std::size_t(*p)].width, m_pages[std::size_t(*p)].height);
    }

    /** The bytes the paint layers take: their tiles as read and as restored, and the images. */
    std::uint64_t bytes() const {
        std::uint64_t images = 0;
        for (const PageSize& size : m_sizes)
            images += std::uint64_t(size.width) * std::uint64_t(size.height) * 4;
        return 2 * m_tileBytes + images;
    }

    /** The images to decode: every used one, with its size. */
    std::vector<GlbImageRequest> requests(const std::vector<int>& views) const {
        std::vector<GlbImageRequest> out;
        for (std::size_t i = 0; i < m_sizes.size(); ++i)
            if (m_sizes[i].width > 0)
                out.push_back({views[i], m_sizes[i].width, m_sizes[i].height});
        return out;
    }

    /** Images in the order of the project's list, the unused ones empty. */
    std::vector<Image> place(std::vector<Image> decoded) const {
        std::vector<Image> images(m_sizes.size());
        std::size_t next = 0;
        for (std::size_t i = 0; i < m_sizes.size(); ++i)
            if (m_sizes[i].width > 0 && next < decoded.size())
                images[i] = std::move(decoded[next++]);
        return images;
    }

private:
    Status use(const Json& entry, int width, int height) {
        const auto image = whole(entry, "image", 0, (long long)m_sizes.size() - 1);
        if (!image || width < 1 || height < 1)
            return {};
        PageSize& size = m_sizes[std::size_t(*image)];
        if (size.width == 0)
            size = {width, height};
        else if (size != PageSize{width, height})
            return Error{"image " + std::to_string(*image) + " is used at two sizes (" +
                         std::to_string(size.width) + " × " + std::to_string(size.height) +
                         " and " + std::to_string(width) + " × " + std::to_string(height) + ")"};
        return {};
    }

    const std::vector<PageSize>& m_pages;
    std::vector<PageSize> m_sizes; // per image, {0, 0}: unused
    std::uint64_t m_tileBytes = 0;
};

/** The project's image list: buffer view numbers, each a whole number the GL's int can hold. */
Result<std::vector<int>> imageViews(const Json& paintLayers) {
    std::vector<int> views;
    const auto it = paintLayers.find("images");
    if (it == paintLayers.end())
        return views;
    if (!it->is_array())
        return Error{"extras.layerpaint.paint_layers.images is not an array"};
    for (const Json& v : *it) {
        if (!v.is_number_unsigned() || v.get<std::uint64_t>() > 0x7FFFFFFF)
            return Error{"extras.layerpaint.paint_layers.images holds something other than a "
                         "buffer view number"};
        views.push_back(int(v.get<std::uint64_t>()));
    }
    return views;
}

/** Plans every image use of the paint layers (their planes, base and roughness-metallic base). */
Result<ImagePlan> planImages(const Json& paintLayers, const std::vector<PageSize>& pages,
                             std::size_t images, std::size_t layerCount) {
    ImagePlan plan(pages, images);
    const auto layers = paintLayers.find("layers");
    if (layers != paintLayers.end() && layers->is_array())
        for (std::size_t i = 0; i < layers->size() && i < layerCount; ++i) {
            const Json& layer = (*layers)[i];
            if (!layer.is_object())
                continue;
            if (const auto channels = layer.find("channels");
                channels != layer.end() && channels->is_object())
                for (const auto& [name, plane] : channels->items())
                    if (Status added = plan.addPlane(plane); !added)
                        return added.takeError();
            if (const auto mask = layer.find("mask"); mask != layer.end())
                if (Status added = plan.addPlane(*mask); !added)
                    return added.takeError();
        }
    for (const char* key : {"base", "base_metallic_roughness"})
        if (const auto entries = paintLayers.find(key);
            entries != paintLayers.end() && entries->is_array())
            for (const Json& entry : *entries)
                if (Status added = plan.addPage(entry); !added)
                    return added.takeError();
    return plan;
}

} // namespace

Status readPaintLayerImages(const std::string& path, const Json& paintLayers,
                            const LoadLimits& limits, Mesh& mesh, SavedPaintLayers& saved,
                            GlbImageLoader loadImages) {
    // The page sizes the planes were saved with are the model's first textures (its base colour
    // textures), in order; its other maps' textures follow them.
    std::vector<PageSize> pages;
    const auto sizes = paintLayers.find("pages");
    if (sizes == paintLayers.end() || !sizes->is_array() || sizes->size() > mesh.textures.size())
        return Error{"the paint layers' textures do not match the model's (" +
                     std::to_string(mesh.textures.size()) + " textures)"};
    for (std::size_t p = 0; p < sizes->size(); ++p) {
        const Json& s = (*sizes)[p];
        if (!s.is_array() || s.size() != 2 || s[0] != mesh.textures[p].width ||
            s[1] != mesh.textures[p].height)
            return Error{"the paint layers' texture " + std::to_string(p) +
                         " does not match the model's in size"};
        pages.push_back({mesh.textures[p].width, mesh.textures[p].height});
    }

    Result<std::vector<int>> views = imageViews(paintLayers);
    if (!views)
        return views.takeError();
    Result<ImagePlan> plan = planImages(paintLayers, pages, views->size(), saved.layers.size());
    if (!plan)
        return Error{"the paint layers' " + plan.error(), ErrorKind::BadInput};
    const std::uint64_t budget =
        limits.maxPaintLayerBytes ? limits.maxPaintLayerBytes : physicalMemory() / 2;
    if (budget > 0 && plan->bytes() > budget)
        return Error{"too large for this machine's memory (its paint layers need " +
                         mebibytes(plan->bytes()) + ", at most " + mebibytes(budget) +
                         " may be used)",
                     ErrorKind::BadInput};
    Result<std::vector<Image>> decoded = loadImages(path, plan->requests(*views), limits);
    if (!decoded)
        return Error{withoutFileName(path, decoded.error()), decoded.errorKind()};
    const std::vector<Image> images = plan->place(std::move(decoded).value());

    const PlaneReader reader(pages, images);
    const auto layersIt = paintLayers.find("layers");
    const Json layers =
        layersIt != paintLayers.end() && layersIt->is_array() ? *layersIt : Json::array();
    for (std::size_t i = 0; i < saved.layers.size() && i < layers.size(); ++i) {
        SavedPaintLayer& layer = saved.layers[i];
        const std::string name = "paint layer \"" + printable(layer.settings.name) + "\"";
        if (const auto channels = layers[i].find("channels"); channels != layers[i].end()) {
            if (!channels->is_object())
                return Error{name + ": its channels are not a JSON object"};
            for (std::size_t c = 0; c < kPaintChannels; ++c) {
                const auto plane = channels->find(kChannelNames[c]);
                if (plane == channels->end())
                    continue;
                auto read = reader.read(*plane, channelTexelBytes(PaintChannel(c)));
                if (!read)
                    return Error{name + ": its " + kChannelNames[c] + " channel " + read.error()};
                layer.channels[c] = std::move(read).value();
            }
        }
        if (const auto mask = layers[i].find("mask"); mask != layers[i].end()) {
            auto read = reader.read(*mask, 1);
            if (!read)
                return Error{name + ": its mask " + read.error()};
            layer.mask = std::move(read).value();
        }
    }

    if (const auto base = paintLayers.find("base"); base != paintLayers.end() && base->is_array()) {
        for (const Json& entry : *base) {
            const auto p = entry.is_object() ? whole(entry, "page", 0, (long long)pages.size() - 1)
                                             : std::nullopt;
            const auto img = entry.is_object()
                                 ? whole(entry, "image", 0, (long long)images.size() - 1)
                                 : std::nullopt;
            if (!p || !img || images[std::size_t(*img)].width != pages[std::size_t(*p)].width ||
                images[std::size_t(*img)].height != pages[std::size_t(*p)].height)
                return Error{"the base under the paint layers does not fit the model's textures"};
            mesh.textures[std::size_t(*p)] = images[std::size_t(*img)];
            if (std::size_t(*p) < mesh.textureSources.size())
                mesh.textureSources[std::size_t(*p)] = {}; // no longer the file's image
        }
    }
    return readBaseMetallicRoughness(paintLayers, pages, images, saved);
}

} // namespace core
