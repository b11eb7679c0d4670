// VariableWatcher: the polled rolling chart's data — "P VAR1 VAR2" through the session at the link's pace
// (the next poll goes out when the previous answer came back, so the queue never holds more than one),
// each answer appended to a rolling window of a SeriesStore with its measured sample rate. Works for any
// variable P prints, including those RECORD cannot take. Pauses while the drive is not at an interactive
// prompt (a program running, a transfer, disconnected). GUI thread only.
#pragma once

#include "scope/series_store.h"

#include <QElapsedTimer>
#include <QObject>
#include <QStringList>
#include <QTimer>

namespace serialport {
struct Bds5Response;
}

namespace app {

class DriveConnection;

class VariableWatcher final : public QObject {
    Q_OBJECT
public:
    static constexpr double kWindow_s = 30; // the chart shows the last 30 s

    explicit VariableWatcher(DriveConnection& connection, QObject* parent = nullptr);

    // 1 to 4 names; takes effect at the next start().
    void setVariables(const QStringList& names) { m_variables = names; }
    const QStringList& variables() const { return m_variables; }
    void start(); // clears the store
    void stop();  // no poll goes out after this (one already on the wire is answered and ignored)
    bool isRunning() const { return m_running; }
    bool isPaused() const { return m_paused; }

    // Times are seconds since start(), taken halfway between sending P and its answer.
    const scope::SeriesStore& store() const { return m_store; }
    // Polls per second over the last few answers; 0 until there are two.
    double rate_hz() const { return m_rate_hz; }
    QString rateText() const; // "polled, 7.8 samples/s"

signals:
    void sampled(double time_s); // every channel got one sample at time_s
    void stateChanged();         // running, stopped, paused, or stopped by an error
    void message(const QString& text);

private:
    void poll();
    void onAnswer(quint64 id, const serialport::Bds5Response& response);
    void onFailed(quint64 id, const QString& reason);
    void setPaused(bool paused);

    DriveConnection& m_connection;
    QStringList m_variables;
    scope::SeriesStore m_store;
    QElapsedTimer m_clock;
    QTimer m_retry; // while paused: look again for an interactive prompt
    quint64 m_pollId = 0;
    double m_sentAt_s = 0;
    double m_rate_hz = 0;
    bool m_running = false;
    bool m_paused = false;
};

} // namespace app
