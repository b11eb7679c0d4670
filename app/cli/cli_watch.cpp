// CliWatch: the polling schedule and the CSV; and the watch verb.
#include "cli_watch.h"

#include "cli_files.h"
#include "cli_runner.h"

#include <algorithm>
#include <cmath>

namespace app::cli {

CliWatch::CliWatch(serialport::DriveSession& session, QList<serialport::WatchChoice> choices, int everyMs,
                   double forSeconds, QObject* parent)
    : QObject(parent), m_poller(session), m_choices(std::move(choices)), m_everyMs(everyMs),
      m_forMs(forSeconds * 1000) {
    for (const auto& c : m_choices) m_names << c.name;
    m_due.setSingleShot(true);
    m_due.setTimerType(Qt::PreciseTimer);
    connect(&m_due, &QTimer::timeout, this, &CliWatch::pollWhenDue);
    connect(&m_poller, &serialport::WatchPoller::answered, this, &CliWatch::onAnswered);
    connect(&m_poller, &serialport::WatchPoller::failed, this, &CliWatch::onFailed);
}

void CliWatch::start() {
    m_clock.start();
    m_nextAt_ms = 0;
    pollWhenDue();
}

// Polls are due every m_everyMs from the first while the time lasts; one that falls due while the previous
// is still on the link goes out when its answer comes (and the ones after follow from then on), never once
// the time is over.
void CliWatch::pollWhenDue() {
    if (m_done || m_poller.isPolling()) return;
    const double t = now_ms();
    if (m_nextAt_ms >= m_forMs || t >= m_forMs)
        return finish(m_result.samples > 0 ? CliWatchResult::Status::Done : CliWatchResult::Status::NoAnswer,
                      m_result.reason);
    if (t < m_nextAt_ms) return m_due.start(int(std::ceil(m_nextAt_ms - t)));
    m_sentAt_ms = t;
    m_nextAt_ms = std::max({m_nextAt_ms + m_everyMs, t + m_poller.minimumIntervalMs()});
    m_poller.poll(m_names);
}

void CliWatch::onAnswered(const QList<double>& values) {
    if (m_done) return;
    if (values.size() == m_names.size()) { // else a damaged answer: no sample this time
        const double t_s = (m_sentAt_ms + now_ms()) / 2 / 1000;
        m_rows += QString::number(t_s, 'f', 3);
        for (double v : values) m_rows += QLatin1Char(',') + QString::number(v, 'g', 12);
        m_rows += QStringLiteral("\r\n");
        emit sampled(++m_result.samples);
    }
    pollWhenDue();
}

void CliWatch::onFailed(const QString& reason, bool refused) {
    if (m_done) return;
    if (refused) return finish(CliWatchResult::Status::Refused, reason);
    ++m_result.missed; // a time-out: the next poll may be answered
    m_result.reason = reason;
    pollWhenDue();
}

void CliWatch::finish(CliWatchResult::Status status, const QString& reason) {
    m_done = true;
    m_due.stop();
    m_poller.cancel();
    m_result.status = status;
    m_result.reason = reason;
    QString header = QStringLiteral("Time (s)");
    for (const auto& c : m_choices)
        header += QLatin1Char(',') + c.name + (c.unit.isEmpty() ? QString() : QStringLiteral(" (%1)").arg(c.unit));
    m_result.csv = header + QStringLiteral("\r\n") + m_rows;
    emit finished(m_result);
}

// watch --vars V1,V2 --every MS --for S --csv FILE (the names checked against the family's in start()).
void CliRunner::watch(const CliCommand& c) {
    QList<serialport::WatchChoice> choices;
    for (const QString& name : c.variables) choices << *serialport::findWatchChoice(m_family, name);
    auto* w = new CliWatch(*m_session, choices, c.watchEveryMs, c.watchForSeconds, this);
    connect(w, &CliWatch::sampled, this, [this](int samples) { progress(QStringLiteral("%1 samples").arg(samples)); });
    connect(w, &CliWatch::finished, this, [this, w, c](const CliWatchResult& r) {
        w->deleteLater();
        progress(QString());
        if (r.status == CliWatchResult::Status::Refused)
            return fail(kDriveError, QStringLiteral("watch: %1").arg(r.reason));
        if (r.status == CliWatchResult::Status::NoAnswer)
            return fail(kNoAnswer, QStringLiteral("watch: no poll was answered with a sample%1")
                                       .arg(r.reason.isEmpty() ? QString() : QStringLiteral(" (%1)").arg(r.reason)));
        QString error;
        if (!writeTextFile(c.csvPath, r.csv, error)) return fail(kUsage, error);
        out(QStringLiteral("%1 samples of %2 written to %3%4\n")
                .arg(r.samples)
                .arg(c.variables.join(QLatin1Char(',')), c.csvPath,
                     r.missed ? QStringLiteral(" (%1 poll(s) unanswered)").arg(r.missed) : QString()));
        next();
    });
    w->start();
}

// Every watch command's names must be the family's: refused before anything is sent, with the list.
bool CliRunner::watchNamesKnown() {
    for (const CliCommand& c : m_options.commands) {
        if (c.kind != CliCommand::Kind::Watch) continue;
        for (const QString& name : c.variables) {
            if (serialport::findWatchChoice(m_family, name)) continue;
            fail(kUsage, QStringLiteral("watch: the %1 has no value \"%2\" to watch; it has: %3")
                             .arg(familyDisplayName(m_family), name,
                                  serialport::watchNames(m_family).join(QStringLiteral(", "))));
            return false;
        }
    }
    return true;
}

} // namespace app::cli
