// SPDX-License-Identifier: GPL-3.0-or-later
// The document's paint-layer operations (docs/architecture.md, "The controller and its history"):
// each builds a PaintLayerChange, applies it to the texture target's stack and records it.
#include <algorithm>
#include <cmath>

#include "core/document/document.h"
#include "core/document/project_state.h"
#include "core/paint/paint_layers/blend_modes.h"

namespace core {

namespace {

nlohmann::json layerRef(std::size_t index) {
    return nlohmann::json(index);
}

const char* kindName(PaintLayerKind kind) {
    return kind == PaintLayerKind::Fill ? "fill" : "paint";
}

/**
 * A fill layer's values as script JSON; a channel the fill leaves alone is missing, or null with
 * `nulls` (so that a change can say it was taken away).
 */
nlohmann::json fillValuesJson(const ChannelValues& v, bool nulls) {
    nlohmann::json values = nlohmann::json::object();
    if (nulls)
        values = {{"base_color", nullptr}, {"roughness", nullptr}, {"metallic", nullptr}};
    if (v.baseColor)
        values["base_color"] = {v.baseColor->x, v.baseColor->y, v.baseColor->z};
    if (v.roughness)
        values["roughness"] = *v.roughness;
    if (v.metallic)
        values["metallic"] = *v.metallic;
    return values;
}

/**
 * The change of an operation that replaced the layers in removed by the one layer now at index
 * (merge down, flatten): that layer goes into held and the removed ones back into the stack, so
 * that applying the change (a swap) does the operation and undoing it puts them back.
 */
PaintLayerChange swapBack(PaintLayerStack& stack, std::size_t index,
                          std::vector<std::unique_ptr<PaintLayer>>& removed) {
    PaintLayerChange change;
    change.kind = PaintLayerChange::Kind::Swap;
    change.index = index;
    change.count = removed.size();
    change.held.push_back(stack.take(index));
    change.selection = {change.held.back()->id, false};
    for (std::size_t i = 0; i < removed.size(); ++i)
        stack.insert(std::move(removed[i]), index + i);
    return change;
}

/** Whether a stack of `layers` paint layers may get one more (a project holds kMaxPaintLayers). */
Status roomForPaintLayer(std::size_t layers) {
    if (layers < kMaxPaintLayers)
        return {};
    return Error{"there are " + std::to_string(layers) + " paint layers already, the most a " +
                     "project can hold; merge or delete some first",
                 ErrorKind::BadInput};
}

} // namespace

const PaintLayer* Document::selectedFillLayer() const {
    const PaintLayerTarget* target = m_paintTarget ? m_paintTarget->paintLayers() : nullptr;
    if (!target || target->selection().mask)
        return nullptr;
    const PaintLayerStack& stack = target->paintLayerStack();
    const std::optional<std::size_t> index = stack.indexOf(target->selection().layer);
    return index && stack.layer(*index).settings.kind == PaintLayerKind::Fill ? &stack.layer(*index)
                                                                              : nullptr;
}

Result<PaintLayerTarget*> Document::paintLayerTarget() {
    Result<PaintTarget*> target = ensurePaintTarget();
    if (!target)
        return target.takeError();
    PaintLayerTarget* layers = (*target)->paintLayers();
    if (!layers)
        return Error{"vertex colours have no paint layers (paint into a texture for them)",
                     ErrorKind::BadInput};
    if (m_tracker.inStroke())
        endStroke();
    return layers;
}

Result<std::size_t> Document::paintLayerIndex(std::uint64_t id) {
    Result<PaintLayerTarget*> target = paintLayerTarget();
    if (!target)
        return target.takeError();
    const std::optional<std::size_t> index = (*target)->paintLayerStack().indexOf(id);
    if (!index)
        return Error{"no paint layer " + std::to_string(id), ErrorKind::BadInput};
    return *index;
}

void Document::applyPaintLayerChange(PaintLayerChange& change, PaintChanges& changes) {
    PaintLayerTarget* target = m_paintTarget ? m_paintTarget->paintLayers() : nullptr;
    if (!target)
        return;
    PaintLayerStack& stack = target->paintLayerStack();
    std::vector<TileKey> tiles;
    const auto covered = [&](const PaintLayer& layer) {
        const std::vector<TileKey> t = stack.tilesCovered(layer);
        tiles.insert(tiles.end(), t.begin(), t.end());
    };
    switch (change.kind) {
    case PaintLayerChange::Kind::Swap: {
        std::vector<std::unique_ptr<PaintLayer>> out;
        for (std::size_t i = 0; i < change.count && change.index < stack.size(); ++i) {
            out.push_back(stack.take(change.index));
            covered(*out.back());
        }
        const std::size_t in = change.held.size();
        for (std::size_t i = 0; i < in; ++i) {
            covered(*change.held[i]);
            stack.insert(std::move(change.held[i]), change.index + i);
        }
        change.held = std::move(out);
        change.count = in;
        break;
    }
    case PaintLayerChange::Kind::Move:
        if (stack.size() > 0) {
            stack.move(change.from, change.to);
            covered(stack.layer(std::min(change.to, stack.size() - 1)));
            std::swap(change.from, change.to);
        }
        break;
    case PaintLayerChange::Kind::Settings:
        if (const auto index = stack.indexOf(change.id)) {
            covered(stack.layer(*index));
            PaintLayerSettings old = stack.layer(*index).settings;
            stack.setSettings(*index, std::move(change.settings));
            change.settings = std::move(old);
            covered(stack.layer(*index));
        }
        break;
    case PaintLayerChange::Kind::Mask:
        if (const auto index = stack.indexOf(change.id)) {
            std::unique_ptr<TiledPlane> old = stack.takeMask(*index);
            stack.setMask(*index, std::move(change.mask));
            change.mask = std::move(old);
            covered(stack.layer(*index));
        }
        break;
    }
    // Selecting is no step of its own, so the selection kept here is the one at the time of the
    // operation (undo) or of its undo (redo); it is checked against the stack all the same.
    const PaintSelection selection = target->selection();
    PaintSelection next = change.selection;
    if (next.layer != 0) {
        const auto index = stack.indexOf(next.layer);
        if (!index)
            next = {stack.size() > 0 ? stack.layer(stack.size() - 1).id : 0, false};
        else if (next.mask && !stack.layer(*index).mask)
            next.mask = false;
    }
    target->setSelection(next);
    change.selection = selection;
    const PaintChanges refreshed = target->refresh(std::move(tiles));
    changes.texels.insert(changes.texels.end(), refreshed.texels.begin(), refreshed.texels.end());
}

void Document::pushPaintLayerChange(PaintLayerChange change, nlohmann::json op,
                                    PaintChanges& changes) {
    m_session.noteState(*this);
    m_session.add(std::move(op));
    applyPaintLayerChange(change, changes);
    HistoryStep step{StepKind::PaintLayers, {}};
    step.parts.emplace_back(std::move(change));
    m_history.push(std::move(step));
}

Result<std::uint64_t> Document::addPaintLayer(PaintLayerSettings settings, PaintChanges& changes) {
    changes.clear();
    Result<PaintLayerTarget*> ready = paintLayerTarget();
    if (!ready)
        return ready.takeError();
    PaintLayerTarget& target = **ready;
    PaintLayerStack& stack = target.paintLayerStack();
    if (Status room = roomForPaintLayer(stack.size()); !room)
        return room.takeError();
    std::size_t index = stack.size();
    if (target.selection().layer == 0)
        index = 0;
    else if (const auto selected = stack.indexOf(target.selection().layer))
        index = *selected + 1;
    settings.opacity =
        std::isfinite(settings.opacity) ? std::clamp(settings.opacity, 0.0f, 1.0f) : 1.0f;
    nlohmann::json op = {
        {"op", "layer-add"}, {"name", settings.name}, {"kind", kindName(settings.kind)}};
    if (settings.kind == PaintLayerKind::Fill)
        op["values"] = fillValuesJson(settings.fill, false);
    index = stack.add(std::move(settings), index);
    PaintLayerChange change;
    change.kind = PaintLayerChange::Kind::Swap;
    change.index = index;
    change.held.push_back(stack.take(index));
    const std::uint64_t id = change.held.back()->id;
    change.selection = {id, false};
    pushPaintLayerChange(std::move(change), std::move(op), changes);
    return id;
}

Result<std::uint64_t> Document::duplicatePaintLayer(std::uint64_t id, PaintChanges& changes) {
    changes.clear();
    Result<std::size_t> index = paintLayerIndex(id);
    if (!index)
        return index.takeError();
    PaintLayerStack& stack = (*paintLayerTarget())->paintLayerStack();
    if (Status room = roomForPaintLayer(stack.size()); !room)
        return room.takeError();
    const std::size_t at = stack.duplicate(*index);
    PaintLayerChange change;
    change.kind = PaintLayerChange::Kind::Swap;
    change.index = at;
    change.held.push_back(stack.take(at));
    const std::uint64_t copy = change.held.back()->id;
    change.selection = {copy, false};
    pushPaintLayerChange(std::move(change),
                         {{"op", "layer-duplicate"}, {"layer", layerRef(*index)}}, changes);
    return copy;
}

Status Document::deletePaintLayer(std::uint64_t id, PaintChanges& changes) {
    changes.clear();
    Result<std::size_t> index = paintLayerIndex(id);
    if (!index)
        return index.takeError();
    PaintLayerTarget& target = **paintLayerTarget();
    PaintLayerChange change;
    change.kind = PaintLayerChange::Kind::Swap;
    change.index = *index;
    change.count = 1;
    change.selection = target.selection();
    if (change.selection.layer == id)
        change.selection = {*index > 0 ? target.paintLayerStack().layer(*index - 1).id : 0, false};
    pushPaintLayerChange(std::move(change), {{"op", "layer-delete"}, {"layer", layerRef(*index)}},
                         changes);
    return {};
}

Status Document::movePaintLayer(std::uint64_t id, std::size_t to, PaintChanges& changes) {
    changes.clear();
    Result<std::size_t> index = paintLayerIndex(id);
    if (!index)
        return index.takeError();
    PaintLayerTarget& target = **paintLayerTarget();
    to = std::min(to, target.paintLayerStack().size() - 1);
    if (to == *index)
        return {};
    PaintLayerChange change;
    change.kind = PaintLayerChange::Kind::Move;
    change.from = *index;
    change.to = to;
    change.selection = target.selection();
    pushPaintLayerChange(std::move(change),
                         {{"op", "layer-move"}, {"layer", layerRef(*index)}, {"index", to}},
                         changes);
    return {};
}

Status Document::setPaintLayerSettings(std::uint64_t id, PaintLayerSettings settings,
                                       PaintChanges& changes) {
    changes.clear();
    Result<std::size_t> index = paintLayerIndex(id);
    if (!index)
        return index.takeError();
    PaintLayerTarget& target = **paintLayerTarget();
    if (!std::isfinite(settings.opacity))
        return Error{"the opacity is not a number", ErrorKind::BadInput};
    settings.opacity = std::clamp(settings.opacity, 0.0f, 1.0f);
    const PaintLayerSettings& old = target.paintLayerStack().layer(*index).settings;
    if (settings == old)
        return {};
    nlohmann::json op = {{"op", "layer-set"}, {"layer", layerRef(*index)}};
    if (settings.name != old.name)
        op["name"] = settings.name;
    if (settings.opacity != old.opacity)
        op["opacity"] = settings.opacity;
    if (settings.blend != old.blend)
        op["blend"] = std::string(blendModeName(settings.blend));
    if (settings.visible != old.visible)
        op["visible"] = settings.visible;
    if (settings.lockTransparency != old.lockTransparency)
        op["lock"] = settings.lockTransparency;
    if (settings.fill != old.fill)
        op["values"] = fillValuesJson(settings.fill, true);
    PaintLayerChange change;
    change.kind = PaintLayerChange::Kind::Settings;
    change.id = id;
    change.settings = std::move(settings);
    change.selection = target.selection();
    pushPaintLayerChange(std::move(change), std::move(op), changes);
    return {};
}

Status Document::mergePaintLayerDown(std::uint64_t id, PaintChanges& changes) {
    changes.clear();
    Result<std::size_t> index = paintLayerIndex(id);
    if (!index)
        return index.takeError();
    if (*index == 0)
        return Error{"the lowest paint layer has no paint layer below to merge into",
                     ErrorKind::BadInput};
    PaintLayerTarget& target = **paintLayerTarget();
    PaintLayerStack& stack = target.paintLayerStack();
    // Merged here, then put back as it was, so the change applies (and undoes) as a swap.
    std::vector<std::unique_ptr<PaintLayer>> removed;
    stack.mergeDown(*index, &removed);
    pushPaintLayerChange(swapBack(stack, *index - 1, removed),
                         {{"op", "layer-merge-down"}, {"layer", layerRef(*index)}}, changes);
    return {};
}

Status Document::flattenPaintLayers(std::string name, PaintChanges& changes) {
    changes.clear();
    Result<PaintLayerTarget*> ready = paintLayerTarget();
    if (!ready)
        return ready.takeError();
    PaintLayerStack& stack = (*ready)->paintLayerStack();
    if (stack.size() == 0)
        return Error{"there are no paint layers to flatten", ErrorKind::BadInput};
    nlohmann::json op = {{"op", "layer-flatten"}, {"name", name}};
    std::vector<std::unique_ptr<PaintLayer>> removed;
    stack.flatten(std::move(name), &removed);
    pushPaintLayerChange(swapBack(stack, 0, removed), std::move(op), changes);
    return {};
}

Status Document::addPaintLayerMask(std::uint64_t id, PaintChanges& changes) {
    changes.clear();
    Result<std::size_t> index = paintLayerIndex(id);
    if (!index)
        return index.takeError();
    const PaintLayerStack& stack = (*paintLayerTarget())->paintLayerStack();
    if (stack.layer(*index).mask)
        return Error{"the paint layer already has a mask", ErrorKind::BadInput};
    PaintLayerChange change;
    change.kind = PaintLayerChange::Kind::Mask;
    change.id = id;
    change.mask = std::make_unique<TiledPlane>(stack.pages(), 1,
                                               std::array<std::uint8_t, 4>{255, 255, 255, 255});
    change.selection = {id, true};
    pushPaintLayerChange(std::move(change), {{"op", "mask-add"}, {"layer", layerRef(*index)}},
                         changes);
    return {};
}

Status Document::deletePaintLayerMask(std::uint64_t id, PaintChanges& changes) {
    changes.clear();
    Result<std::size_t> index = paintLayerIndex(id);
    if (!index)
        return index.takeError();
    PaintLayerTarget& target = **paintLayerTarget();
    if (!target.paintLayerStack().layer(*index).mask)
        return Error{"the paint layer has no mask", ErrorKind::BadInput};
    PaintLayerChange change;
    change.kind = PaintLayerChange::Kind::Mask;
    change.id = id;
    change.selection = target.selection();
    if (change.selection == PaintSelection{id, true})
        change.selection.mask = false;
    pushPaintLayerChange(std::move(change), {{"op", "mask-delete"}, {"layer", layerRef(*index)}},
                         changes);
    return {};
}

Status Document::selectPaint(PaintSelection selection) {
    Result<PaintLayerTarget*> ready = paintLayerTarget();
    if (!ready)
        return ready.takeError();
    PaintLayerTarget& target = **ready;
    if (selection.layer == 0) {
        selection.mask = false;
    } else {
        const auto index = target.paintLayerStack().indexOf(selection.layer);
        if (!index)
            return Error{"no paint layer " + std::to_string(selection.layer), ErrorKind::BadInput};
        if (selection.mask && !target.paintLayerStack().layer(*index).mask)
            return Error{"the paint layer has no mask", ErrorKind::BadInput};
    }
    if (selection == target.selection())
        return {};
    nlohmann::json op = {{"op", selection.mask ? "mask-select" : "layer-select"}};
    if (selection.layer == 0)
        op["layer"] = "base";
    else
        op["layer"] = layerRef(*target.paintLayerStack().indexOf(selection.layer));
    // Logged so a replayed session paints where the user did, but no undo step: clicks on layers
    // would otherwise fill Edit > Undo (an operation's undo restores the selection it had).
    m_session.noteState(*this);
    m_session.add(std::move(op));
    target.setSelection(selection);
    return {};
}

} // namespace core
