// SPDX-License-Identifier: GPL-3.0-or-later
// The paint layers of a project: their structure as JSON under extras.layerpaint.paint_layers,
// taken from a document and put back into one. The planes' texels travel as images in the file
// (core/io/project/project_file.cpp); here they are copies of the stack's planes.
#include <algorithm>
#include <cmath>
#include <set>

#include "core/base/color.h"
#include "core/base/text.h"
#include "core/document/document.h"
#include "core/document/project_state.h"

namespace core {

namespace {

using Json = nlohmann::json;

const char* kindName(PaintLayerKind kind) {
    return kind == PaintLayerKind::Fill ? "fill" : "paint";
}

void warn(std::vector<std::string>* warnings, const std::string& where, const std::string& what) {
    if (warnings)
        warnings->push_back(where + " " + what + "; the default is used");
}

bool unitNumber(const Json& j, float& out) {
    if (!j.is_number())
        return false;
    const double v = j.get<double>();
    if (!std::isfinite(v) || v < 0.0 || v > 1.0)
        return false;
    out = static_cast<float>(v);
    return true;
}

} // namespace

Json paintLayersToJson(const SavedPaintLayers& saved) {
    Json layers = Json::array();
    for (const SavedPaintLayer& layer : saved.layers) {
        const PaintLayerSettings& s = layer.settings;
        Json fill = Json::object();
        if (s.fill.baseColor) // linear, as every colour of the file
            fill["base_color"] = {decodeSrgb(double(s.fill.baseColor->x)),
                                  decodeSrgb(double(s.fill.baseColor->y)),
                                  decodeSrgb(double(s.fill.baseColor->z))};
        if (s.fill.roughness)
            fill["roughness"] = *s.fill.roughness;
        if (s.fill.metallic)
            fill["metallic"] = *s.fill.metallic;
        layers.push_back({{"id", layer.id},
                          {"name", s.name},
                          {"kind", kindName(s.kind)},
                          {"opacity", s.opacity},
                          {"blend", std::string(blendModeName(s.blend))},
                          {"visible", s.visible},
                          {"lock_transparency", s.lockTransparency},
                          {"fill", std::move(fill)}});
    }
    return {{"layers", std::move(layers)},
            {"selection", {{"layer", saved.selection.layer}, {"mask", saved.selection.mask}}}};
}

Result<SavedPaintLayers> paintLayersFromJson(const Json& j, std::vector<std::string>* warnings) {
    if (!j.is_object())
        return Error{"extras.layerpaint.paint_layers is not a JSON object"};
    SavedPaintLayers saved;
    const auto layers = j.find("layers");
    if (layers != j.end() && !layers->is_array())
        return Error{"extras.layerpaint.paint_layers.layers is not an array"};
    if (layers != j.end() && layers->size() > kMaxPaintLayers)
        return Error{"the project has " + std::to_string(layers->size()) +
                         " paint layers; at most " + std::to_string(kMaxPaintLayers) + " are read",
                     ErrorKind::BadInput};
    std::set<std::uint64_t> ids;
    if (layers != j.end()) {
        for (std::size_t i = 0; i < layers->size(); ++i) {
            const Json& l = (*layers)[i];
            const std::string where =
                "extras.layerpaint.paint_layers.layers[" + std::to_string(i) + "]";
            if (!l.is_object())
                return Error{where + " is not a JSON object"};
            SavedPaintLayer layer;
            const auto id = l.find("id");
            if (id == l.end() || !id->is_number_unsigned() || id->get<std::uint64_t>() == 0 ||
                !ids.insert(id->get<std::uint64_t>()).second)
                return Error{where + ".id is not a unique whole number from 1"};
            layer.id = id->get<std::uint64_t>();
            PaintLayerSettings& s = layer.settings;
            if (const auto v = l.find("name"); v != l.end() && v->is_string())
                s.name = v->get<std::string>();
            else if (v != l.end())
                warn(warnings, where + ".name", "is not text");
            if (const auto v = l.find("kind"); v != l.end()) {
                if (*v == "fill")
                    s.kind = PaintLayerKind::Fill;
                else if (*v != "paint")
                    warn(warnings, where + ".kind", "is neither \"paint\" nor \"fill\"");
            }
            if (const auto v = l.find("opacity"); v != l.end() && !unitNumber(*v, s.opacity))
                warn(warnings, where + ".opacity", "is not a number from 0 to 1");
            if (const auto v = l.find("blend"); v != l.end()) {
                const auto mode =
                    v->is_string() ? blendModeFromName(v->get<std::string>()) : std::nullopt;
                if (mode)
                    s.blend = *mode;
                else
                    warn(warnings, where + ".blend", "is not a blend mode's name");
            }
            for (const auto& [key, flag] : {std::pair{"visible", &s.visible},
                                            std::pair{"lock_transparency", &s.lockTransparency}}) {
                if (const auto v = l.find(key); v != l.end()) {
                    if (v->is_boolean())
                        *flag = v->get<bool>();
                    else
                        warn(warnings, where + "." + key, "is not true or false");
                }
            }
            if (const auto fill = l.find("fill"); fill != l.end() && fill->is_object()) {
                if (const auto c = fill->find("base_color"); c != fill->end()) {
                    glm::vec3 color{0.0f};
                    bool ok = c->is_array() && c->size() == 3;
                    for (int k = 0; ok && k < 3; ++k)
                        ok = unitNumber((*c)[std::size_t(k)], color[k]);
                    if (ok)
                        s.fill.baseColor = glm::vec3(float(encodeSrgb(double(color.x))),
                                                     float(encodeSrgb(double(color.y))),
                                                     float(encodeSrgb(double(color.z))));
                    else
                        warn(warnings, where + ".fill.base_color", "is not three numbers 0..1");
                }
                for (const auto& [key, value] : {std::pair{"roughness", &s.fill.roughness},
                                                 std::pair{"metallic", &s.fill.metallic}}) {
                    if (const auto v = fill->find(key); v != fill->end()) {
                        float f = 0.0f;
                        if (unitNumber(*v, f))
                            *value = f;
                        else
                            warn(warnings, where + ".fill." + key, "is not a number from 0 to 1");
                    }
                }
            }
            saved.layers.push_back(std::move(layer));
        }
    }
    if (const auto sel = j.find("selection"); sel != j.end() && sel->is_object()) {
        const auto layer = sel->find("layer");
        if (layer != sel->end() && layer->is_number_unsigned() &&
            (layer->get<std::uint64_t>() == 0 || ids.contains(layer->get<std::uint64_t>())))
            saved.selection.layer = layer->get<std::uint64_t>();
        else if (layer != sel->end())
            warn(warnings, "extras.layerpaint.paint_layers.selection.layer",
                 "names no paint layer");
        const auto mask = sel->find("mask");
        if (mask != sel->end() && mask->is_boolean())
            saved.selection.mask = saved.selection.layer != 0 && mask->get<bool>();
    }
    return saved;
}

std::shared_ptr<const SavedPaintLayers> capturePaintLayers(const Document& doc) {
    const PaintTarget* current = doc.currentPaintTarget();
    const PaintLayerTarget* target = current ? current->paintLayers() : nullptr;
    return target ? capturePaintLayers(*target) : nullptr;
}

std::shared_ptr<const SavedPaintLayers> capturePaintLayers(const PaintLayerTarget& target) {
    if (target.paintLayerStack().size() == 0)
        return nullptr;
    const PaintLayerStack& stack = target.paintLayerStack();
    auto saved = std::make_shared<SavedPaintLayers>();
    for (std::size_t i = 0; i < stack.size(); ++i) {
        const PaintLayer& layer = stack.layer(i);
        SavedPaintLayer out;
        out.id = layer.id;
        out.settings = layer.settings;
        for (std::size_t c = 0; c < kPaintChannels; ++c)
            if (layer.channels[c])
                out.channels[c] = std::make_shared<const TiledPlane>(*layer.channels[c]);
        if (layer.mask)
            out.mask = std::make_shared<const TiledPlane>(*layer.mask);
        saved->layers.push_back(std::move(out));
    }
    saved->selection = target.selection();
    for (std::uint32_t p = 0; p < stack.pages().size(); ++p) {
        const Image& composite = stack.compositeImage(p);
        Image base;
        if (stack.baseColor(p) != composite.rgba)
            base = Image{composite.width, composite.height, stack.baseColor(p)};
        saved->base.push_back(std::move(base));
        if (stack.hasMaterialChannels()) {
            const Image& mr = stack.compositeMetallicRoughnessImage(p);
            Image baseMr;
            if (stack.baseMetallicRoughness(p) != mr.rgba)
                baseMr = Image{mr.width, mr.height, stack.baseMetallicRoughness(p)};
            saved->baseMetallicRoughness.push_back(std::move(baseMr));
            saved->metallicRoughness.push_back(mr);
        }
    }
    return saved;
}

Status restorePaintLayers(Document& doc, const SavedPaintLayers& saved) {
    if (!doc.currentPaintTarget() || !doc.currentPaintTarget()->paintLayers())
        return Error{"the paint layers need a texture to paint into; they are left out"};
    Result<PaintLayerTarget*> ready = doc.paintLayerTarget();
    if (!ready)
        return ready.takeError();
    return restorePaintLayers(**ready, saved);
}

Status restorePaintLayers(PaintLayerTarget& target, const SavedPaintLayers& saved) {
    PaintLayerStack& stack = target.paintLayerStack();
    const auto fits = [&](const std::shared_ptr<const TiledPlane>& plane, int texelBytes) {
        return !plane || (plane->pages() == stack.pages() && plane->texelBytes() == texelBytes);
    };
    for (const SavedPaintLayer& layer : saved.layers) {
        for (std::size_t c = 0; c < kPaintChannels; ++c) {
            const bool material = c != std::size_t(PaintChannel::BaseColor);
            if (!fits(layer.channels[c], channelTexelBytes(PaintChannel(c))) ||
                (layer.channels[c] && material && !stack.hasMaterialChannels()))
                return Error{"paint layer \"" + printable(layer.settings.name) +
                             "\" does not fit the model's textures"};
        }
        if (!fits(layer.mask, 1))
            return Error{"the mask of paint layer \"" + printable(layer.settings.name) +
                         "\" does not fit the model's textures"};
    }
    for (std::size_t p = 0; p < saved.base.size() && p < stack.pages().size(); ++p) {
        const Image& base = saved.base[p];
        if (!base.empty() && base.rgba.size() == stack.baseColor(std::uint32_t(p)).size())
            stack.baseColor(std::uint32_t(p)) = base.rgba;
    }
    for (std::size_t p = 0; stack.hasMaterialChannels() && p < saved.baseMetallicRoughness.size() &&
                            p < stack.pages().size();
         ++p) {
        const Image& base = saved.baseMetallicRoughness[p];
        if (!base.empty() &&
            base.rgba.size() == stack.baseMetallicRoughness(std::uint32_t(p)).size())
            stack.baseMetallicRoughness(std::uint32_t(p)) = base.rgba;
    }
    while (stack.size() > 0)
        stack.take(stack.size() - 1);
    for (const SavedPaintLayer& savedLayer : saved.layers) {
        auto layer = std::make_unique<PaintLayer>();
        layer->id = savedLayer.id;
        layer->settings = savedLayer.settings;
        for (std::size_t c = 0; c < kPaintChannels; ++c)
            if (savedLayer.channels[c])
                layer->channels[c] = std::make_unique<TiledPlane>(*savedLayer.channels[c]);
        if (savedLayer.mask)
            layer->mask = std::make_unique<TiledPlane>(*savedLayer.mask);
        stack.insert(std::move(layer), stack.size());
    }
    stack.updateAll();
    PaintSelection selection = saved.selection;
    if (selection.layer != 0 && !stack.indexOf(selection.layer))
        selection = {};
    if (selection.mask &&
        (!stack.indexOf(selection.layer) || !stack.layer(*stack.indexOf(selection.layer)).mask))
        selection.mask = false;
    target.setSelection(selection);
    return {};
}

} // namespace core
