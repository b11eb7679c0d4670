// Bds5Download: the >BDS state machine.
#include "bds5_download.h"

#include "bds5_verify.h"

namespace serialport {

namespace {
const QString kLoadPrompt = QStringLiteral("l->");
constexpr int kEditPassword = 110; // ERR 110 EDIT PASSWORD (L7123-7134)
constexpr int kProgramFull = 86;   // ERR 86 USER PROGRAM FULL (L7396)

bool isLoadPrompt(const QString& prompt) {
    return modeOfPrompt(prompt) == Bds5Mode::ProgramLoad;
}
} // namespace

Bds5Download::Bds5Download(Bds5Session& session, const QString& programText, Options options, QObject* parent)
    : Bds5Transfer(session, parent), m_program(Bds5ProgramText::prepare(programText, options.stripComments)),
      m_options(std::move(options)) {
    connect(&session, &Bds5Session::stopSent, this, [this] {
        if (!isRunning() || isCancelling()) return;
        m_stopped = true;
        cancel();
    });
}

void Bds5Download::begin() {
    m_result = {};
    if (!sessionAtInteractivePrompt()) {
        m_result.status = Bds5TransferResult::Status::Refused;
        m_result.summary =
            tr("The drive is not at its --> prompt (mode: %1): nothing was sent and its program "
               "is unchanged. Stop the program (Break) and download again.")
                .arg(session() ? modeName(session()->mode()) : tr("not connected"));
        return finish(m_result);
    }
    if (m_program.lineCount() == 0) {
        m_result.status = Bds5TransferResult::Status::Refused;
        m_result.summary = tr("The program is empty: nothing was sent and the drive's program is unchanged.");
        return finish(m_result);
    }
    m_attempt = 1;
    enter();
}

void Bds5Download::enter() {
    m_step = Step::Entering;
    emit stageChanged(m_attempt == 1 ? tr("Sending the program")
                                     : tr("Sending the program (attempt %1 of %2)")
                                           .arg(m_attempt)
                                           .arg(m_options.attempts));
    emit progress(0, m_program.lineCount());
    send(m_options.password.isEmpty() ? QStringLiteral(">BDS")
                                      : QStringLiteral(">BDS %1").arg(m_options.password));
}

bool Bds5Download::retry(const QString& reason) {
    if (isCancelling() || m_full || m_attempt >= m_options.attempts || !session()) return false;
    // A closed link (the cable pulled) is not a damaged line: say so now rather than wait for it.
    if (session()->state() == Bds5Session::State::Closed) return false;
    ++m_attempt;
    m_result = {};
    m_sent = 0;
    m_leftLoadMode.clear();
    if (m_verify) {
        m_verify->disconnect(this);
        m_verify->deleteLater();
        m_verify = nullptr;
    }
    emit stageChanged(tr("%1 — starting again").arg(reason));
    // Esc leaves program-load mode if the drive is still in it, and is harmless at -->. >BDS then starts
    // an empty program, so nothing of the damaged attempt survives.
    m_step = Step::Resyncing;
    sendEscape();
    return true;
}

void Bds5Download::answered(const Bds5Response& response) {
    switch (m_step) {
    case Step::Resyncing: return enter();
    case Step::Entering:
        for (const Bds5ErrorLine& e : response.errors) {
            if (e.code != kEditPassword && retry(tr("The drive answered >BDS with %1").arg(describeError(e))))
                return;
            m_result.status = Bds5TransferResult::Status::Refused;
            m_result.errors.append({0, 0, response.command, e});
            m_result.summary =
                e.code == kEditPassword
                    ? tr("The drive's program is protected by an editor password (ERR 110 EDIT PASSWORD): "
                         "nothing was sent and its program is unchanged. Enter the password (Program > Drive "
                         "Password...) and download again.")
                    : tr("The drive refused >BDS with %1: nothing was sent and its program is unchanged.")
                          .arg(describeError(e));
            return finish(m_result);
        }
        if (!isLoadPrompt(response.prompt)) {
            if (retry(tr("The drive answered >BDS with \"%1\"").arg(response.prompt))) return;
            m_result.status = Bds5TransferResult::Status::Refused;
            m_result.summary =
                tr("The drive answered >BDS with \"%1\" instead of the l-> prompt: nothing was sent "
                   "and its program is unchanged.")
                    .arg(response.prompt);
            return finish(m_result);
        }
        m_step = Step::Sending;
        if (isCancelling()) return leave(); // Esc before the first line: the program is unchanged
        return sendNextLine();
    case Step::Sending: {
        const int driveLine = m_sent + 1;
        for (const Bds5ErrorLine& e : response.errors) {
            m_result.errors.append({m_program.sourceLine(driveLine), driveLine, response.command, e});
            if (e.code == kProgramFull) m_full = true;
        }
        if (!isLoadPrompt(response.prompt)) { // power cycle, reset: the rest must not run as commands
            if (retry(tr("The drive left program-load mode at line %1").arg(m_sent + 1))) return;
            m_leftLoadMode = response.prompt;
            return finish([this] {
                m_result.status = Bds5TransferResult::Status::Failed;
                m_result.summary = tr("The drive left program-load mode at line %1 of %2 (it answered with "
                                      "\"%3\"). %4 Download again.")
                                       .arg(m_sent + 1)
                                       .arg(m_program.lineCount())
                                       .arg(m_leftLoadMode, heldText());
                m_result.linesDone = m_sent;
                return m_result;
            }());
        }
        // The echo came back damaged: the line may have reached the drive damaged too, and load mode cannot
        // take a line back. Start again now rather than learn it from the read-back.
        if (response.garbled && retry(tr("Drive line %1 came back damaged").arg(driveLine))) return;
        if (!m_full) ++m_sent;
        emit progress(m_sent, m_program.lineCount());
        if (m_full || isCancelling() || m_sent == m_program.lineCount()) return leave();
        return sendNextLine();
    }
    case Step::Leaving:
        return afterLeaving(response);
    case Step::Verifying:
        return;
    }
}

void Bds5Download::sendNextLine() {
    send(m_program.lines().at(m_sent));
}

void Bds5Download::leave() {
    m_step = Step::Leaving;
    sendEscape();
}

void Bds5Download::cancel() {
    Bds5Transfer::cancel();
    if (m_verify) m_verify->cancel();
}

QString Bds5Download::strippedText() const {
    if (m_program.skippedLines() == 0) return {};
    return tr(" (%n comment or blank line(s) not sent)", nullptr, m_program.skippedLines());
}

QString Bds5Download::heldText() const {
    if (m_sent == 0) return tr("The drive's program is unchanged.");
    return tr("The drive now holds only the first %n line(s) of the program: do not run it.", nullptr,
              m_sent);
}

void Bds5Download::afterLeaving(const Bds5Response&) {
    m_result.linesDone = m_sent;
    const int total = m_program.lineCount();
    if (m_full) {
        m_result.status = Bds5TransferResult::Status::Failed;
        const int line = m_sent + 1;
        m_result.summary =
            tr("The program does not fit in the drive (ERR 86 USER PROGRAM FULL at drive line %1, "
               "editor line %2). %3 Shorten the program or download it without comments.")
                .arg(line)
                .arg(m_program.sourceLine(line))
                .arg(heldText());
        return finish(m_result);
    }
    if (isCancelling()) {
        m_result.status = Bds5TransferResult::Status::Cancelled;
        m_result.summary = (m_stopped ? tr("Stopped (^X): download cancelled after %1 of %2 lines. %3")
                                      : tr("Download cancelled after %1 of %2 lines. %3"))
                               .arg(m_sent)
                               .arg(total)
                               .arg(heldText());
        return finish(m_result);
    }
    if (!m_options.verify) {
        m_result.summary = tr("Downloaded %n line(s)%1 (not verified).", nullptr, total).arg(strippedText());
        return finish(m_result);
    }
    m_step = Step::Verifying;
    m_reads = 0;
    startVerify();
}

void Bds5Download::startVerify() {
    const int total = m_program.lineCount();
    ++m_reads;
    if (m_verify) {
        m_verify->disconnect(this);
        m_verify->deleteLater();
    }
    m_verify = new Bds5Verify(*session(), m_program, this);
    connect(m_verify, &Bds5Transfer::stageChanged, this, &Bds5Transfer::stageChanged);
    connect(m_verify, &Bds5Transfer::progress, this, &Bds5Transfer::progress);
    connect(m_verify, &Bds5Transfer::finished, this, [this, total](const Bds5TransferResult& verified) {
        using Status = Bds5TransferResult::Status;
        if (verified.status == Status::Mismatch || verified.status == Status::Failed) {
            // The read-back itself crosses the wire: read once more before sending everything again.
            if (m_reads < 2 && !isCancelling()) return startVerify();
            if (retry(verified.summary)) return;
        }
        Bds5TransferResult r = verified;
        r.errors = m_result.errors + r.errors;
        r.linesDone = m_sent;
        if (r.status == Bds5TransferResult::Status::Cancelled)
            r.summary =
                tr("Downloaded %n line(s); verification was cancelled, so the drive's program was not "
                   "compared.",
                   nullptr, total);
        else
            r.summary = tr("Downloaded %n line(s)%1. ", nullptr, total).arg(strippedText()) + r.summary;
        finish(r);
    });
    m_verify->start();
}

void Bds5Download::lost(const QString& reason) {
    if (m_step != Step::Verifying && retry(tr("No answer from the drive (%1)").arg(reason))) return;
    m_result.status = Bds5TransferResult::Status::Failed;
    m_result.linesDone = m_sent;
    if (m_step == Step::Entering || m_step == Step::Resyncing) {
        // >BDS may have reached the drive even though its l-> did not come back.
        if (session()) session()->sendUrgent("\x1b");
        m_result.summary = tr("No answer from the drive when starting the download (%1). The drive may have "
                              "started an empty program; download again.")
                               .arg(reason);
    } else {
        // The drive may still be in program-load mode: leave it, so nothing typed later lands in the program.
        if (session()) session()->sendUrgent("\x1b");
        m_result.summary = tr("No answer from the drive during the download (%1), after %2 of %3 lines. %4 "
                              "Download again.")
                               .arg(reason)
                               .arg(m_sent)
                               .arg(m_program.lineCount())
                               .arg(heldText());
    }
    finish(m_result);
}

} // namespace serialport
