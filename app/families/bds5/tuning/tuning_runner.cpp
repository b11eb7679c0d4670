// TuningRunner: gains, runs and TUNE over the session.
#include "tuning_runner.h"

#include "families/bds5/drive_connection.h"
#include "families/bds5/record/scope_catalog.h"
#include "soft_limits.h"

#include "app/tuning/tuning_frame.h"

#include "scope/play_parser.h"
#include "serialport/bds5_variable_file.h"

#include <QTimer>

namespace app {

namespace {
const QStringList kNumericGains = {QStringLiteral("KP"),  QStringLiteral("KF"),    QStringLiteral("KV"),
                                   QStringLiteral("KVI"), QStringLiteral("KPROP"), QStringLiteral("LPFHZ"),
                                   QStringLiteral("ILIM")};
const QStringList kSwitches = {QStringLiteral("LPF"), QStringLiteral("PL"), QStringLiteral("PROP"),
                               QStringLiteral("PLIM")};
constexpr double kSaturation = 0.98; // of ILIM
constexpr int kBitsPerByte = 10;     // 8N1

std::optional<int> valueOf(const QString& word) {
    if (word.compare(QLatin1String("ON"), Qt::CaseInsensitive) == 0) return 1;
    if (word.compare(QLatin1String("OFF"), Qt::CaseInsensitive) == 0) return 0;
    bool ok = false;
    const double v = word.toDouble(&ok);
    return ok ? std::optional<int>(int(std::lround(v))) : std::nullopt;
}
} // namespace

TuningRunner::TuningRunner(DriveConnection& connection, QObject* parent) : Tuner(parent), m_connection(connection) {
    qRegisterMetaType<TuningRun>();
}

quint64 TuningRunner::send(const QString& line, serialport::Bds5Session::Echo echo) {
    serialport::Bds5Session* session = m_connection.session();
    if (!session || !m_connection.isConnected()) {
        emit message(tr("Not connected to a drive: use Drive > Connect."));
        return 0;
    }
    connect(session, &serialport::Bds5Session::finished, this, &TuningRunner::onAnswer, Qt::UniqueConnection);
    return session->send(line, echo);
}

void TuningRunner::setGain(const QString& name, int value) {
    const QString line = QStringLiteral("%1=%2").arg(name).arg(value);
    if (const quint64 id = send(line)) {
        m_pendingGains.insert(id, name);
        m_gains[name] = value; // in force for every command queued after it
    }
}

void TuningRunner::readGains() {
    // Background reads (on connecting, after TUNE): out of the terminal, like the variable browser's polls.
    const auto quiet = serialport::Bds5Session::Echo::Quiet;
    m_readId = send(QStringLiteral("P ") + kNumericGains.join(QLatin1Char(' ')), quiet);
    m_readSwitchesId = send(QStringLiteral("P ") + kSwitches.join(QLatin1Char(' ')), quiet);
    m_readDriveValuesId = send(QStringLiteral("P ") + TestMove::proposalInputs().join(QLatin1Char(' ')), quiet);
}

void TuningRunner::onAnswer(quint64 id, const serialport::Bds5Response& response) {
    if (m_pendingGains.contains(id)) {
        const QString name = m_pendingGains.take(id);
        if (response.errors.isEmpty()) {
            emit gainConfirmed(name, m_gains.value(name));
            emit gainAnswered(name, m_gains.value(name), {});
            return emit proposalChanged(); // ILIM and KV go into the proposal
        }
        const QString why = serialport::describeError(response.errors.first());
        emit gainRefused(name, why);
        emit gainAnswered(name, m_gains.value(name), why);
        readGains(); // the drive's value is the truth
        return;
    }
    if (id == m_readDriveValuesId) {
        const QStringList names = TestMove::proposalInputs();
        const QStringList words = response.lines.join(QLatin1Char(' ')).split(QLatin1Char(' '), Qt::SkipEmptyParts);
        bool ok = false;
        for (int i = 0; i < std::min(words.size(), names.size()); ++i)
            if (const double v = words[i].toDouble(&ok); ok) m_driveValues[names[i]] = v;
        emit driveValuesRead();
        emit proposalChanged();
        // The last of readGains()' answers: a run that waited for them starts with the amplitude the panel has
        // just proposed from these values (on the first run too, not only from the second on).
        if (m_runAfterRead) {
            m_runAfterRead = false;
            if (m_running)
                startRun(); // a run was waiting for the gains
            else
                runOnce(); // TUNE: show the step with the gains it chose
        }
        return;
    }
    if (id == m_limitsId) {
        m_limitsId = 0;
        const auto limits = SoftLimits::parse(response.lines);
        if (!response.errors.isEmpty() || !limits) {
            const QString answer = response.errors.isEmpty() ? response.text.trimmed()
                                                             : serialport::describeError(response.errors.first());
            return endRuns(tr("The soft limits could not be read (%1 answered \"%2\"): the test move was not run.")
                               .arg(SoftLimits::printLine(), answer));
        }
        m_limitsChecked = true;
        const QString why = limits->conflict(m_move, m_driveValues);
        if (why.isEmpty()) return startRun();
        m_awaitingLimits = true;
        return emit softLimitsInTheWay(why);
    }
    if (id == m_limitsOffId) {
        m_limitsOffId = 0;
        if (!response.errors.isEmpty()) // the run goes on; MoveWatch reports the ERR 23 that follows
            emit message(tr("The drive refused PLIM=0: %1").arg(serialport::describeError(response.errors.first())));
        return;
    }
    if (id == m_readId || id == m_readSwitchesId) {
        const QStringList& names = id == m_readId ? kNumericGains : kSwitches;
        const QStringList words = response.lines.join(QLatin1Char(' ')).split(QLatin1Char(' '), Qt::SkipEmptyParts);
        for (int i = 0; i < std::min(words.size(), names.size()); ++i)
            if (const auto v = valueOf(words[i])) m_gains[names[i]] = *v;
        if (id == m_readSwitchesId) {
            emit gainsRead(m_gains);
            QMap<QString, double> values;
            for (auto it = m_gains.begin(); it != m_gains.end(); ++it) values.insert(it.key(), it.value());
            emit gainValuesRead(values);
        }
        return;
    }
    if (id == m_tuneId) {
        m_tuneId = 0;
        if (!response.errors.isEmpty()) {
            emit message(tr("TUNE failed: %1").arg(serialport::describeError(response.errors.first())));
            return;
        }
        emit message(tr("TUNE done: reading the gains it chose, then a step to show the response."));
        m_runAfterRead = true;
        readGains();
    }
}

void TuningRunner::runOnce() {
    if (m_running) return;
    m_running = true;
    m_continuous = false;
    emit stateChanged();
    startRun();
}

void TuningRunner::runContinuously() {
    m_continuous = true;
    if (!m_running) {
        m_running = true;
        startRun();
    }
    emit stateChanged();
}

void TuningRunner::stop() {
    m_continuous = false;
    if (m_awaitingLimits || m_limitsId) return endRuns(tr("Not run: stopped before the test move."));
    if (m_record) m_record->cancel();
    emit stateChanged();
}

void TuningRunner::runWithoutSoftLimits() {
    if (!m_awaitingLimits) return;
    m_awaitingLimits = false;
    m_limitsOff = true;
    m_limitsOffId = send(QStringLiteral("PLIM=0")); // queued ahead of the run's RECORD
    startRun();
}

// Once per Run Once or Run Continuously: PLIM, PMAX, PMIN and PFB against the test move (SoftLimits).
void TuningRunner::checkSoftLimits() {
    m_limitsId = send(SoftLimits::printLine(), serialport::Bds5Session::Echo::Quiet);
    if (!m_limitsId) endRuns(tr("Not connected to a drive: use Drive > Connect."));
}

void TuningRunner::endRuns(const QString& failure) {
    m_cycle.invalidate();
    m_running = m_continuous = false;
    m_awaitingLimits = m_limitsChecked = false;
    m_limitsId = 0;
    if (m_limitsOff) { // turned off for the test only: the drive's limits are back once it is over
        m_limitsOff = false;
        setGain(QStringLiteral("PLIM"), 1);
    }
    if (!failure.isEmpty()) emit runFailed(failure);
    emit stateChanged();
}

void TuningRunner::startRun() {
    serialport::Bds5Session* session = m_connection.session();
    if (!session || !m_connection.isConnected()) return endRuns(tr("Not connected to a drive: use Drive > Connect."));
    if (m_gains.isEmpty()) { // the run's gains must be known: read them first, then run
        m_runAfterRead = true;
        m_cycle.start();
        return readGains();
    }
    if (!m_limitsChecked) return checkSoftLimits();
    if (!m_runAfterRead && !m_cycle.isValid()) m_cycle.start();
    m_runGains = m_gains; // every assignment queued so far reaches the drive before RECORD
    m_record = new serialport::Bds5RecordPlay(*session, m_move.plan(), this);
    m_watch = new MoveWatch(*session, *m_record); // a refused or faulted move ends the run without a result
    connect(m_record, &serialport::Bds5Transfer::progress, this, &TuningRunner::progress);
    connect(m_record, &serialport::Bds5Transfer::finished, this, &TuningRunner::onRecorded);
    emit runStarted(int(m_runs.size()) + 1);
    emit recordStarted(m_record);
    m_record->start();
}

void TuningRunner::onRecorded(const serialport::Bds5TransferResult& result) {
    const serialport::Bds5RecordPlan plan = m_record ? m_record->plan() : m_move.plan();
    const QMap<QString, int> gains = m_runGains;
    const QString moveFailure = m_watch ? m_watch->reason() : QString();
    if (m_record) m_record->deleteLater();
    // Samples of a move the drive refused or cut short would measure nothing (an "overshoot 0.0 %"): no run.
    if (!moveFailure.isEmpty() || (result.ok() && !result.errors.isEmpty())) {
        const serialport::Bds5LineError* refused = result.errors.isEmpty() ? nullptr : &result.errors.first();
        const QString why =
            !moveFailure.isEmpty()
                ? moveFailure
                : tr("the drive refused %1: %2.").arg(refused->sent, serialport::describeError(refused->error));
        return endRuns(tr("Run %1 stopped: %2 No row or overlay was added.").arg(m_runs.size() + 1).arg(why));
    }
    if (!result.ok()) return endRuns(result.summary);
    std::vector<std::string> lines;
    qint64 bytes = 6; // "PLAY" CR LF echoed
    for (const QString& l : result.lines) {
        lines.push_back(l.toStdString());
        bytes += l.size() + 2;
    }
    const auto parsed = scope::parsePlay(lines, unitOf);
    if (!parsed.capture || parsed.capture->channels.size() < 2)
        return endRuns(tr("PLAY could not be read: %1").arg(QString::fromStdString(parsed.error)));
    TuningRun run;
    run.number = int(m_runs.size()) + 1;
    run.gains = gains;
    run.capture = *parsed.capture;
    const QString changed = m_runs.isEmpty() ? QString() : [&] {
        QStringList diffs;
        for (auto it = gains.begin(); it != gains.end(); ++it)
            if (m_runs.last().gains.value(it.key()) != it.value())
                diffs << QStringLiteral("%1=%2").arg(it.key()).arg(it.value());
        return diffs.join(QLatin1Char(' '));
    }();
    run.capture.title = tr("Run %1%2")
                            .arg(run.number)
                            .arg(changed.isEmpty() ? QString() : QStringLiteral(": ") + changed)
                            .toStdString();
    const auto& c = run.capture.channels;
    run.metrics = scope::analyseStep(c[1].values, run.capture.interval_s, c[0].values);
    if (const scope::CaptureChannel* icmd = run.capture.find("ICMD"); icmd && !icmd->values.empty()) {
        double peak = 0;
        for (const double v : icmd->values) peak = std::max(peak, std::abs(v));
        run.currentSaturated = peak >= kSaturation * gains.value(QStringLiteral("ILIM"), 100);
    }
    const int baud = m_connection.session() ? std::max(1, m_connection.session()->link().baudRate()) : 9600;
    run.cycle_s = double(m_cycle.nsecsElapsed()) / 1e9;
    m_cycle.invalidate();
    run.ideal_s = plan.durationMs() / 1000.0 + double(bytes) * kBitsPerByte / baud;
    run.softLimitsOff = m_limitsOff;
    m_runs.append(run);
    emit runFinished(run);
    emit runShown(rowOf(run));
    if (m_continuous)
        QTimer::singleShot(0, this, &TuningRunner::startRun);
    else
        endRuns();
}

void TuningRunner::undoTo(int runNumber) {
    if (runNumber < 1 || runNumber > m_runs.size()) return;
    const QMap<QString, int> target = m_runs[runNumber - 1].gains;
    for (auto it = target.begin(); it != target.end(); ++it)
        if (m_gains.value(it.key()) != it.value()) setGain(it.key(), it.value());
    emit message(tr("Gains set back to those of run %1.").arg(runNumber));
}

void TuningRunner::tune(int bandwidthHz, int stability) {
    m_tuneId = send(QStringLiteral("TUNE %1 %2").arg(bandwidthHz).arg(stability));
    if (m_tuneId) emit message(tr("TUNE %1 %2: the drive shakes the motor...").arg(bandwidthHz).arg(stability));
}

QString TuningRunner::gainsAsVar() const {
    QString text;
    for (auto it = m_gains.begin(); it != m_gains.end(); ++it)
        text += QStringLiteral("%1 %2\n").arg(it.key()).arg(it.value());
    return serialport::Bds5VariableFile::parse(text).toText(
        {tr("Tuning gains saved by ServoDesk's tuning panel."), tr("Variables > Send to Drive sends them back.")});
}

// The Tuning panel's view.

QList<TuningGain> TuningRunner::tunerGains() const {
    QList<TuningGain> gains;
    for (const GainInfo& g : tuningGains())
        gains << TuningGain{g.name, g.name, double(g.minimum), double(g.maximum), 0, g.unit, g.description, g.isSwitch};
    return gains;
}

namespace {
const TestMove::Kind kKinds[] = {TestMove::Kind::VelocityStep, TestMove::Kind::PositionStep,
                                 TestMove::Kind::BackAndForth, TestMove::Kind::FrequencyStep};
}

QList<TunerMove> TuningRunner::tunerMoves() const {
    QList<TunerMove> moves;
    const QString proposed = tr(" Proposed from the drive's ILIM, IMAX, KV, ACC and units so that ICMD stays at most "
                                "about half of ILIM.");
    for (const TestMove::Kind kind : kKinds) {
        const bool distance = kind == TestMove::Kind::PositionStep;
        const QString what = distance ? tr("The distance of the incremental move (MI), in the drive's position units.")
                                      : tr("The jog velocity (J), in the drive's velocity units.");
        moves << TunerMove{TestMove::kindName(kind), {}, 0, what + proposed};
    }
    return moves;
}

// The speed stays while the gains change (the runs' overlays compare one move); a new hold or a proposal taken
// proposes it again.
void TuningRunner::setMove(int index, int amplitude, int holdMs) {
    const bool newHold = holdMs != m_move.durationMs;
    m_move.kind = kKinds[std::clamp(index, 0, int(std::size(kKinds)) - 1)];
    m_move.amplitude = amplitude;
    m_move.durationMs = holdMs;
    if ((newHold || m_takeProposal) && !m_driveValues.isEmpty())
        m_moveVelocity = TestMove::proposedMoveVelocity(holdMs, proposalValues());
    m_takeProposal = false;
    m_move.moveVelocity = m_move.kind == TestMove::Kind::PositionStep ? m_moveVelocity : 0;
}

void TuningRunner::useMoveVelocity(int velocity) {
    m_moveVelocity = velocity > 0 || m_driveValues.isEmpty()
                         ? velocity
                         : TestMove::proposedMoveVelocity(m_move.durationMs, proposalValues());
    m_move.moveVelocity = m_move.kind == TestMove::Kind::PositionStep ? m_moveVelocity : 0;
}

QString TuningRunner::moveText() const {
    return m_move.plan().recordLine() + QStringLiteral(" \u2014 ") + m_move.description();
}

TestMove::DriveValues TuningRunner::proposalValues() const {
    TestMove::DriveValues values = m_driveValues;
    for (const char* name : {"ILIM", "KV"}) // the gains as last sent win over the values as last read
        if (m_gains.contains(QLatin1String(name))) values[QLatin1String(name)] = m_gains.value(QLatin1String(name));
    return values;
}

std::optional<int> TuningRunner::proposedAmplitude() const {
    if (m_driveValues.isEmpty()) return std::nullopt;
    return TestMove::proposedAmplitude(m_move.kind, m_move.durationMs, proposalValues());
}

QString TuningRunner::proposalText() const {
    const auto proposed = proposedAmplitude();
    return proposed ? tr("Proposed: %1, so that ICMD stays at most about half of ILIM.").arg(*proposed)
                    : tr("Proposed amplitude: once the drive's values are read.");
}

QString TuningRunner::runStartText(int number) const {
    return tr("Run %1: %2").arg(number).arg(m_move.description());
}

QStringList TuningRunner::extraColumns() const {
    return {tr("SS error"), tr("Cycle (s)"), QStringLiteral("\u00d7 ideal")};
}

const scope::Capture* TuningRunner::runCapture(int number) const {
    return number >= 1 && number <= m_runs.size() ? &m_runs[number - 1].capture : nullptr;
}

std::optional<GainsFile> TuningRunner::gainsFile() const {
    return GainsFile{tr("Variable sets (*.var *.VAR);;All files (*)"), QStringLiteral("gains.var"), gainsAsVar()};
}

TunerRow TuningRunner::rowOf(const TuningRun& run) const {
    TunerRow row{run.number, run.capture, run.metrics, {}, {}, {}, {}};
    row.extraCells = {run.metrics.steadyStateError ? QString::number(*run.metrics.steadyStateError, 'f', 1)
                                                   : QStringLiteral("\u2014"),
                      QString::number(run.cycle_s, 'f', 2),
                      QString::number(run.cycle_s / std::max(run.ideal_s, 1e-9), 'f', 2)};
    if (run.currentSaturated)
        row.warning = tr("ICMD reached ILIM in run %1: the current saturated, so the step shows the current limit "
                         "rather than the loop. Lower the amplitude.")
                          .arg(run.number);
    row.status = stepSummary(run.number, run.metrics);
    if (run.softLimitsOff) row.status += tr(" The soft limits were off for it (PLIM=0); PLIM=1 follows the runs.");
    return row;
}

} // namespace app
