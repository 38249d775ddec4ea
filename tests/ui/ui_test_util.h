// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <algorithm>
#include <cstdlib>
#include <functional>

#include <QApplication>
#include <QImage>
#include <QRgb>
#include <QString>
#include <QTimer>
#include <QWidget>
#include <QWindow>

#include "ui/shell/stall_meter.h"

namespace ui_test {

// Generous: llvmpipe under a loaded CI machine is slow, and a test waits only as long as needed.
inline constexpr int kLoadTimeoutMs = 60000;
inline constexpr int kBuildTimeoutMs = 30000;

/**
 * Runs act on the next modal widget of type T (that accept takes, if given) as soon as it shows:
 * its exec() runs its own event loop meanwhile.
 */
template <typename T>
void onNextModal(std::function<void(T*)> act, std::function<bool(T*)> accept = {}) {
    auto* timer = new QTimer(qApp);
    timer->setInterval(20);
    QObject::connect(timer, &QTimer::timeout, timer, [timer, act, accept] {
        auto* widget = qobject_cast<T*>(QApplication::activeModalWidget());
        if (!widget || !widget->isVisible() || !widget->windowHandle() ||
            !widget->windowHandle()->isExposed() || (accept && !accept(widget)))
            return;
        timer->stop();
        timer->deleteLater();
        act(widget);
    });
    timer->start();
}

/** The application's freeze after which queued presses are dropped, set for one scope. */
class BusyInputMs {
public:
    explicit BusyInputMs(double ms)
        : m_app(dynamic_cast<ui::MeteredApplication*>(QCoreApplication::instance())) {
        if (m_app) {
            m_before = m_app->busyInputMs();
            m_app->setBusyInputMs(ms);
        }
    }
    ~BusyInputMs() {
        if (m_app)
            m_app->setBusyInputMs(m_before);
    }
    BusyInputMs(const BusyInputMs&) = delete;
    BusyInputMs& operator=(const BusyInputMs&) = delete;
    ui::MeteredApplication* app() const { return m_app; }

private:
    ui::MeteredApplication* m_app;
    double m_before = 0.0;
};

/** The title as shown (windowTitle() keeps the "[*]" unsaved-changes placeholder). */
inline QString shownTitle(const QWidget& window) {
    return window.windowHandle() ? window.windowHandle()->title() : QString();
}

/** The largest difference of the red, green and blue channels. */
inline int channelDifference(QRgb a, QRgb b) {
    return std::max({std::abs(qRed(a) - qRed(b)), std::abs(qGreen(a) - qGreen(b)),
                     std::abs(qBlue(a) - qBlue(b))});
}

/** Fraction of pixels that differ (by more than 8 in a channel); 1 for different sizes. */
inline double differingFraction(const QImage& a, const QImage& b) {
    const QImage ra = a.convertToFormat(QImage::Format_RGB32);
    const QImage rb = b.convertToFormat(QImage::Format_RGB32);
    if (ra.size() != rb.size())
        return 1.0;
    qint64 count = 0;
    for (int y = 0; y < ra.height(); ++y)
        for (int x = 0; x < ra.width(); ++x)
            count += channelDifference(ra.pixel(x, y), rb.pixel(x, y)) > 8 ? 1 : 0;
    return double(count) / double(qint64(ra.width()) * ra.height());
}

} // namespace ui_test
