// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QApplication>
#include <QElapsedTimer>
#include <QPointer>
#include <QString>
#include <QWidget>

#include <cstdint>
#include <vector>

class QAbstractEventDispatcher;

namespace ui {

/** An event the GUI thread took long to handle: what it was and for how long. */
struct Stall {
    double ms = 0.0;
    QString event; // the event's type, e.g. "Paint", "MouseButtonPress"
    // The receiving object's class, its name if it has one, and for an object that is no widget
    // (a timer) the class of its parent.
    QString receiver;
};

/**
 * The application, measuring how long each event takes to handle on the GUI thread: an event
 * handled in at least stallThresholdMs() (an event-loop stall: the window does not answer
 * meanwhile) is kept in stalls() and, with logStalls(), printed on stderr as
 * "layerpaint: stall 2412 ms at 1765111234.503: Paint to ui::Viewport" (when it began, as Unix
 * time in seconds). Time spent in events handled inside it
 * (a dialog's own loop, processEvents()) and waiting in such a nested loop is not its own. The
 * GUI reads the threshold from LAYERPAINT_STALL_MS; below 0 (the default) no stall is recorded.
 *
 * Input given while the window did not answer is not trusted: after an event that kept the GUI
 * thread busyInputMs() or longer, the input already waiting is handled at once, and a mouse or
 * pen press among it for a guarded widget (the view) is dropped with the drag that follows it.
 * A click on a window that has not yet shown what it now holds never lands as a stroke on it; a
 * stroke begun before the freeze goes on with what was given meanwhile.
 */
class MeteredApplication : public QApplication {
public:
    MeteredApplication(int& argc, char** argv);

    void setStallThresholdMs(double ms) { m_thresholdMs = ms; }
    double stallThresholdMs() const { return m_thresholdMs; }
    void setLogStalls(bool log) { m_log = log; }
    /** The first 1000 stalls since the last clearStalls(). */
    const std::vector<Stall>& stalls() const { return m_stalls; }
    void clearStalls() { m_stalls.clear(); }
    /** The threshold LAYERPAINT_STALL_MS sets (milliseconds), or -1 when unset or invalid. */
    static double thresholdFromEnvironment();

    /** Drops the presses queued for widget (and its children) during a freeze, and their drags. */
    void guardFromQueuedInput(QWidget* widget);
    /** How long an event must keep the GUI thread for its queued input to be distrusted. */
    void setBusyInputMs(double ms) { m_busyInputMs = ms; }
    double busyInputMs() const { return m_busyInputMs; }
    /** How many mouse and pen events were dropped since the start. */
    std::size_t droppedInputEvents() const { return m_droppedInput; }

    bool notify(QObject* receiver, QEvent* event) override;

private:
    /** An event being handled: when it began and how much of that was others' time. */
    struct Frame {
        std::int64_t startNs = 0;
        std::int64_t othersNs = 0;
    };

    void watchDispatcher();
    void record(double ms, const QObject* receiver, const QEvent* event);
    bool isGuarded(const QObject* receiver) const;
    /** Whether the event is a press given while frozen, or the rest of such a press's drag. */
    bool dropsInput(const QObject* receiver, const QEvent* event);
    void dropQueuedInput();

    double m_thresholdMs = -1.0;
    bool m_log = false;
    QElapsedTimer m_clock;
    std::vector<Frame> m_frames;
    std::int64_t m_blockedSinceNs = -1;
    QAbstractEventDispatcher* m_watched = nullptr;
    std::vector<Stall> m_stalls;
    double m_busyInputMs = 250.0;
    std::vector<QPointer<QWidget>> m_guarded;
    bool m_busy = false;       // an event since the outermost one began took busyInputMs()
    bool m_dropping = false;   // handling the input queued meanwhile
    bool m_swallowing = false; // dropping what follows a dropped press, up to its release
    std::size_t m_droppedInput = 0;
};

} // namespace ui
