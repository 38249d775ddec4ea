// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QHash>
#include <QObject>
#include <QPointer>
#include <QSize>

class QDockWidget;
class QMainWindow;

namespace ui {

/**
 * Gives a main window's docked panels back the size the artist gave them once the window is
 * large enough again. Shrinking a window squeezes its panels along with the central widget, and
 * QMainWindow hands all the room of a later enlargement to the central widget; this restores
 * each panel's width (left and right areas) or height (top and bottom) as last set by the
 * artist (dragging a separator or a panel) or as first shown. Lives as a child of the window.
 */
class DockSizeKeeper : public QObject {
    Q_OBJECT

public:
    explicit DockSizeKeeper(QMainWindow* window);

    /** The size a panel is given back, or 0 before it was first seen docked. */
    int preferredSize(const QDockWidget* dock) const;

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    /** Watches panels added since the last call; remembers sizes of newly seen ones. */
    void watchDocks();
    /** The size of dock across the central widget, or 0 when floating or hidden. */
    int sizeAcross(const QDockWidget* dock) const;
    void restore();

    QMainWindow* m_window;
    QHash<const QDockWidget*, int> m_preferred;
    QHash<const QDockWidget*, QPointer<QDockWidget>> m_watched;
    QSize m_windowSize;
    bool m_restorePending = false;
};

} // namespace ui
