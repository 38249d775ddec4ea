// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/document/document.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include <glm/geometric.hpp>

#include "core/base/text.h"
#include "core/depth/connectivity.h"

namespace core {

Document::Document()
    : m_mesh(std::make_shared<const Mesh>()), m_topology(std::make_shared<const MeshTopology>()) {}

void Document::setMesh(Mesh mesh, std::string name) {
    auto topology = std::make_shared<const MeshTopology>(buildMeshTopology(mesh));
    setMesh(std::move(mesh), std::move(name), std::move(topology));
}

void Document::setMesh(Mesh mesh, std::string name, std::shared_ptr<const MeshTopology> topology) {
    setMesh(std::make_shared<const Mesh>(std::move(mesh)), std::move(name), std::move(topology));
}

void Document::setMesh(std::shared_ptr<const Mesh> mesh, std::string name,
                       std::shared_ptr<const MeshTopology> topology) {
    m_mesh = std::move(mesh);
    m_topology = std::move(topology);
    m_name = std::move(name);
    ++m_meshSerial;
    clearDepthLayers();
    m_paintTarget.reset();
    m_modelTargetRevision.reset();
    ++m_targetSerial;
    m_history.clear();
    m_session.clear();
    resetCamera();
}

void Document::resetCamera() {
    m_camera = Camera{};
    m_camera.frame(m_mesh->bounds(), m_viewAspect, kFrameMargin);
}

void Document::setViewAspect(float aspect) {
    if (aspect > 0.0f && std::isfinite(aspect))
        m_viewAspect = aspect;
}

void Document::clearDepthLayers() {
    if (m_tracker.inStroke())
        endStroke();
    if (m_hideRanks)
        endHide();
    if (m_depthLayers) {
        // The order steps of these layers name regions that are gone with them.
        ++m_depthLayersSerial;
        m_history.dropStaleOrders(m_depthLayersSerial);
    }
    m_tracker.clearDepthLayers();
    m_lineStart.reset(); // pixels of another view
    m_depthLayers.reset();
    m_order = {};
    m_ranks.clear();
    m_fragmentHidden.clear();
    m_tracker.setHiddenFragments({});
}

void Document::layersChanged() {
    m_tracker.setDepthLayers(*m_depthLayers);
    m_order = RegionOrder(m_depthLayers->segmentation.graph);
    ++m_depthLayersSerial;
    m_history.dropStaleOrders(m_depthLayersSerial);
    orderChanged();
    m_tracker.setVisibleFragment([this](std::size_t pixel) { return visibleFragment(pixel); });
}

void Document::setRegionOrder(RegionOrder order) {
    if (!m_depthLayers || order.regionCount() != m_depthLayers->segmentation.graph.regions.size())
        return;
    m_order = std::move(order);
    orderChanged();
}

void Document::orderChanged() {
    m_ranks = m_order.ranks();
    ++m_orderSerial;
    // Hidden regions take no paint: the tracker skips their fragments.
    const std::vector<std::uint32_t>& region = m_depthLayers->segmentation.region;
    const bool anyHidden = std::any_of(m_ranks.begin(), m_ranks.end(),
                                       [](std::uint32_t rank) { return rank == kNone; });
    m_fragmentHidden.clear();
    if (anyHidden) {
        m_fragmentHidden.resize(region.size());
        for (std::size_t f = 0; f < region.size(); ++f)
            m_fragmentHidden[f] = std::uint8_t(m_order.isHidden(region[f]));
    }
    m_tracker.setHiddenFragments(m_fragmentHidden);
}

std::optional<std::size_t> Document::pixelIndex(glm::vec2 pixel) const {
    if (!m_depthLayers)
        return std::nullopt;
    const DepthStack& stack = m_depthLayers->stack;
    // Compared as floats first: converting a huge or NaN float to an integer is undefined.
    if (!(pixel.x >= 0.0f && pixel.y >= 0.0f && pixel.x < float(stack.width) &&
          pixel.y < float(stack.height)))
        return std::nullopt;
    const auto x = std::size_t(pixel.x), y = std::size_t(pixel.y);
    if (x >= std::size_t(stack.width) || y >= std::size_t(stack.height))
        return std::nullopt;
    return y * std::size_t(stack.width) + x;
}

std::uint32_t Document::popUpAt(glm::vec2 pixel) {
    const auto index = pixelIndex(pixel);
    if (!index)
        return kNone;
    m_session.noteState(*this);
    const std::vector<std::uint32_t> regions =
        regionsAtPixel(m_depthLayers->stack, m_depthLayers->segmentation.region, *index);
    RegionOrderState before = m_order.state();
    const std::uint32_t region = m_order.cycleAt(regions);
    if (region != kNone) {
        m_session.add({{"op", "popup"}, {"at", {pixel.x, pixel.y}}});
        orderChanged();
        pushOrderStep(StepKind::PopUp, std::move(before));
    }
    return region;
}

bool Document::popUpRegion(std::uint32_t region) {
    if (region >= m_order.regionCount())
        return false;
    m_session.noteState(*this);
    RegionOrderState before = m_order.state();
    m_order.popUpWithNeighbours(region);
    m_session.add({{"op", "popup"}, {"region", region}});
    orderChanged();
    pushOrderStep(StepKind::PopUp, std::move(before));
    return true;
}

void Document::pushOrderStep(StepKind kind, RegionOrderState before) {
    RegionOrderState after = m_order.state();
    if (after == before)
        return;
    HistoryStep step{kind, {}};
    step.parts.emplace_back(OrderChange{std::move(before), std::move(after), m_depthLayersSerial});
    m_history.push(std::move(step));
}

void Document::beginHide() {
    if (!m_depthLayers || m_hideRanks)
        return;
    m_session.noteState(*this);
    m_hideRanks = m_ranks;
    m_hideBefore = m_order.state();
    m_session.add({{"op", "hide"}, {"path", nlohmann::json::array()}, {"radius", 0.0f}});
}

std::size_t Document::hideAlong(glm::vec2 a, glm::vec2 b, float radius) {
    if (!m_hideRanks)
        return 0;
    // The session's hide operation: a path of the stroke's points (its first segment from a).
    nlohmann::json& op = m_session.last();
    if (op["path"].empty())
        op["path"].push_back({a.x, a.y});
    op["path"].push_back({b.x, b.y});
    op["radius"] = radius;
    return hideAlong(a, b, radius, *m_hideRanks);
}

void Document::endHide() {
    if (!m_hideRanks)
        return;
    m_hideRanks.reset();
    pushOrderStep(StepKind::Hide, std::move(m_hideBefore));
}

bool Document::unhideRegions(std::span<const std::uint32_t> regions) {
    if (!m_depthLayers)
        return false;
    m_session.noteState(*this);
    RegionOrderState before = m_order.state();
    nlohmann::json ids = nlohmann::json::array();
    for (const std::uint32_t region : regions) {
        if (m_order.isHidden(region)) {
            m_order.unhide(region);
            ids.push_back(region);
        }
    }
    if (ids.empty())
        return false;
    m_session.add({{"op", "unhide"}, {"regions", std::move(ids)}});
    orderChanged();
    pushOrderStep(StepKind::Unhide, std::move(before));
    return true;
}

bool Document::unhideAll() {
    if (!m_depthLayers || m_order.hiddenRegions().empty())
        return false;
    m_session.noteState(*this);
    RegionOrderState before = m_order.state();
    m_order.unhideAll();
    m_session.add({{"op", "unhide-all"}});
    orderChanged();
    pushOrderStep(StepKind::Unhide, std::move(before));
    return true;
}

bool Document::resetRegionOrder() {
    if (!m_depthLayers)
        return false;
    RegionOrderState before = m_order.state();
    m_order.reset();
    if (m_order.state() == before)
        return false;
    m_session.noteState(*this);
    m_session.add({{"op", "reset-order"}});
    orderChanged();
    pushOrderStep(StepKind::ResetOrder, std::move(before));
    return true;
}

std::size_t Document::hideAlong(glm::vec2 a, glm::vec2 b, float radius,
                                std::span<const std::uint32_t> ranks) {
    if (!m_depthLayers || !(radius >= 0.0f))
        return 0;
    const std::vector<std::uint32_t> regions = visibleRegionsAlong(
        m_depthLayers->stack, m_depthLayers->segmentation.region, ranks, a, b, radius);
    std::size_t hidden = 0;
    for (const std::uint32_t region : regions) {
        if (!m_order.isHidden(region)) {
            m_order.hide(region);
            ++hidden;
        }
    }
    if (hidden > 0)
        orderChanged();
    return hidden;
}

std::optional<glm::vec3> Document::surfacePoint(glm::vec2 pixel) const {
    const auto index = pixelIndex(pixel);
    if (!index)
        return std::nullopt;
    const std::uint32_t fragment = visibleFragment(*index);
    if (fragment == kNone)
        return std::nullopt;
    const DepthStack& stack = m_depthLayers->stack;
    const glm::vec2 centre(float(*index % std::size_t(stack.width)) + 0.5f,
                           float(*index / std::size_t(stack.width)) + 0.5f);
    return m_depthLayers->view.unproject(centre, stack.depth[fragment]);
}

std::uint32_t Document::visibleFragment(std::size_t pixel) const {
    if (!m_depthLayers)
        return kNone;
    if (m_shownLayer > 0) {
        if (pixel >= m_depthLayers->stack.pixelCount())
            return kNone;
        const std::uint32_t fragment = m_depthLayers->stack.fragment(pixel, m_shownLayer);
        const std::vector<std::uint32_t>& region = m_depthLayers->segmentation.region;
        if (fragment == kNone || fragment >= region.size() || region[fragment] >= m_ranks.size() ||
            m_ranks[region[fragment]] == kNone)
            return kNone;
        return fragment;
    }
    return visibleFragmentByRank(m_depthLayers->stack, m_depthLayers->segmentation.region, m_ranks,
                                 pixel);
}

std::optional<glm::vec4> Document::pickColor(std::size_t pixel) {
    if (!m_depthLayers || pixel >= m_depthLayers->stack.pixelCount())
        return std::nullopt;
    const std::uint32_t fragment = visibleFragment(pixel);
    if (fragment == kNone)
        return std::nullopt;
    const std::uint32_t triangle = m_depthLayers->stack.triangle[fragment];
    if (triangle >= m_mesh->triangleCount())
        return std::nullopt;
    PaintTarget* target = paintTarget();
    if (!target)
        return std::nullopt;
    // Where the ray through the pixel centre meets the triangle's plane, in view space, as
    // barycentric weights. The capture covered this pixel centre with this triangle, so the
    // point lies on it (up to rounding; colorAt drops small negative weights).
    const View& view = m_depthLayers->view;
    const int width = m_depthLayers->stack.width;
    const float px = float(pixel % std::size_t(width)) + 0.5f;
    const float py = float(pixel / std::size_t(width)) + 0.5f;
    const PixelRays rays = PixelRays::fromView(view);
    const glm::dvec3 origin(rays.origin(px, py)), direction(rays.direction(px, py));
    glm::dvec3 corner[3];
    for (int c = 0; c < 3; ++c) {
        const glm::vec3& p =
            m_mesh->positions[m_mesh->indices[3 * std::size_t(triangle) + std::size_t(c)]];
        corner[c] = glm::dvec3(view.view * glm::vec4(p, 1.0f));
    }
    const glm::dvec3 e1 = corner[1] - corner[0], e2 = corner[2] - corner[0];
    const glm::dvec3 normal = glm::cross(e1, e2);
    const double area2 = glm::dot(normal, normal);
    const double along = glm::dot(normal, direction);
    glm::vec3 weights(1.0f / 3.0f);
    if (area2 > 0.0 && along != 0.0) {
        const double t = glm::dot(normal, corner[0] - origin) / along;
        const glm::dvec3 hit = origin + t * direction;
        const glm::dvec3 d = hit - corner[0];
        const double w1 = glm::dot(glm::cross(d, e2), normal) / area2;
        const double w2 = glm::dot(glm::cross(e1, d), normal) / area2;
        weights = glm::vec3(float(1.0 - w1 - w2), float(w1), float(w2));
    }
    return target->colorAt(triangle, weights);
}

void Document::setDepthLayerOptions(const DepthLayerOptions& options) {
    const bool recapture = options.cullBackFaces != m_depthLayerOptions.cullBackFaces;
    m_depthLayerOptions = options;
    if (recapture) {
        clearDepthLayers();
    } else if (m_depthLayers) {
        if (m_tracker.inStroke())
            endStroke();
        resegmentDepthLayers(*m_depthLayers, *m_mesh, m_depthLayerOptions, m_engine);
        layersChanged();
    }
}

Status Document::buildDepthLayers(DepthCapturer& capturer, const View& view) {
    auto layers =
        core::buildDepthLayers(capturer, *m_mesh, *m_topology, view, m_depthLayerOptions, m_engine);
    if (!layers)
        return layers.takeError();
    clearDepthLayers();
    m_depthLayers = std::make_unique<DepthLayers>(std::move(layers).value());
    layersChanged();
    return {};
}

bool Document::adoptLayers(DepthLayers layers, std::uint64_t meshSerial) {
    const DepthLayerOptions& o = layers.options;
    if (meshSerial != m_meshSerial || o.cullBackFaces != m_depthLayerOptions.cullBackFaces)
        return false;
    const bool resegment =
        o.threshold != m_depthLayerOptions.threshold || o.test != m_depthLayerOptions.test;
    clearDepthLayers();
    m_depthLayers = std::make_unique<DepthLayers>(std::move(layers));
    // The threshold may have moved while the worker ran: bring the result up to date.
    if (resegment)
        resegmentDepthLayers(*m_depthLayers, *m_mesh, m_depthLayerOptions, m_engine);
    layersChanged();
    return true;
}

Result<PaintTarget*> Document::ensurePaintTarget() {
    if (!m_paintTarget) {
        auto target = makePaintTargetWithLayout(m_mesh, m_topology, m_paintOptions);
        if (!target)
            return target.takeError();
        m_paintTarget = std::move(target).value();
        ++m_targetSerial;
    }
    return m_paintTarget.get();
}

PaintTarget* Document::paintTarget() {
    Result<PaintTarget*> target = ensurePaintTarget();
    return target ? *target : nullptr;
}

PaintTargetKind Document::paintTargetKind() const {
    if (m_paintTarget)
        return m_paintTarget->kind();
    if (m_paintOptions.kind)
        return *m_paintOptions.kind;
    return m_mesh->hasUvs() ? PaintTargetKind::Texture : PaintTargetKind::VertexColors;
}

Status Document::setPaintTarget(const PaintTargetOptions& options, const ProgressFn& progress) {
    auto target = makePaintTargetWithLayout(m_mesh, m_topology, options, progress);
    if (!target)
        return target.takeError();
    forgetUntouchedModelTarget();
    installPaintTarget(std::move(target).value(), options);
    return {};
}

Status Document::adoptPaintTarget(std::unique_ptr<PaintTarget> target,
                                  const PaintTargetOptions& options, std::uint64_t meshSerial) {
    if (!target || meshSerial != m_meshSerial ||
        target->mesh().triangleCount() != m_mesh->triangleCount() ||
        (!needsUvLayout(*m_mesh, options) && &target->mesh() != m_mesh.get()))
        return Error{"the paint target was made for another model"};
    forgetUntouchedModelTarget();
    installPaintTarget(std::move(target), options);
    return {};
}

void Document::forgetUntouchedModelTarget() {
    // Chosen away before anything was done with it: as if it had not been made yet (it stood for
    // the one the first stroke would have made), so the choice is no undo step either.
    if (m_modelTargetRevision && *m_modelTargetRevision == m_history.revision())
        m_paintTarget.reset();
}

PaintTargetKind Document::suggestedPaintTargetKind() const {
    return defaultTargetKind(*m_mesh, Brush{}.radius);
}

Status Document::adoptModelPaintTarget(std::unique_ptr<PaintTarget> target,
                                       const PaintTargetOptions& options) {
    if (m_paintTarget)
        return Error{"the model has a paint target already"};
    if (Status s = adoptPaintTarget(std::move(target), options, m_meshSerial); !s)
        return s;
    m_modelTargetRevision = m_history.revision();
    return {};
}

void Document::installPaintTarget(std::unique_ptr<PaintTarget> target,
                                  const PaintTargetOptions& options, nlohmann::json operation) {
    if (m_tracker.inStroke())
        endStroke();
    m_modelTargetRevision.reset();
    if (m_paintTarget) {
        m_session.noteState(*this);
        if (operation.is_null()) {
            const bool colours = target->kind() == PaintTargetKind::VertexColors;
            operation = {{"op", "set-target"},
                         {"kind", colours ? "vertex-colors" : "texture"},
                         {"resolution", options.resolution}};
            if (options.automaticUvs)
                operation["automatic_uvs"] = true;
        }
        m_session.add(std::move(operation));
        HistoryStep step{StepKind::PaintTarget, {}};
        step.parts.emplace_back(TargetSwap{std::move(m_paintTarget), m_paintOptions});
        m_history.push(std::move(step));
    }
    m_paintOptions = options;
    m_paintTarget = std::move(target);
    ++m_targetSerial;
}

Result<PaintTarget*> Document::readyToPaint() {
    if (!m_depthLayers)
        return Error{"the layers of this view are not built yet"};
    if (const PaintLayer* fill = selectedFillLayer())
        return Error{"\"" + printable(fill->settings.name) +
                         "\" is a fill layer, the same everywhere: paint its mask to shape it, or "
                         "a paint layer",
                     ErrorKind::BadInput};
    Result<PaintTarget*> target = ensurePaintTarget();
    if (target && m_tracker.inStroke())
        endStroke();
    return target;
}

Status Document::beginStroke(const StrokePoint& point, PaintChanges& changes) {
    changes.clear();
    Result<PaintTarget*> ready = readyToPaint();
    if (!ready)
        return ready.takeError();
    PaintTarget* target = *ready;
    m_session.noteState(*this);
    m_session.strokePoint(point);
    m_strokeOrderBefore = m_order.state();
    m_dabs.clear();
    m_strokeEnd.reset();
    const StrokePoint start = m_stabilizer.begin(curved(point), m_brush);
    m_tracker.startStroke(start, m_brush, m_dabs);
    target->beginStroke(m_brush);
    startSymmetry();
    paintDabs(changes);
    return {};
}

void Document::moveStroke(const StrokePoint& point, PaintChanges& changes) {
    changes.clear();
    if (!m_tracker.inStroke() || !m_paintTarget)
        return;
    m_session.strokePoint(point);
    m_dabs.clear();
    if (const std::optional<StrokePoint> tip = m_stabilizer.move(curved(point)))
        m_tracker.moveStroke(*tip, m_dabs);
    paintDabs(changes);
}

StrokePoint Document::curved(StrokePoint point) const {
    point.pressure = m_pressureCurve.apply(point.pressure);
    return point;
}

void Document::paintDabs(PaintChanges& changes) {
    const auto start = std::chrono::steady_clock::now();
    if (!m_dabs.empty())
        m_strokeEnd = LineStart{m_dabs.back().center, m_dabs.back().layer};
    for (const Dab& dab : m_dabs) {
        if (m_autoPopUp && m_tracker.layerAware())
            popUpUnder(dab);
        if (m_copiesPaint)
            m_paintTarget->beginDabGroup();
        const PaintChanges& dabChanges = m_paintTarget->paint(*m_depthLayers, dab);
        changes.texels.insert(changes.texels.end(), dabChanges.texels.begin(),
                              dabChanges.texels.end());
        changes.vertices.insert(changes.vertices.end(), dabChanges.vertices.begin(),
                                dabChanges.vertices.end());
        if (m_copiesPaint)
            paintCopies(dab, changes);
    }
    m_dabStats = {m_dabs.size(), std::chrono::duration<double, std::milli>(
                                     std::chrono::steady_clock::now() - start)
                                     .count()};
}

void Document::popUpUnder(const Dab& dab) {
    const auto index = pixelIndex(dab.center);
    if (!index || dab.layer == 0)
        return;
    const std::uint32_t fragment = m_depthLayers->stack.fragment(*index, dab.layer);
    if (fragment == kNone || fragment == visibleFragment(*index))
        return;
    const std::uint32_t region = m_depthLayers->segmentation.region[fragment];
    if (region >= m_order.regionCount() || m_order.isHidden(region))
        return;
    m_order.popUp(region);
    orderChanged();
}

void Document::endStroke() {
    PaintChanges changes;
    endStroke(changes);
}

void Document::endStroke(PaintChanges& changes) {
    changes.clear();
    // Catch-up: the tip goes the rest of the string to where the pointer was released.
    const std::optional<StrokePoint> rest = m_stabilizer.release();
    if (rest && m_tracker.inStroke() && m_paintTarget && m_paintTarget->inStroke() &&
        m_depthLayers) {
        m_dabs.clear();
        m_tracker.moveStroke(*rest, m_dabs);
        paintDabs(changes);
    }
    m_tracker.endStroke();
    m_session.endStroke();
    if (m_strokeEnd)
        m_lineStart = m_strokeEnd;
    m_strokeEnd.reset();
    pushStrokeStep();
}

Status Document::startLine(nlohmann::json op, PaintChanges& changes) {
    changes.clear();
    if (!m_depthLayers)
        return Error{"the layers of this view are not built yet"};
    if (m_tracker.inStroke())
        endStroke();
    m_session.noteState(*this);
    m_session.add(std::move(op));
    return {};
}

Status Document::lineTo(const StrokePoint& point, PaintChanges& changes) {
    if (Status started = startLine(
            {{"op", "line-to"}, {"to", {point.position.x, point.position.y, point.pressure}}},
            changes);
        !started)
        return started;
    if (!m_lineStart)
        return paintLine(point, 0, point, changes);
    const StrokePoint from{m_lineStart->position, point.pressure};
    return paintLine(from, m_lineStart->layer, point, changes);
}

Status Document::line(const StrokePoint& from, const StrokePoint& to, PaintChanges& changes) {
    if (Status started = startLine({{"op", "line"},
                                    {"from", {from.position.x, from.position.y, from.pressure}},
                                    {"to", {to.position.x, to.position.y, to.pressure}}},
                                   changes);
        !started)
        return started;
    return paintLine(from, 0, to, changes);
}

Status Document::paintLine(const StrokePoint& from, std::uint32_t layer, const StrokePoint& to,
                           PaintChanges& changes) {
    Result<PaintTarget*> ready = readyToPaint();
    if (!ready)
        return ready.takeError();
    PaintTarget* target = *ready;
    m_strokeOrderBefore = m_order.state();
    m_strokeEnd.reset();
    m_dabs.clear();
    m_tracker.startStroke(curved(from), m_brush, m_dabs, layer);
    target->beginStroke(m_brush);
    startSymmetry();
    paintDabs(changes);
    m_dabs.clear();
    m_tracker.moveStroke(curved(to), m_dabs);
    paintDabs(changes); // adds to what the first dab painted
    m_tracker.endStroke();
    if (m_strokeEnd)
        m_lineStart = m_strokeEnd;
    m_strokeEnd.reset();
    pushStrokeStep();
    return {};
}

void Document::pushStrokeStep() {
    if (!m_paintTarget || !m_paintTarget->inStroke())
        return;
    // The stroke and the pop-ups it caused are one step.
    HistoryStep step{StepKind::Stroke, {}};
    if (TileUndoRecord record = m_paintTarget->endStroke(); !record.empty())
        step.parts.emplace_back(std::move(record));
    if (m_depthLayers && m_order.state() != m_strokeOrderBefore)
        step.parts.emplace_back(
            OrderChange{std::move(m_strokeOrderBefore), m_order.state(), m_depthLayersSerial});
    m_strokeOrderBefore = {};
    m_history.push(std::move(step));
}

Status Document::fill(glm::vec2 position, FillMode mode, float tolerance, PaintChanges& changes) {
    changes.clear();
    Result<PaintTarget*> ready = readyToPaint();
    if (!ready)
        return ready.takeError();
    PaintTarget* target = *ready;
    const DepthStack& stack = m_depthLayers->stack;
    const auto pixel = pixelIndex(position);
    if (!pixel)
        return {};
    const std::uint32_t fragment = visibleFragment(*pixel);
    if (fragment == kNone || fragment >= stack.fragmentCount())
        return {};
    const std::uint32_t triangle = stack.triangle[fragment];
    m_session.noteState(*this);
    nlohmann::json op = {
        {"op", "fill"}, {"at", {position.x, position.y}}, {"mode", fillModeName(mode)}};
    if (mode == FillMode::Color)
        op["tolerance"] = tolerance;
    m_session.add(std::move(op));

    // The brush's colour and opacity at full weight everywhere it fills.
    Brush brush = m_brush;
    brush.hardness = 1.0f;
    brush.flow = 1.0f;
    brush.eraser = false;
    target->beginStroke(brush);
    switch (mode) {
    case FillMode::Region: {
        const std::uint32_t region = fragment < m_depthLayers->segmentation.region.size()
                                         ? m_depthLayers->segmentation.region[fragment]
                                         : kNone;
        changes =
            target->paint(*m_depthLayers, regionFillDab(*m_depthLayers, region, brush.opacity));
        break;
    }
    case FillMode::Surface:
        changes = target->paintElements(
            triangleElements(*target, componentTriangles(*m_topology, triangle)));
        break;
    case FillMode::Color:
        if (const auto point = surfacePointAt(*m_mesh, m_depthLayers->view, triangle, position))
            changes = target->paintElements(
                similarColorElements(*target, *m_topology, triangle, *point, tolerance));
        break;
    }
    HistoryStep step{StepKind::Fill, {}};
    if (TileUndoRecord record = target->endStroke(); !record.empty())
        step.parts.emplace_back(std::move(record));
    m_history.push(std::move(step));
    return {};
}

void Document::applyStep(HistoryStep& step, bool undo, PaintChanges& changes) {
    const auto apply = [&](StepPart& part) {
        if (auto* record = std::get_if<TileUndoRecord>(&part)) {
            if (m_paintTarget &&
                (undo ? record->undo(*m_paintTarget) : record->redo(*m_paintTarget))) {
                const PaintChanges touched = m_paintTarget->changes(*record);
                changes.texels.insert(changes.texels.end(), touched.texels.begin(),
                                      touched.texels.end());
                changes.vertices.insert(changes.vertices.end(), touched.vertices.begin(),
                                        touched.vertices.end());
            }
        } else if (auto* order = std::get_if<OrderChange>(&part)) {
            if (m_depthLayers && order->depthLayersSerial == m_depthLayersSerial &&
                m_order.setState(undo ? order->before : order->after))
                orderChanged();
        } else if (auto* layerChange = std::get_if<PaintLayerChange>(&part)) {
            applyPaintLayerChange(*layerChange, changes);
        } else if (auto* swap = std::get_if<TargetSwap>(&part)) {
            std::swap(m_paintTarget, swap->other);
            std::swap(m_paintOptions, swap->otherOptions);
            ++m_targetSerial;
        }
    };
    if (undo)
        for (auto it = step.parts.rbegin(); it != step.parts.rend(); ++it)
            apply(*it);
    else
        for (StepPart& part : step.parts)
            apply(part);
}

bool Document::undo(PaintChanges& changes) {
    return walkHistory(true, changes);
}

bool Document::redo(PaintChanges& changes) {
    return walkHistory(false, changes);
}

bool Document::walkHistory(bool undo, PaintChanges& changes) {
    changes.clear();
    if (m_tracker.inStroke())
        endStroke();
    if (m_hideRanks)
        endHide();
    HistoryStep* step = undo ? m_history.nextUndo() : m_history.nextRedo();
    if (!step)
        return false;
    m_session.add({{"op", undo ? "undo" : "redo"}});
    applyStep(*step, undo, changes);
    if (undo)
        m_history.undone();
    else
        m_history.redone();
    return true;
}

Mesh Document::paintedMesh() const {
    return m_paintTarget ? m_paintTarget->paintedMesh() : *m_mesh;
}

} // namespace core
