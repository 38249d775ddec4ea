// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/shell/stall_meter.h"

#include <QAbstractEventDispatcher>
#include <QDateTime>
#include <QEvent>
#include <QMetaEnum>
#include <QMouseEvent>
#include <QThread>

#include <algorithm>
#include <cstdio>

namespace ui {

namespace {
constexpr std::size_t kMaxKept = 1000; // stalls() keeps the first ones; the log has them all
// What was queued during a freeze arrives within a few event-loop rounds (the window system's
// queue is read, then its events sent); a batch of them is run again, up to a limit, while an
// event in it froze the window again.
constexpr int kDrainRounds = 4;
constexpr int kMaxDrainBatches = 16;
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
    if (QThread::currentThread() != thread())
        return QApplication::notify(receiver, event);
    if (dropsInput(receiver, event)) {
        event->accept(); // handled: no mouse event is made of a dropped pen event
        ++m_droppedInput;
        return true;
    }
    watchDispatcher();
    m_frames.push_back({m_clock.nsecsElapsed(), 0});
    const bool handled = QApplication::notify(receiver, event);
    const Frame frame = m_frames.back();
    m_frames.pop_back();
    const std::int64_t elapsed = m_clock.nsecsElapsed() - frame.startNs;
    if (!m_frames.empty())
        m_frames.back().othersNs += elapsed;
    const double ms = double(elapsed - frame.othersNs) / 1e6;
    if (m_thresholdMs >= 0.0 && ms >= m_thresholdMs)
        record(ms, receiver, event);
    m_busy = m_busy || ms >= m_busyInputMs;
    // Once the outermost event is done, so no widget is half-way through painting.
    if (m_frames.empty() && m_busy && !m_dropping)
        dropQueuedInput();
    return handled;
}

void MeteredApplication::guardFromQueuedInput(QWidget* widget) {
    std::erase_if(m_guarded, [](const QPointer<QWidget>& g) { return g.isNull(); });
    m_guarded.emplace_back(widget);
}

bool MeteredApplication::isGuarded(const QObject* receiver) const {
    if (!receiver || !receiver->isWidgetType())
        return false;
    const auto* widget = static_cast<const QWidget*>(receiver);
    return std::any_of(m_guarded.begin(), m_guarded.end(), [widget](const QPointer<QWidget>& g) {
        return g && (g == widget || g->isAncestorOf(widget));
    });
}

bool MeteredApplication::dropsInput(const QObject* receiver, const QEvent* event) {
    const QEvent::Type type = event->type();
    const bool press = type == QEvent::MouseButtonPress || type == QEvent::MouseButtonDblClick ||
                       type == QEvent::TabletPress;
    const bool rest = type == QEvent::MouseMove || type == QEvent::MouseButtonRelease ||
                      type == QEvent::TabletMove || type == QEvent::TabletRelease;
    if ((!press && !rest) || !isGuarded(receiver))
        return false;
    const auto* pointer = static_cast<const QSinglePointEvent*>(event);
    if (press) {
        // A press given while the window was frozen, and everything up to its release; a
        // press of another button during a stroke begun before goes to that stroke.
        if (!m_swallowing)
            m_swallowing = m_dropping && pointer->buttons() == pointer->button();
        return m_swallowing;
    }
    if (!m_swallowing)
        return false; // a stroke begun before goes on with what was given meanwhile
    if (pointer->buttons() != Qt::NoButton)
        return true;
    // Its last release, dropped; or a move with no button held, its release having gone
    // elsewhere: the swallowing ends either way.
    m_swallowing = false;
    return type == QEvent::MouseButtonRelease || type == QEvent::TabletRelease;
}

void MeteredApplication::dropQueuedInput() {
    // The window system's queue is read on its own thread while this one is busy, so what was
    // given meanwhile is waiting now: handled here, the presses for the guarded widgets dropped.
    m_dropping = true;
    const std::size_t before = m_droppedInput;
    QAbstractEventDispatcher* dispatcher = QAbstractEventDispatcher::instance(thread());
    for (int batch = 0; dispatcher && m_busy && batch < kMaxDrainBatches; ++batch) {
        m_busy = false;
        for (int round = 0;
             round < kDrainRounds && dispatcher->processEvents(QEventLoop::AllEvents); ++round) {
        }
    }
    m_dropping = false;
    if (m_log && m_thresholdMs >= 0.0 && m_droppedInput > before)
        std::fprintf(stderr, "layerpaint: %zu mouse or pen events given while busy dropped\n",
                     m_droppedInput - before);
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
