// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/panels/depth_layers_panel.h"

#include <QIcon>
#include <QLabel>
#include <QListWidget>
#include <QLocale>
#include <QPainter>
#include <QPixmap>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/depth/depth_layers.h"
#include "render/depth_compositor.h"

namespace ui {

namespace {
constexpr int kLayerRole = Qt::UserRole + 1;
const QSize kThumbnailSize(88, 50);

/** The compositor's default background, so an empty thumbnail pixel looks like the viewport. */
QRgb backgroundRgb() {
    const glm::vec4 c = render::CompositeOptions{}.background;
    return qRgb(int(c.r * 255.0f + 0.5f), int(c.g * 255.0f + 0.5f), int(c.b * 255.0f + 0.5f));
}

QRgb toRgb(const glm::vec4& c) {
    const auto channel = [](float v) { return int(std::clamp(v, 0.0f, 1.0f) * 255.0f + 0.5f); };
    return qRgb(channel(c.r), channel(c.g), channel(c.b));
}
} // namespace

DepthLayersPanel::DepthLayersPanel(QWidget* parent) : QWidget(parent) {
    m_hint = new QLabel(tr("Depth layers appear when the view stays still."), this);
    m_hint->setObjectName(QStringLiteral("layersHint"));
    m_hint->setWordWrap(true);
    m_hint->setAlignment(Qt::AlignCenter);
    m_hint->setEnabled(false);

    m_list = new QListWidget(this);
    m_list->setObjectName(QStringLiteral("layerList"));
    m_list->setIconSize(kThumbnailSize);
    m_list->setUniformItemSizes(true);
    m_list->setSelectionMode(QAbstractItemView::SingleSelection);
    m_list->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    m_list->setSpacing(1);
    m_list->setToolTip(
        tr("Click a depth layer to see it alone; “All depth layers” shows the whole view."));

    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_list, 1);
    layout->addWidget(m_hint);

    connect(m_list, &QListWidget::currentRowChanged, this, [this](int row) {
        if (m_updating || row < 0)
            return;
        emit layerActivated(std::uint32_t(m_list->item(row)->data(kLayerRole).toUInt()));
    });
    // Clicking the row that is already current still asks for it (e.g. back from another mode).
    connect(m_list, &QListWidget::itemClicked, this, [this](QListWidgetItem* item) {
        if (!m_updating && item == m_list->currentItem())
            emit layerActivated(std::uint32_t(item->data(kLayerRole).toUInt()));
    });
    m_list->setVisible(false);
}

void DepthLayersPanel::setDepthLayers(const core::DepthLayers* layers) {
    if (!layers) {
        m_list->setEnabled(false);
        return;
    }
    rebuild(*layers);
}

void DepthLayersPanel::setThumbnailStyle(ThumbnailStyle style, const core::DepthLayers* layers) {
    if (m_style == style)
        return;
    m_style = style;
    if (layers)
        rebuild(*layers);
}

void DepthLayersPanel::setCurrentLayer(std::uint32_t layer) {
    m_updating = true;
    for (int row = 0; row < m_list->count(); ++row) {
        if (m_list->item(row)->data(kLayerRole).toUInt() == layer) {
            m_list->setCurrentRow(row);
            break;
        }
    }
    m_updating = false;
}

std::uint32_t DepthLayersPanel::currentLayer() const {
    const QListWidgetItem* item = m_list->currentItem();
    return item ? std::uint32_t(item->data(kLayerRole).toUInt()) : 0;
}

int DepthLayersPanel::layerCount() const {
    return std::max(0, m_list->count() - 1);
}

