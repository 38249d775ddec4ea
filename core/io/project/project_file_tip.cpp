// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/io/project/project_file_tip.h"

#include <algorithm>

#include "core/base/text.h"
#include "core/io/export.h"
#include "core/io/image/image_encode.h"

namespace core {

namespace {

using Json = nlohmann::json;

// Where the attachments' view indices go when there are no paint layers to hold them.
constexpr const char* kTipViews = "brush_tip_views";

} // namespace

Status addBrushTipImage(const Brush& brush, Json& layerpaint, GlbAdditions& additions) {
    if (brush.tip != kUserTip || !brush.userTip || brush.userTip->alpha.empty())
        return {};
    const TipImage& tip = *brush.userTip;
    // Stored as a grey picture (dark paints), which is what a user tip file looks like.
    Image image;
    image.width = tip.width;
    image.height = tip.height;
    image.rgba.resize(tip.alpha.size() * 4);
    for (std::size_t i = 0; i < tip.alpha.size(); ++i) {
        const auto v = std::uint8_t(255 - tip.alpha[i]);
        image.rgba[i * 4] = image.rgba[i * 4 + 1] = image.rgba[i * 4 + 2] = v;
        image.rgba[i * 4 + 3] = 255;
    }
    auto png = encodeImage(image, ExportFormat::Png8);
    if (!png)
        return Error{"the brush tip cannot be encoded: " + png.error()};
    if (additions.attachmentsAt.empty())
        additions.attachmentsAt =
            Json::json_pointer("/" + std::string(kProjectExtrasKey) + "/" + kTipViews);
    layerpaint["brush"]["tip_image"] = additions.attachments.size();
    additions.attachments.push_back(std::move(png).value());
    return {};
}

Status readBrushTipImage(const std::string& path, const Json& layerpaint, const LoadLimits& limits,
                         GlbImageLoader loadImages, Brush& brush) {
    const Json* views = nullptr;
    if (const auto pl = layerpaint.find("paint_layers");
        pl != layerpaint.end() && pl->is_object() && pl->contains("images"))
        views = &(*pl)["images"];
    else if (const auto tv = layerpaint.find(kTipViews); tv != layerpaint.end())
        views = &*tv;
    const Json* index = nullptr;
    if (const auto b = layerpaint.find("brush"); b != layerpaint.end() && b->is_object())
        if (const auto t = b->find("tip_image"); t != b->end())
            index = &*t;
    if (!views || !views->is_array() || !index || !index->is_number_unsigned() ||
        index->get<std::uint64_t>() >= views->size())
        return Error{"the brush tip image is missing"};
    const Json& view = (*views)[index->get<std::size_t>()];
    if (!view.is_number_unsigned() || view.get<std::uint64_t>() > 0x7FFFFFFF)
        return Error{"the brush tip image is missing"};
    auto images = loadImages(path, {{int(view.get<std::uint64_t>())}}, limits);
    if (!images)
        return Error{withoutFileName(path, images.error()), images.errorKind()};
    if (images->size() != 1)
        return Error{"the brush tip image is missing"};
    const Image& image = (*images)[0];
    TipImage tip = tipFromRgba(image.width, image.height, image.rgba);
    if (tip.alpha.empty())
        return Error{"the brush tip image is empty"};
    brush.userTip = std::make_shared<const TipImage>(std::move(tip));
    brush.tip = std::string(kUserTip);
    return {};
}

Result<std::shared_ptr<const TipImage>> loadTipImageFile(const std::string& path,
                                                         const LoadLimits& limits) {
    auto image = loadImageFile(path, limits);
    if (!image)
        return image.takeError();
    TipImage tip = tipFromRgba(image->width, image->height, image->rgba);
    if (tip.alpha.empty() ||
        std::all_of(tip.alpha.begin(), tip.alpha.end(), [](std::uint8_t a) { return a == 0; }))
        return Error{path + ": the image is empty or white, so the tip would paint nothing",
                     ErrorKind::BadInput};
    return std::shared_ptr<const TipImage>(std::make_shared<TipImage>(std::move(tip)));
}

} // namespace core
