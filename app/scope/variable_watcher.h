// VariableWatcher: the polled rolling chart's data — one sample at a time from the family's WatchSource
// (the next poll goes out when the previous answer came back, so the link never holds more than one),
// each answer appended to a rolling window of a SeriesStore with its measured sample rate. Pauses while
// the source says no poll may go out (a program running on the BDS5, a transfer, disconnected) and looks
// again every 250 ms. GUI thread only.
#pragma once

#include "scope/series_store.h"

#include <QElapsedTimer>
#include <QObject>
#include <QStringList>
#include <QTimer>

namespace app {

class WatchSource;

class VariableWatcher final : public QObject {
    Q_OBJECT
public:
    static constexpr double kWindow_s = 30; // the chart shows the last 30 s

    explicit VariableWatcher(WatchSource& source, QObject* parent = nullptr);

    WatchSource& source() const { return m_source; }
    // 1 to 4 names of the source's choices; takes effect at the next start().
    void setVariables(const QStringList& names) { m_variables = names; }
    const QStringList& variables() const { return m_variables; }
    void start(); // clears the store
    void stop();  // no poll goes out after this (one already on the wire is answered and ignored)
    bool isRunning() const { return m_running; }
    bool isPaused() const { return !m_pauseReason.isEmpty(); }

    // Times are seconds since start(), taken halfway between the poll and its answer.
    const scope::SeriesStore& store() const { return m_store; }
    // Samples per second over the last few answers; 0 until there are two.
    double rate_hz() const { return m_rate_hz; }
    QString rateText() const; // "polled, 7.8 samples/s"

signals:
    void sampled(double time_s); // every channel got one sample at time_s
    void stateChanged();         // running, stopped, paused, or stopped by an error
    void message(const QString& text);

private:
    void poll();
    void onAnswered(const QList<double>& values);
    void onFailed(const QString& reason, bool stopWatching);
    void setPauseReason(const QString& reason);

    WatchSource& m_source;
    QStringList m_variables;
    scope::SeriesStore m_store;
    QElapsedTimer m_clock;
    QTimer m_retry; // while paused or after a failed poll: look again
    QString m_pauseReason;
    double m_sentAt_s = 0;
    double m_rate_hz = 0;
    bool m_polling = false; // a poll is in flight
    bool m_running = false;
};

} // namespace app
