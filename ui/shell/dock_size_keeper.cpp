// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/shell/dock_size_keeper.h"

#include <QDockWidget>
#include <QEvent>
#include <QGuiApplication>
#include <QList>
#include <QMainWindow>
#include <QTimer>

namespace ui {

DockSizeKeeper::DockSizeKeeper(QMainWindow* window) : QObject(window), m_window(window) {
    m_window->installEventFilter(this);
    m_windowSize = m_window->size();
}

int DockSizeKeeper::preferredSize(const QDockWidget* dock) const {
    return m_preferred.value(dock, 0);
}

int DockSizeKeeper::sizeAcross(const QDockWidget* dock) const {
    if (!dock->isVisible() || dock->isFloating())
        return 0;
    switch (m_window->dockWidgetArea(const_cast<QDockWidget*>(dock))) {
    case Qt::LeftDockWidgetArea:
    case Qt::RightDockWidgetArea:
        return dock->width();
    case Qt::TopDockWidgetArea:
    case Qt::BottomDockWidgetArea:
        return dock->height();
    default:
        return 0;
    }
}

void DockSizeKeeper::watchDocks() {
    // Only the window's own panels (not docks of a nested window).
    for (QDockWidget* dock : m_window->findChildren<QDockWidget*>(Qt::FindDirectChildrenOnly)) {
        if (!m_watched.contains(dock)) {
            m_watched.insert(dock, dock);
            dock->installEventFilter(this);
        }
        // Seen docked for the first time: its size then is the one to keep.
        if (!m_preferred.contains(dock))
            if (const int size = sizeAcross(dock); size > 0)
                m_preferred.insert(dock, size);
    }
}

bool DockSizeKeeper::eventFilter(QObject* watched, QEvent* event) {
    if (watched == m_window) {
        if (event->type() == QEvent::Resize || event->type() == QEvent::Show) {
            const QSize size = m_window->size();
            const bool grew =
                size.width() > m_windowSize.width() || size.height() > m_windowSize.height();
            m_windowSize = size;
            // After the layout has placed everything at the new size.
            if (grew && !m_restorePending) {
                m_restorePending = true;
                QTimer::singleShot(0, this, &DockSizeKeeper::restore);
            }
        } else if (event->type() == QEvent::LayoutRequest) {
            watchDocks();
        }
    } else if (event->type() == QEvent::Resize) {
        auto* dock = static_cast<QDockWidget*>(watched);
        // The artist drags a separator or a panel: that size is the one to keep. Sizes the
        // window's own resizing gives are not.
        if (QGuiApplication::mouseButtons() != Qt::NoButton && m_window->size() == m_windowSize)
            if (const int size = sizeAcross(dock); size > 0)
                m_preferred.insert(dock, size);
    } else if (event->type() == QEvent::Show) {
        watchDocks();
    }
    return QObject::eventFilter(watched, event);
}

void DockSizeKeeper::restore() {
    m_restorePending = false;
    watchDocks();
    QList<QDockWidget*> across[2]; // horizontal (left and right areas), vertical
    QList<int> sizes[2];
    for (auto it = m_watched.cbegin(); it != m_watched.cend(); ++it) {
        QDockWidget* dock = it.value();
        if (!dock)
            continue;
        const int size = sizeAcross(dock);
        const int preferred = m_preferred.value(dock, 0);
        if (size <= 0 || preferred <= size)
            continue;
        const Qt::DockWidgetArea area = m_window->dockWidgetArea(dock);
        const int axis = area == Qt::LeftDockWidgetArea || area == Qt::RightDockWidgetArea ? 0 : 1;
        across[axis].append(dock);
        sizes[axis].append(preferred);
    }
    // The central widget keeps at least its minimum size: QMainWindow gives what it can.
    if (!across[0].isEmpty())
        m_window->resizeDocks(across[0], sizes[0], Qt::Horizontal);
    if (!across[1].isEmpty())
        m_window->resizeDocks(across[1], sizes[1], Qt::Vertical);
}

} // namespace ui
