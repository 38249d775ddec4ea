// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/tools/region_tools.h"

#include <QAction>
#include <QKeySequence>
#include <QSettings>

#include <utility>

#include "core/document/document.h"
#include "ui/panels/hidden_regions_panel.h"
#include "ui/view/viewport.h"

namespace ui {

namespace {
const QString kAutoPopUpKey = QStringLiteral("regions/autoPopUp");
const QString kTransparencyKey = QStringLiteral("regions/seeThroughPopUps");
const QString kOrbitKey = QStringLiteral("regions/orbitAboutSurface");

glm::vec2 toVec(QPointF p) {
    return {float(p.x()), float(p.y())};
}

QAction* makeToggle(const QString& text, const QString& name, const QString& tip,
                    const QString& key, bool fallback, QObject* parent) {
    auto* action = new QAction(text, parent);
    action->setObjectName(name);
    action->setCheckable(true);
    action->setChecked(QSettings().value(key, fallback).toBool());
    action->setStatusTip(tip);
    action->setToolTip(tip);
    QObject::connect(action, &QAction::toggled, parent,
                     [key](bool on) { QSettings().setValue(key, on); });
    return action;
}
} // namespace

RegionTools::RegionTools(core::Document& document, Viewport& viewport,
                         std::function<bool()> ensureDepthLayers, QObject* parent)
    : QObject(parent), m_document(document), m_viewport(viewport),
      m_ensureDepthLayers(std::move(ensureDepthLayers)) {
    m_autoPopUp = makeToggle(tr("&Automatic Pop-up"), QStringLiteral("actionAutoPopUp"),
                             tr("While painting layer-aware, bring the surface under the brush "
                                "to the front when it goes behind another"),
                             kAutoPopUpKey, true, this);
    m_document.setAutoPopUp(m_autoPopUp->isChecked());
    connect(m_autoPopUp, &QAction::toggled, this, [this](bool on) { m_document.setAutoPopUp(on); });

    m_transparency = makeToggle(tr("&See-Through Pop-ups"), QStringLiteral("actionSeeThrough"),
                                tr("Draw popped-up and revealed regions half transparent, so "
                                   "what surrounds them stays visible"),
                                kTransparencyKey, false, this);
    m_viewport.setPopUpTransparency(m_transparency->isChecked());
    connect(m_transparency, &QAction::toggled, &m_viewport, &Viewport::setPopUpTransparency);

    m_orbitAboutSurface = makeToggle(
        tr("Orbit About &Surface Point"), QStringLiteral("actionOrbitAboutSurface"),
        tr("Start an orbit on the model to turn about that point, on whatever depth layer "
           "is shown there"),
        kOrbitKey, true, this);
    m_viewport.setOrbitAboutSurface(m_orbitAboutSurface->isChecked());
    connect(m_orbitAboutSurface, &QAction::toggled, &m_viewport, &Viewport::setOrbitAboutSurface);

    m_resetOrder = new QAction(tr("&Reset Region Order"), this);
    m_resetOrder->setObjectName(QStringLiteral("actionResetOrder"));
    m_resetOrder->setShortcut(QKeySequence(Qt::Key_R));
    m_resetOrder->setStatusTip(
        tr("Show the regions in their original order (depth layer 1 in front)"));
    m_resetOrder->setToolTip(tr("Reset the region order (R)"));
    connect(m_resetOrder, &QAction::triggered, this, [this] {
        if (m_document.resetRegionOrder())
            changed();
    });

    m_unhideAll = new QAction(tr("U&nhide All Regions"), this);
    m_unhideAll->setObjectName(QStringLiteral("actionUnhideAll"));
    m_unhideAll->setShortcut(QKeySequence(Qt::SHIFT | Qt::Key_H));
    m_unhideAll->setToolTip(tr("Show every hidden region again (Shift+H)"));
    connect(m_unhideAll, &QAction::triggered, this, [this] {
        if (m_document.unhideAll())
            changed();
    });
    layersChanged();
}

HiddenRegionsPanel* RegionTools::createPanel(QWidget* parent) {
    m_panel = new HiddenRegionsPanel(parent);
    connect(m_panel, &HiddenRegionsPanel::unhideAllRequested, m_unhideAll, &QAction::trigger);
    connect(m_panel, &HiddenRegionsPanel::unhideRequested, this,
            [this](const std::vector<std::uint32_t>& regions) {
                if (m_document.unhideRegions(regions))
                    changed();
            });
    m_panel->setRegions(m_document.depthLayers(), m_document.regionOrder());
    return m_panel;
}

void RegionTools::popUpAt(QPointF pixel) {
    if (!m_ensureDepthLayers())
        return;
    const std::uint32_t region = m_document.popUpAt(toVec(pixel));
    if (region == core::kNone) {
        emit message(tr("Nothing to pop up here"));
        return;
    }
    changed();
    emit message(tr("Region %1 (depth layer %2) in front; click again to go deeper")
                     .arg(region)
                     .arg(m_document.regionOrder().layerOf(region)));
}

void RegionTools::popUpRegion(std::uint32_t region) {
    if (!m_document.depthLayers())
        return;
    if (m_document.popUpRegion(region))
        changed();
}

void RegionTools::beginHide(QPointF pixel, float radius) {
    endHide();
    if (!m_ensureDepthLayers())
        return;
    // The order at the press decides what the stroke hides: it never drills through what it
    // reveals.
    m_document.beginHide();
    m_hideRadius = radius;
    m_hideLast = pixel;
    moveHide(pixel);
}

bool RegionTools::isHiding() const {
    return m_document.inHide();
}

void RegionTools::moveHide(QPointF pixel) {
    if (!m_document.inHide())
        return;
    if (m_document.hideAlong(toVec(m_hideLast), toVec(pixel), m_hideRadius) > 0)
        orderApplied();
    m_hideLast = pixel;
}

void RegionTools::endHide() {
    if (!m_document.inHide())
        return;
    const std::uint64_t revision = m_document.history().revision();
    m_document.endHide();
    if (m_document.history().revision() != revision) {
        changed();
        emit message(tr("%n region(s) hidden", nullptr,
                        int(m_document.regionOrder().hiddenRegions().size())));
    }
}

void RegionTools::beginStroke() {
    m_inStroke = true;
    m_strokeOrderSerial = m_document.regionOrderSerial();
}

void RegionTools::strokeMoved() {
    if (m_inStroke && m_document.regionOrderSerial() != m_strokeOrderSerial) {
        m_strokeOrderSerial = m_document.regionOrderSerial();
        orderApplied();
    }
}

void RegionTools::endStroke() {
    strokeMoved();
    m_inStroke = false;
}

void RegionTools::layersChanged() {
    m_inStroke = false;
    if (m_panel)
        m_panel->setRegions(m_document.depthLayers(), m_document.regionOrder());
    const bool layers = m_document.depthLayers() != nullptr;
    m_resetOrder->setEnabled(layers);
    m_unhideAll->setEnabled(layers && !m_document.regionOrder().hiddenRegions().empty());
}

void RegionTools::changed() {
    orderApplied();
}

void RegionTools::orderApplied() {
    m_viewport.regionOrderChanged();
    if (m_panel)
        m_panel->setRegions(m_document.depthLayers(), m_document.regionOrder());
    m_unhideAll->setEnabled(m_document.depthLayers() &&
                            !m_document.regionOrder().hiddenRegions().empty());
}

} // namespace ui
