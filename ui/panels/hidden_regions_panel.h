// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstdint>
#include <vector>

#include <QWidget>

class QListWidget;
class QPushButton;

namespace core {
struct DepthLayers;
class RegionOrder;
} // namespace core

namespace ui {

/**
 * The Paint-to-Hide panel: the regions hidden in this view (colour of the segmentation map,
 * layer, size) with Unhide for the selected ones and Unhide All.
 */
class HiddenRegionsPanel : public QWidget {
    Q_OBJECT

public:
    explicit HiddenRegionsPanel(QWidget* parent = nullptr);

    /** Lists order's hidden regions (layers may be null: nothing is hidden then). */
    void setRegions(const core::DepthLayers* layers, const core::RegionOrder& order);
    /** The listed region ids, in list order. */
    std::vector<std::uint32_t> regions() const;

signals:
    void unhideRequested(const std::vector<std::uint32_t>& regions);
    void unhideAllRequested();

private:
    void updateButtons();

    QListWidget* m_list = nullptr;
    QPushButton* m_unhide = nullptr;
    QPushButton* m_unhideAll = nullptr;
};

} // namespace ui
