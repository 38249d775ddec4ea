// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/shell/stall_meter.h"

#include <QAbstractEventDispatcher>
#include <QDateTime>
#include <QEvent>
#include <QMetaEnum>
#include <QThread>

#include <cstdio>

namespace ui {

namespace {
constexpr std::size_t kMaxKept = 1000; // stalls() keeps the first ones; the log has them all
} // namespace

MeteredApplication::MeteredApplication(int& argc, char** argv) : QApplication(argc, argv) {
    m_clock.start();
}

double MeteredApplication::thresholdFromEnvironment() {
    bool ok = false;
    const double ms = qEnvironmentVariable("LAYERPAINT_STALL_MS").toDouble(&ok);
    return ok && ms >= 0.0 ? ms : -1.0;
}

void MeteredApplication::watchDispatcher() {
    // Time a nested event loop spends waiting for events is nobody's: taken out of the frame
    // that runs the loop.
    QAbstractEventDispatcher* dispatcher = QAbstractEventDispatcher::instance(thread());
    if (!dispatcher || dispatcher == m_watched)
        return;
    m_watched = dispatcher;
    connect(dispatcher, &QAbstractEventDispatcher::aboutToBlock, this,
            [this] { m_blockedSinceNs = m_clock.nsecsElapsed(); });
    connect(dispatcher, &QAbstractEventDispatcher::awake, this, [this] {
        if (m_blockedSinceNs >= 0 && !m_frames.empty())
            m_frames.back().othersNs += m_clock.nsecsElapsed() - m_blockedSinceNs;
        m_blockedSinceNs = -1;
    });
}

bool MeteredApplication::notify(QObject* receiver, QEvent* event) {
    if (m_thresholdMs < 0.0 || QThread::currentThread() != thread())
        return QApplication::notify(receiver, event);
    watchDispatcher();
    m_frames.push_back({m_clock.nsecsElapsed(), 0});
    const bool handled = QApplication::notify(receiver, event);
    const Frame frame = m_frames.back();
    m_frames.pop_back();
    const std::int64_t elapsed = m_clock.nsecsElapsed() - frame.startNs;
    if (!m_frames.empty())
        m_frames.back().othersNs += elapsed;
    const double ms = double(elapsed - frame.othersNs) / 1e6;
    if (ms >= m_thresholdMs)
        record(ms, receiver, event);
    return handled;
}

void MeteredApplication::record(double ms, const QObject* receiver, const QEvent* event) {
    Stall stall;
    stall.ms = ms;
    const char* type = QMetaEnum::fromType<QEvent::Type>().valueToKey(event->type());
    stall.event = type ? QString::fromLatin1(type) : QString::number(int(event->type()));
    stall.receiver =
        receiver ? QString::fromLatin1(receiver->metaObject()->className()) : QString();
    if (receiver && !receiver->objectName().isEmpty())
        stall.receiver += QStringLiteral(" (%1)").arg(receiver->objectName());
    // A timer or helper object says little by itself: whose it is.
    if (receiver && receiver->parent() && !receiver->isWidgetType())
        stall.receiver += QStringLiteral(" in %1").arg(
            QString::fromLatin1(receiver->parent()->metaObject()->className()));
    if (m_log)
        std::fprintf(stderr, "layerpaint: stall %.0f ms at %.3f: %s to %s\n", ms,
                     double(QDateTime::currentMSecsSinceEpoch()) / 1e3 - ms / 1e3,
                     qPrintable(stall.event), qPrintable(stall.receiver));
    if (m_stalls.size() < kMaxKept)
        m_stalls.push_back(std::move(stall));
}

} // namespace ui
