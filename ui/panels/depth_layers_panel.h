// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstdint>

#include <QImage>
#include <QSize>
#include <QWidget>

class QLabel;
class QListWidget;

namespace core {
struct DepthLayers;
}

namespace ui {

/**
 * The Depth Layers panel: an "All depth layers" row, then one row per depth layer with a thumbnail
 * and its fragment and region counts. Choosing a row asks for that layer alone (layerActivated()).
 */
class DepthLayersPanel : public QWidget {
    Q_OBJECT

public:
    /** What the thumbnails show: the shaded layer, or its regions in their map colours. */
    enum class ThumbnailStyle { Shaded, Regions };

    explicit DepthLayersPanel(QWidget* parent = nullptr);

    /**
     * Shows the rows of layers. nullptr means the layers are out of date (the view moves): the
     * old rows stay, greyed out, until the next call.
     */
    void setDepthLayers(const core::DepthLayers* layers);
    /** Changes the thumbnails' style, redrawing them from layers (may be null). */
    void setThumbnailStyle(ThumbnailStyle style, const core::DepthLayers* layers);
    ThumbnailStyle thumbnailStyle() const { return m_style; }
    /** Selects the row of a layer (1-based; 0 = all layers) without emitting layerActivated(). */
    void setCurrentLayer(std::uint32_t layer);
    /** The selected row's layer; 0 = all layers. */
    std::uint32_t currentLayer() const;
    /** Rows of depth layers (without the "All depth layers" row). */
    int layerCount() const;

    /**
     * A thumbnail of one layer (1-based) of at most size, with the view's aspect ratio; pixels
     * without a fragment on that layer show the viewport's background.
     */
    static QImage thumbnail(const core::DepthLayers& layers, std::uint32_t layer, QSize size,
                            ThumbnailStyle style);

signals:
    /** The user chose a row: a layer (1-based) to show alone, or 0 for all layers. */
    void layerActivated(std::uint32_t layer);

private:
    void rebuild(const core::DepthLayers& layers);

    QLabel* m_hint = nullptr;
    QListWidget* m_list = nullptr;
    ThumbnailStyle m_style = ThumbnailStyle::Shaded;
    bool m_updating = false;
};

} // namespace ui
