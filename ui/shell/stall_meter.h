// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QApplication>
#include <QElapsedTimer>
#include <QString>

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
 * GUI reads the threshold from LAYERPAINT_STALL_MS; below 0 (the default) nothing is measured.
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

    bool notify(QObject* receiver, QEvent* event) override;

private:
    /** An event being handled: when it began and how much of that was others' time. */
    struct Frame {
        std::int64_t startNs = 0;
        std::int64_t othersNs = 0;
    };

    void watchDispatcher();
    void record(double ms, const QObject* receiver, const QEvent* event);

    double m_thresholdMs = -1.0;
    bool m_log = false;
    QElapsedTimer m_clock;
    std::vector<Frame> m_frames;
    std::int64_t m_blockedSinceNs = -1;
    QAbstractEventDispatcher* m_watched = nullptr;
    std::vector<Stall> m_stalls;
};

} // namespace ui
