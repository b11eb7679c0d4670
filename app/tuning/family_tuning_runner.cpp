// FamilyTuningRunner: the runs' sequence (prepare, start, hold, back, settle, capture, measure) and the gains.
#include "family_tuning_runner.h"

#include "tuning_frame.h"

#include "app/variables/variable_rules.h"

#include "serialport/drive_session.h"
#include "serialport/simulator_link.h"
#include "serialport/watch_poller.h"

#include <algorithm>
#include <cmath>
#include <memory>

namespace app {

namespace {
constexpr double kPre_s = 0.02;  // captured before the move's start was sent
constexpr int kClockPollMs = 2; // how often a wait looks at the drive's clock
} // namespace

FamilyTuningRunner::FamilyTuningRunner(TuningProfile profile, QObject* parent)
    : Tuner(parent), m_profile(std::move(profile)) {
    m_amplitude = m_profile.moves.value(0).amplitude;
    m_wait.setInterval(kClockPollMs);
    connect(&m_wait, &QTimer::timeout, this, [this] {
        if (clock_s() < m_until_s) return;
        m_wait.stop();
        if (auto then = std::exchange(m_then, {})) then();
    });
    m_wall.start();
}

void FamilyTuningRunner::attach(serialport::DriveSession* session, serialport::Link* link) {
    if (session == m_session && link == m_link) return;
    disconnect(m_answered);
    disconnect(m_lost);
    delete m_poller;
    m_poller = nullptr;
    const bool wasRunning = m_running;
    m_batches.clear();
    m_session = session;
    m_link = link;
    m_prepared = false;
    if (wasRunning) fail(tr("The connection closed during the run."));
    if (!session) return;
    m_poller = new serialport::WatchPoller(*session, this);
    connect(m_poller, &serialport::WatchPoller::answered, this, [this](const QList<double>& values) {
        if (!m_polling) return;
        if (!values.isEmpty()) m_polled.append({clock_s(), values.first()});
        m_poller->poll({m_profile.watch});
    });
    // A refusal ends the run; a poll that went unanswered (a busy line, a slow adapter) is a missed sample,
    // counted and shown with the run, and polling goes on.
    connect(m_poller, &serialport::WatchPoller::failed, this, [this](const QString& reason, bool refused) {
        if (!m_polling) return;
        if (refused) return fail(tr("Polling %1 failed: %2").arg(m_profile.watch, reason));
        ++m_missedPolls;
        m_poller->poll({m_profile.watch});
    });
    // One line in flight at a time: the front batch's next line.
    m_answered = connect(session, &serialport::DriveSession::answered, this,
                         [this](quint64 id, const serialport::LineAnswer& answer) {
                             if (m_batches.isEmpty() || m_batches.front().waiting != id) return;
                             Batch& b = m_batches.front();
                             b.waiting = 0;
                             if (!answer.ok()) {
                                 const Batch refused = m_batches.takeFirst();
                                 const QString line = refused.lines.value(refused.answers.size());
                                 if (refused.failed) refused.failed(tr("%1: %2").arg(line, answer.error));
                             } else if (b.answers << answer; b.answers.size() == b.lines.size()) {
                                 const Batch done = m_batches.takeFirst();
                                 if (done.done) done.done(done.answers);
                             }
                             pump();
                         });
    m_lost = connect(session, &serialport::DriveSession::lost, this, [this](quint64 id, const QString& reason) {
        if (m_batches.isEmpty() || m_batches.front().waiting != id) return;
        const Batch b = m_batches.takeFirst();
        if (b.failed) b.failed(tr("%1: no answer (%2)").arg(b.lines.value(b.answers.size()), reason));
        pump();
    });
}

void FamilyTuningRunner::pump() {
    // An empty batch (a run's prepare once prepared) completes in its turn, after the lines queued before it.
    while (!m_batches.isEmpty() && m_batches.front().lines.isEmpty()) {
        const Batch empty = m_batches.takeFirst();
        if (empty.done) empty.done({});
    }
    if (m_batches.isEmpty() || !m_session || m_batches.front().waiting != 0) return;
    Batch& b = m_batches.front();
    m_lastSent_s = clock_s();
    b.waiting = m_session->sendLine(b.lines.value(b.answers.size()));
}

void FamilyTuningRunner::sendAll(const QStringList& lines, Answered done, std::function<void(const QString&)> failed) {
    if (!m_session) {
        if (failed) failed(tr("Not connected to the drive."));
        return;
    }
    m_batches.append(Batch{lines, {}, 0, std::move(done), std::move(failed)});
    pump();
}

void FamilyTuningRunner::setGain(const QString& name, double value) {
    const QStringList lines = m_profile.writeGain(name, value);
    if (lines.isEmpty()) return;
    sendAll(
        lines,
        [this, name, value](const QList<serialport::LineAnswer>&) {
            m_gains[name] = value;
            emit gainConfirmed(name, value);
            emit gainAnswered(name, value, {});
        },
        [this, name, value](const QString& why) {
            emit gainRefused(name, why);
            emit gainAnswered(name, value, why);
        });
}

void FamilyTuningRunner::readGains() {
    sendAll(
        m_profile.readGains,
        [this](const QList<serialport::LineAnswer>& answers) {
            const QMap<QString, double> read = m_profile.parseGains(answers);
            for (auto it = read.begin(); it != read.end(); ++it) m_gains[it.key()] = it.value();
            emit gainsRead(read);
            emit gainValuesRead(read);
        },
        [this](const QString& why) { emit message(tr("Reading the gains failed: %1").arg(why)); });
}

void FamilyTuningRunner::setMove(int index, int amplitude, int holdMs) {
    m_moveIndex = std::clamp(index, 0, int(m_profile.moves.size()) - 1);
    m_amplitude = amplitude;
    m_holdMs = std::max(holdMs, 10);
}

void FamilyTuningRunner::runOnce() {
    if (m_running) return;
    m_continuous = false;
    startRun();
}

void FamilyTuningRunner::runContinuously() {
    m_continuous = true;
    if (!m_running) startRun();
    emit stateChanged();
}

void FamilyTuningRunner::stop() {
    m_continuous = false;
    emit stateChanged();
}

void FamilyTuningRunner::startRun() {
    if (!m_session) return fail(tr("Not connected to the drive: connect first (Drive > Connect)."));
    m_running = true;
    emit runStarted(int(m_runs.size()) + 1);
    emit stateChanged();
    const auto failed = [this](const QString& why) { fail(tr("The drive refused %1").arg(why)); };
    const QStringList prepare = (m_faulted ? m_profile.clearFault : QStringList()) +
                                (m_prepared ? QStringList() : m_profile.prepare);
    sendAll(prepare, [this, failed](const QList<serialport::LineAnswer>&) {
        m_prepared = true;
        m_faulted = false;
        m_runGains = m_gains; // every gain written before the run has been answered by now: lines go in order
        if (!qobject_cast<serialport::SimulatorLink*>(m_link.data())) { // a real drive: poll while the move runs
            m_polled.clear();
            m_missedPolls = 0;
            m_polling = true;
            m_poller->poll({m_profile.watch});
        }
        sendAll(m_profile.lines(move().start, m_amplitude),
                [this](const QList<serialport::LineAnswer>&) { afterStart(); }, failed);
    }, failed);
}

void FamilyTuningRunner::afterStart() {
    if (!m_running) return;
    // One line in flight at a time: the last line sent was the start's last. Its send time, not this answer's
    // arrival, places the capture: a busy GUI thread may read the answer long after the drive acted on it
    // (the step then fell before the captured window: "the response did not move").
    m_start_s = m_lastSent_s;
    waitUntil(clock_s() + m_holdMs / 1000.0, [this] {
        sendAll(m_profile.lines(move().back, m_amplitude), [this](const QList<serialport::LineAnswer>&) { afterBack(); },
                [this](const QString& why) { fail(tr("The drive refused %1").arg(why)); });
    });
}

void FamilyTuningRunner::afterBack() {
    if (!m_running) return;
    waitUntil(clock_s() + m_holdMs / 1000.0, [this] { capture(); });
}

void FamilyTuningRunner::capture() {
    if (auto* sim = qobject_cast<serialport::SimulatorLink*>(m_link.data())) {
        QPointer<FamilyTuningRunner> self(this);
        return sim->readMonitor([self](const drive_core::MonitorTrace& trace) {
            if (!self || !self->m_running) return;
            if (trace.volts.empty()) return self->fail(tr("The simulated drive's bench has no analog monitor."));
            // From kPre_s before the start was sent to the newest sample.
            const double span_s = trace.lastSample_s - (self->m_start_s - kPre_s);
            const auto wanted = std::size_t(std::clamp(span_s / trace.interval_s, 1.0, double(trace.volts.size())));
            scope::Capture c;
            c.interval_s = trace.interval_s;
            scope::CaptureChannel channel{self->m_profile.monitor.toStdString(), "V", {}};
            channel.values.assign(trace.volts.end() - long(wanted), trace.volts.end());
            c.channels.push_back(std::move(channel));
            if (trace.command.size() == trace.volts.size()) { // the second probe: the velocity loop's input
                scope::CaptureChannel command{self->m_profile.command.toStdString(), "V", {}};
                command.values.assign(trace.command.end() - long(wanted), trace.command.end());
                c.channels.push_back(std::move(command));
            }
            const QString source = tr("bench oscilloscope on %1, %2 samples/s")
                                       .arg(QString::fromStdString(trace.signal))
                                       .arg(1.0 / trace.interval_s, 0, 'f', 0);
            self->checkFault(std::move(c), source);
        });
    }
    // A real drive: the polled samples, evenly spaced over their span (the link's own pace).
    m_polling = false;
    if (m_polled.size() < 3) return fail(tr("Too few samples of %1 came back to measure the run.").arg(m_profile.watch));
    const double first = m_polled.front().first, last = m_polled.back().first;
    scope::Capture c;
    c.interval_s = (last - first) / double(m_polled.size() - 1);
    scope::CaptureChannel channel{m_profile.watch.toStdString(), m_profile.watchUnit.toStdString(), {}};
    for (const auto& [t, v] : m_polled) channel.values.push_back(v);
    c.channels.push_back(std::move(channel));
    QString source = tr("%1 polled, %2 samples/s").arg(m_profile.watch).arg(1.0 / c.interval_s, 0, 'f', 1);
    if (m_missedPolls > 0) source += tr(", %n poll(s) unanswered", nullptr, m_missedPolls);
    checkFault(std::move(c), source);
}

void FamilyTuningRunner::checkFault(scope::Capture capture, const QString& source) {
    // The capture waits in the callback while the drive is asked; a drive that cannot say adds no run.
    auto held = std::make_shared<scope::Capture>(std::move(capture));
    sendAll(
        m_profile.faultCheck,
        [this, held, source](const QList<serialport::LineAnswer>& answers) {
            if (m_running) finishRun(std::move(*held), source, m_profile.faultIn(answers));
        },
        [this](const QString& why) { fail(tr("Reading the drive's fault state failed: %1").arg(why)); });
}

void FamilyTuningRunner::finishRun(scope::Capture capture, const QString& source, const QString& fault) {
    FamilyTuningRun run;
    run.number = int(m_runs.size()) + 1;
    run.gains = m_runGains;
    QStringList changed;
    if (!m_runs.isEmpty())
        for (auto it = m_runGains.begin(); it != m_runGains.end(); ++it)
            if (m_runs.back().gains.value(it.key()) != it.value())
                changed << QStringLiteral("%1=%2").arg(it.key()).arg(it.value());
    capture.title = tr("Run %1").arg(run.number).toStdString() +
                    (changed.isEmpty() ? std::string() : ": " + changed.join(QLatin1Char(' ')).toStdString());
    // The step is the move's first half: up to when it went back.
    const std::vector<double>& values = capture.channels.front().values;
    const auto half = std::min(values.size(), std::size_t((kPre_s + m_holdMs / 1000.0) / capture.interval_s));
    run.metrics = scope::analyseStep(std::span(values.data(), half), capture.interval_s);
    run.capture = std::move(capture);
    run.source = source;
    run.fault = fault;
    if (!fault.isEmpty()) {
        m_faulted = true;
        m_prepared = false; // the fault disabled the drive: prepare again after clearing it
        m_continuous = false;
    }
    m_runs.append(run);
    m_running = false;
    emit runFinished(m_runs.back());
    emit runShown(rowOf(m_runs.back()));
    if (m_continuous) return startRun();
    emit stateChanged();
}

void FamilyTuningRunner::fail(const QString& why) {
    m_polling = false;
    m_wait.stop();
    m_then = {};
    const bool was = m_running;
    m_running = m_continuous = false;
    emit runFailed(tr("Not run: %1").arg(why));
    if (was) emit stateChanged();
}

void FamilyTuningRunner::undoTo(int runNumber) {
    for (const FamilyTuningRun& run : m_runs) {
        if (run.number != runNumber) continue;
        for (auto it = run.gains.begin(); it != run.gains.end(); ++it)
            if (m_gains.value(it.key()) != it.value()) setGain(it.key(), it.value());
        emit message(tr("Gains of run %1 sent.").arg(runNumber));
        return;
    }
}

QList<TunerMove> FamilyTuningRunner::tunerMoves() const {
    QList<TunerMove> moves;
    for (const TuningMove& m : m_profile.moves)
        moves << TunerMove{m.name, m.amplitudeUnit, m.amplitude,
                           tr("Amplitude in %1. %2.").arg(m.amplitudeUnit, m.description)};
    return moves;
}

QString FamilyTuningRunner::moveText() const {
    return move().description + QStringLiteral(".\n") +
           m_profile.lines(move().start, m_amplitude).join(QStringLiteral(", ")) + QStringLiteral(" \u2192 ") +
           m_profile.lines(move().back, m_amplitude).join(QStringLiteral(", "));
}

QString FamilyTuningRunner::runStartText(int number) const {
    return tr("Run %1: %2, %3 %4, held %5 ms\u2026")
        .arg(number)
        .arg(move().name)
        .arg(m_amplitude)
        .arg(move().amplitudeUnit)
        .arg(m_holdMs);
}

QStringList FamilyTuningRunner::extraColumns() const {
    return {tr("Sampled")};
}

const scope::Capture* FamilyTuningRunner::runCapture(int number) const {
    for (const FamilyTuningRun& run : m_runs)
        if (run.number == number) return &run.capture;
    return nullptr;
}

// The gains as last read or confirmed, in the family's own file (empty until the drive has given them).
std::optional<GainsFile> FamilyTuningRunner::gainsFile() const {
    if (m_profile.gainsFileName.isEmpty()) return std::nullopt;
    QList<QPair<QString, QString>> values;
    for (const TuningGain& g : m_profile.gains)
        if (m_gains.contains(g.name)) values.append({g.parameter, QString::number(m_gains.value(g.name), 'g', 10)});
    const auto file = VariableRules::make(m_profile.family)->fileText(values);
    return GainsFile{m_profile.gainsFilter, m_profile.gainsFileName, file.text};
}

TunerRow FamilyTuningRunner::rowOf(const FamilyTuningRun& run) const {
    TunerRow row{run.number, run.capture, run.metrics, {}, {}, {}, {}};
    row.extraCells = {run.fault.isEmpty() ? run.source : tr("FAULT %1; %2").arg(run.fault, run.source)};
    if (!run.fault.isEmpty()) {
        row.fault = tr("The drive faulted during this run: %1").arg(run.fault);
        row.status = tr("Run %1: the drive faulted \u2014 %2. The response is shown up to the fault; the next run "
                        "clears it first (%3).")
                         .arg(run.number)
                         .arg(run.fault, m_profile.clearFault.join(QStringLiteral(", ")));
    } else if (!run.metrics.hasStep) {
        row.status =
            tr("Run %1: the response did not move \u2014 is the drive enabled and the move allowed?").arg(run.number);
    } else {
        row.status = stepSummary(run.number, run.metrics);
    }
    return row;
}

double FamilyTuningRunner::clock_s() const {
    if (m_link)
        if (const auto ms = m_link->driveClockMs()) return *ms / 1000.0;
    return double(m_wall.elapsed()) / 1000.0; // a real drive runs in real time
}

void FamilyTuningRunner::waitUntil(double clock_s, std::function<void()> then) {
    m_until_s = clock_s;
    m_then = std::move(then);
    m_wait.start();
}

} // namespace app
