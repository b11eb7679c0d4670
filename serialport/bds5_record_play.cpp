// Bds5RecordPlay: RECORD, timed commands, wait, PLAY.
#include "bds5_record_play.h"

namespace serialport {

namespace {
constexpr int kTickMs = 20;
constexpr int kNothingRecorded = 65; // ERR 65 RECORD NOT READY
constexpr int kNotRecordable = 89;   // ERR 89 NOT FOR ALARM/HOLD/RECORD
constexpr int kTooManyPoints = 90;   // ERR 90 TOO MANY POINTS
constexpr int kRecordPoints = 1000;  // n x variables (L7425)
// PLAY readings before giving up. A wire that never damaged anything needs one, else a clean copy needs two; at 1 % dropped + 1 % corrupted bytes about nine
// captures in ten of 20-120 samples come together within sixteen (tests/serialport/play_campaign_test.cpp).
constexpr int kMaxPlays = 16;
} // namespace

QString Bds5RecordPlan::recordLine() const {
    return QStringLiteral("RECORD %1 %2 %3").arg(samples).arg(intervalMs).arg(variables.join(QLatin1Char(' ')));
}

Bds5RecordPlay::Bds5RecordPlay(Bds5Session& session, Bds5RecordPlan plan, QObject* parent)
    : Bds5Transfer(session, parent), m_plan(std::move(plan)) {
    m_tick.setInterval(kTickMs);
    connect(&m_tick, &QTimer::timeout, this, &Bds5RecordPlay::tick);
}

QString Bds5RecordPlay::variablesText() const {
    return m_plan.variables.join(QStringLiteral(", "));
}

void Bds5RecordPlay::cancel() {
    Bds5Transfer::cancel();
    if (!isRunning()) return;
    if (m_stage == Stage::Play && session())
        session()->sendUrgent("\x1b"); // Esc stops the listing
    else if (m_stage == Stage::Commands && !m_commandInFlight)
        finishCancelled();
}

void Bds5RecordPlay::abort(const QString& summary) {
    if (!isRunning() || isCancelling()) return;
    m_abortSummary = summary;
    cancel();
}

void Bds5RecordPlay::begin() {
    m_abortSummary.clear();
    m_stage = Stage::Record;
    m_nextCommand = 0;
    m_commandInFlight = false;
    m_result = {};
    m_listing.reset();
    m_plays = 0;
    if (!sessionAtInteractivePrompt()) {
        m_result.status = Bds5TransferResult::Status::Refused;
        m_result.summary = tr("The drive is not at its --> prompt (mode: %1): nothing was recorded. RECORD and "
                              "PLAY work at the interactive prompt.")
                               .arg(session() ? modeName(session()->mode()) : tr("not connected"));
        return finish(m_result);
    }
    emit stageChanged(tr("Setting up the recording (%1)").arg(m_plan.recordLine()));
    send(m_plan.recordLine());
}

void Bds5RecordPlay::answered(const Bds5Response& response) {
    switch (m_stage) {
    case Stage::Record: {
        if (!response.errors.isEmpty()) {
            const Bds5ErrorLine& e = response.errors.first();
            m_result.errors.append({0, 0, m_plan.recordLine(), e});
            m_result.status = Bds5TransferResult::Status::Refused;
            QString why;
            if (e.code == kNotRecordable)
                why = tr("%1 cannot be recorded (PE, REMOTE, TMR1-4, VAVG, VXAVG and user switches cannot).")
                          .arg(e.entry.isEmpty() ? variablesText() : e.entry);
            else if (e.code == kTooManyPoints)
                why = tr("%1 samples of %n variable(s) is more than the drive's %2 points.", nullptr,
                         int(m_plan.variables.size()))
                          .arg(m_plan.samples)
                          .arg(kRecordPoints);
            else
                why = tr("The drive refused it.");
            m_result.summary = tr("%1 — %2 Nothing was recorded.").arg(describeError(e), why);
            return finish(m_result);
        }
        if (isCancelling()) return finishCancelled();
        m_since.start();
        m_lateMs = 0;
        m_stage = Stage::Commands;
        emit stageChanged(tr("Recording %1 every %2 ms").arg(variablesText()).arg(m_plan.intervalMs));
        m_tick.start();
        return tick();
    }
    case Stage::Commands: {
        m_commandInFlight = false;
        const QString sent = m_plan.commands.value(m_nextCommand - 1).line;
        for (const Bds5ErrorLine& e : response.errors) m_result.errors.append({0, 0, sent, e});
        if (isCancelling()) return finishCancelled();
        return tick();
    }
    case Stage::Play: {
        emit playEnded(true);
        if (isCancelling()) {
            m_result.status = m_abortSummary.isEmpty() ? Bds5TransferResult::Status::Cancelled
                                                       : Bds5TransferResult::Status::Failed;
            m_result.summary = m_abortSummary.isEmpty()
                                   ? tr("Reading the recording was cancelled; it stays on the drive (PLAY again "
                                        "to read it).")
                                   : m_abortSummary;
            return finish(m_result);
        }
        if (!response.errors.isEmpty() && response.errors.first().code == kNothingRecorded && !response.garbled) {
            const Bds5ErrorLine& e = response.errors.first();
            m_result.errors.append({0, 0, QStringLiteral("PLAY"), e});
            m_result.status = Bds5TransferResult::Status::Failed;
            m_result.summary = tr("%1 — the drive holds no recording.").arg(describeError(e));
            return finish(m_result);
        }
        // Any other error line means PLAY or its answer was damaged on the wire: the copy counts as damaged.
        m_listing->addCopy(response.text, response.garbled);
        if (m_listing->complete()) {
            m_stage = Stage::Done;
            m_result.lines = m_listing->lines();
            m_result.linesDone = int(m_result.lines.size());
            m_result.summary = tr("Recorded %1 every %2 ms: %n sample(s).", nullptr, m_plan.samples)
                                   .arg(variablesText())
                                   .arg(m_plan.intervalMs);
            const int troubled = m_listing->damagedCopies() + m_listing->lostCopies();
            if (troubled > 0)
                m_result.summary += tr(" PLAY was read %1 times: the link damaged %2 of them, and the samples "
                                       "shown are the ones the readings agree on.")
                                        .arg(m_plays)
                                        .arg(troubled);
            if (!m_result.errors.isEmpty())
                m_result.summary +=
                    tr(" The drive refused \"%1\": %2.")
                        .arg(m_result.errors.first().sent, describeError(m_result.errors.first().error));
            return finish(m_result);
        }
        if (const auto other = m_listing->otherHeader()) {
            m_result.status = Bds5TransferResult::Status::Failed;
            m_result.summary = tr("The drive recorded \"%1\", not \"%2\": the RECORD command was damaged on "
                                  "its way. Nothing was shown; record again.")
                                   .arg(*other, m_plan.recordLine());
            return finish(m_result);
        }
        return playAgainOrFail(response.errors.isEmpty()
                                   ? tr("the listing was damaged")
                                   : tr("the drive answered %1").arg(describeError(response.errors.first())));
    }
    case Stage::Done: break;
    }
}

// Sends the next command when its time has come; PLAY once every command went out and the time is up.
void Bds5RecordPlay::tick() {
    if (m_stage != Stage::Commands || m_commandInFlight) return;
    const qint64 elapsed = m_since.elapsed();
    const int total = m_plan.durationMs() + m_plan.marginMs;
    emit progress(int(std::min<qint64>(elapsed, total)), total);
    if (m_nextCommand < m_plan.commands.size()) {
        // The commands keep their spacing: one the host sent late (a loaded host stalls for seconds) delays
        // those after it, rather than the next going out at once and cutting the move short on the drive.
        const Bds5RecordPlan::TimedCommand& c = m_plan.commands[m_nextCommand];
        if (elapsed < c.atMs + m_lateMs) return;
        m_lateMs = elapsed - c.atMs;
        ++m_nextCommand;
        m_commandInFlight = true;
        return send(c.line);
    }
    if (elapsed >= total + m_lateMs) sendPlay();
}

void Bds5RecordPlay::sendPlay() {
    m_tick.stop();
    m_stage = Stage::Play;
    if (!m_listing) {
        m_listing.emplace(m_plan.recordLine().toUpper(), m_plan.samples, int(m_plan.variables.size()));
        // A link that has damaged nothing since it opened gets one reading (as Motion Link read it); after
        // any damage every PLAY is read until the copies agree.
        m_listing->setTrustCleanCopy(session() && session()->linkTroubles() == 0);
    }
    ++m_plays;
    emit stageChanged(
        m_plays == 1 ? tr("Reading %n sample(s) (PLAY)", nullptr, m_plan.samples)
                     : tr("Reading %n sample(s) again to check them (PLAY %1)", nullptr, m_plan.samples).arg(m_plays));
    emit playSent(m_plays); // before the PLAY goes out: its echo may come back at once
    send(QStringLiteral("PLAY"));
    countLinesInto(0, m_plan.samples + 1);
}

// After a reading that left samples unsettled: PLAY once more, or give up saying how far it got.
void Bds5RecordPlay::playAgainOrFail(const QString& lastTrouble) {
    const bool connected = session() && session()->state() != Bds5Session::State::Closed;
    if (connected && m_plays < kMaxPlays) return sendPlay();
    m_result.status = Bds5TransferResult::Status::Failed;
    m_result.summary = tr("PLAY was read %1 times and %2 of %3 samples never came through alike often enough to "
                          "be trusted (%4 readings damaged, %5 lost; last: %6). Nothing was shown; the recording "
                          "stays on the drive — check the cable and read it again.")
                           .arg(m_plays)
                           .arg(m_listing->samples() - m_listing->samplesAgreed())
                           .arg(m_listing->samples())
                           .arg(m_listing->damagedCopies())
                           .arg(m_listing->lostCopies())
                           .arg(lastTrouble);
    if (!connected) m_result.summary = tr("The recording could not be read: %1.").arg(lastTrouble);
    finish(m_result);
}

void Bds5RecordPlay::finishCancelled() {
    m_tick.stop();
    const bool motionLeft = m_nextCommand > 0 && m_nextCommand < m_plan.commands.size();
    if (motionLeft && !m_plan.onCancel.isEmpty() && session()) session()->send(m_plan.onCancel);
    m_result.status = Bds5TransferResult::Status::Cancelled;
    m_result.summary =
        motionLeft && !m_plan.onCancel.isEmpty()
            ? tr("The recording was cancelled; \"%1\" was sent to end the test move.").arg(m_plan.onCancel)
            : tr("The recording was cancelled; nothing was read from the drive.");
    if (!m_abortSummary.isEmpty()) {
        m_result.status = Bds5TransferResult::Status::Failed;
        m_result.summary = m_abortSummary;
        if (motionLeft && !m_plan.onCancel.isEmpty())
            m_result.summary += tr(" \"%1\" was sent to end the test move.").arg(m_plan.onCancel);
    }
    finish(m_result);
}

void Bds5RecordPlay::lost(const QString& reason) {
    m_tick.stop();
    if (m_stage == Stage::Play) emit playEnded(false);
    if (m_stage == Stage::Play && m_listing && !isCancelling()) {
        m_listing->addLostCopy(); // the session asks for a prompt again; the next PLAY waits for it
        return playAgainOrFail(reason);
    }
    m_result.status = Bds5TransferResult::Status::Failed;
    m_result.summary = tr("The recording failed: %1.").arg(reason);
    finish(m_result);
}

} // namespace serialport