void DepthLayersPanel::rebuild(const core::DepthLayers& layers) {
    const std::uint32_t current = currentLayer();
    const std::vector<std::uint32_t> fragments = layers.stack.fragmentsPerLayer();
    std::vector<std::uint32_t> regions(fragments.size(), 0);
    for (const core::Region& region : layers.segmentation.graph.regions) {
        if (region.layer >= 1 && region.layer <= regions.size())
            ++regions[region.layer - 1];
    }
    const QLocale locale;
    const qreal ratio = devicePixelRatioF();
    const QSize pixels(qRound(kThumbnailSize.width() * ratio),
                       qRound(kThumbnailSize.height() * ratio));
    const auto icon = [&](std::uint32_t layer) {
        QImage image = thumbnail(layers, layer, pixels, m_style);
        image.setDevicePixelRatio(ratio);
        // Centred on a fixed-size canvas so rows line up whatever the view's aspect ratio.
        QPixmap canvas(pixels);
        canvas.setDevicePixelRatio(ratio);
        canvas.fill(Qt::transparent);
        QPainter painter(&canvas);
        const QSizeF logical = QSizeF(image.size()) / ratio;
        painter.drawImage(QPointF((kThumbnailSize.width() - logical.width()) / 2.0,
                                  (kThumbnailSize.height() - logical.height()) / 2.0),
                          image);
        painter.end();
        return QIcon(canvas);
    };

    m_updating = true;
    m_list->clear();
    auto* all = new QListWidgetItem(
        icon(1), tr("All depth layers\nDepth layers: %1\nRegions: %2")
                     .arg(locale.toString(qulonglong(fragments.size())),
                          locale.toString(qulonglong(layers.segmentation.graph.regions.size()))));
    all->setData(kLayerRole, 0u);
    all->setToolTip(tr("The whole view, front to back"));
    m_list->addItem(all);
    for (std::size_t i = 0; i < fragments.size(); ++i) {
        const auto layer = std::uint32_t(i + 1);
        const QString count = locale.toString(qulonglong(fragments[i]));
        auto* item = new QListWidgetItem(
            icon(layer), tr("Depth layer %1\nFragments: %2\nRegions: %3")
                             .arg(locale.toString(layer), count, locale.toString(regions[i])));
        item->setData(kLayerRole, layer);
        item->setToolTip(tr("Show depth layer %1 alone").arg(layer));
        m_list->addItem(item);
    }
    m_updating = false;
    setCurrentLayer(std::min<std::uint32_t>(current, std::uint32_t(fragments.size())));
    m_list->setEnabled(true);
    m_list->setVisible(true);
    m_hint->setVisible(false);
}

QImage DepthLayersPanel::thumbnail(const core::DepthLayers& layers, std::uint32_t layer, QSize size,
                                   ThumbnailStyle style) {
    const core::DepthStack& stack = layers.stack;
    if (stack.width <= 0 || stack.height <= 0 || size.isEmpty())
        return {};
    // The view's aspect ratio inside size.
    const double scale =
        std::min(double(size.width()) / stack.width, double(size.height()) / stack.height);
    const int width = std::max(1, int(std::lround(stack.width * scale)));
    const int height = std::max(1, int(std::lround(stack.height * scale)));
    QImage image(width, height, QImage::Format_RGB32);

    const QRgb background = backgroundRgb();
    const auto& regionOf = layers.segmentation.region;
    const auto sampleColor = [&](int x, int y) -> QRgb {
        const std::size_t pixel = std::size_t(y) * std::size_t(stack.width) + std::size_t(x);
        const std::uint32_t fragment = stack.fragment(pixel, layer);
        if (fragment == core::kNone)
            return background;
        if (style == ThumbnailStyle::Regions && fragment < regionOf.size())
            return toRgb(render::regionColor(regionOf[fragment]));
        // A headlight on the triangle's view-space plane, as the viewport shades.
        const core::SurfaceTriangle* triangle = layers.geometry.find(stack.triangle[fragment]);
        const float facing = triangle ? std::abs(triangle->plane.z) : 1.0f;
        const float light = 0.25f + 0.75f * facing;
        return qRgb(int(205 * light), int(208 * light), int(214 * light));
    };

    // 2 × 2 samples a thumbnail pixel: cheap (a few thousand lookups) and smooth edges.
    for (int ty = 0; ty < height; ++ty) {
        auto* row = reinterpret_cast<QRgb*>(image.scanLine(ty));
        for (int tx = 0; tx < width; ++tx) {
            int r = 0, g = 0, b = 0;
            for (int sy = 0; sy < 2; ++sy) {
                for (int sx = 0; sx < 2; ++sx) {
                    const int x = std::min(stack.width - 1,
                                           int((tx + (sx + 0.5) / 2.0) * stack.width / width));
                    const int y = std::min(stack.height - 1,
                                           int((ty + (sy + 0.5) / 2.0) * stack.height / height));
                    const QRgb c = sampleColor(x, y);
                    r += qRed(c);
                    g += qGreen(c);
                    b += qBlue(c);
                }
            }
            row[tx] = qRgb(r / 4, g / 4, b / 4);
        }
    }
    return image;
}

} // namespace ui
