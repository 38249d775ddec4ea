// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/panels/hidden_regions_panel.h"

#include <QColor>
#include <QHBoxLayout>
#include <QIcon>
#include <QLabel>
#include <QListWidget>
#include <QPixmap>
#include <QPushButton>
#include <QVBoxLayout>

#include "core/depth/depth_layers.h"
#include "core/regions/region_order.h"
#include "render/depth_compositor.h"

namespace ui {

namespace {
QIcon swatch(std::uint32_t region) {
    const glm::vec4 c = render::regionColor(region);
    QPixmap pixmap(16, 16);
    pixmap.fill(QColor::fromRgbF(c.r, c.g, c.b));
    return QIcon(pixmap);
}
} // namespace

HiddenRegionsPanel::HiddenRegionsPanel(QWidget* parent) : QWidget(parent) {
    auto* layout = new QVBoxLayout(this);
    auto* hint =
        new QLabel(tr("Paint with the Hide tool (H) to hide regions and see behind them."), this);
    hint->setWordWrap(true);
    layout->addWidget(hint);
    m_list = new QListWidget(this);
    m_list->setObjectName(QStringLiteral("hiddenRegionsList"));
    m_list->setSelectionMode(QAbstractItemView::ExtendedSelection);
    layout->addWidget(m_list);
    auto* buttons = new QHBoxLayout;
    m_unhide = new QPushButton(tr("&Unhide"), this);
    m_unhide->setObjectName(QStringLiteral("unhideButton"));
    m_unhide->setToolTip(tr("Show the selected regions again"));
    m_unhideAll = new QPushButton(tr("Unhide &All"), this);
    m_unhideAll->setObjectName(QStringLiteral("unhideAllButton"));
    buttons->addWidget(m_unhide);
    buttons->addWidget(m_unhideAll);
    layout->addLayout(buttons);

    connect(m_unhide, &QPushButton::clicked, this, [this] {
        std::vector<std::uint32_t> chosen;
        for (const QListWidgetItem* item : m_list->selectedItems())
            chosen.push_back(item->data(Qt::UserRole).toUInt());
        if (!chosen.empty())
            emit unhideRequested(chosen);
    });
    connect(m_unhideAll, &QPushButton::clicked, this, &HiddenRegionsPanel::unhideAllRequested);
    connect(m_list, &QListWidget::itemSelectionChanged, this, &HiddenRegionsPanel::updateButtons);
    connect(m_list, &QListWidget::itemDoubleClicked, this, [this](QListWidgetItem* item) {
        emit unhideRequested({item->data(Qt::UserRole).toUInt()});
    });
    updateButtons();
}

void HiddenRegionsPanel::setRegions(const core::DepthLayers* layers,
                                    const core::RegionOrder& order) {
    m_list->clear();
    if (layers) {
        const std::vector<core::Region>& regions = layers->segmentation.graph.regions;
        for (const std::uint32_t id : order.hiddenRegions()) {
            if (id >= regions.size())
                continue;
            auto* item = new QListWidgetItem(
                swatch(id),
                tr("Region %1 · depth layer %2 · %n pixel(s)", nullptr, int(regions[id].pixels))
                    .arg(id)
                    .arg(regions[id].layer),
                m_list);
            item->setData(Qt::UserRole, id);
        }
    }
    updateButtons();
}

std::vector<std::uint32_t> HiddenRegionsPanel::regions() const {
    std::vector<std::uint32_t> ids;
    for (int i = 0; i < m_list->count(); ++i)
        ids.push_back(m_list->item(i)->data(Qt::UserRole).toUInt());
    return ids;
}

void HiddenRegionsPanel::updateButtons() {
    m_unhide->setEnabled(!m_list->selectedItems().isEmpty());
    m_unhideAll->setEnabled(m_list->count() > 0);
}

} // namespace ui
