// The SC750 .BIN download (see sc750_download.h and PROTOCOL.md §4).
#include "sc750_download.h"

#include "drive_core/sc750/sc750_bin.h"
#include "drive_core/sc750/sc750_frame.h"
#include "drive_core/sc750/sc750_program.h"

#include <QRegularExpression>

namespace serialport {

namespace sc = drive_core::sc750;

namespace {
constexpr std::size_t kMaxChunk = 64; // the drive takes up to 64 bytes a W frame
constexpr std::size_t kMinChunk = 8;
constexpr int kGrowAfter = 4; // acknowledged chunks in a row before the chunk size doubles again

// Answers that end the download: the drive refused for a reason another try will not change (PROTOCOL.md
// §4): 03 program running, and at Z 05 image refused or 06 incompatible version. Read whole and only where
// the drive gives them: a damaged answer can pass the frame checksum (a sum: "!04 OFFSET" with two bits
// flipped reads "!05 OFFRET") and must not pass for a refusal.
bool refusal(const QString& reason, bool atEnd) {
    static const QRegularExpression kAnyTime(QStringLiteral("^03 PROGRAM RUNNING$"));
    static const QRegularExpression kAtEnd(QStringLiteral("^06 incompatible|^05 (?!CHECKSUM$)"));
    return kAnyTime.match(reason).hasMatch() || (atEnd && kAtEnd.match(reason).hasMatch());
}
} // namespace

Sc750Download::Sc750Download(Sc750Session& session, std::vector<std::uint8_t> bin, QObject* parent)
    : QObject(parent), m_session(session), m_bin(std::move(bin)) {
    connect(&m_session, &Sc750Session::finished, this, &Sc750Download::onFinished);
    connect(&m_session, &Sc750Session::failed, this, &Sc750Download::onFailed);
    connect(&m_session, &Sc750Session::stopSent, this, [this] {
        m_stopped = !m_cancelled;
        m_cancelled = true;
    });
}

void Sc750Download::start() {
    m_step = Step::Identify; // first make sure the drive takes this .BIN version (PROTOCOL.md §7)
    sendStep();
}

void Sc750Download::cancel() {
    m_cancelled = true;
}

void Sc750Download::sendStep() {
    if (m_cancelled)
        return finish(false, QStringLiteral("%1 at byte %2 of %3; %4")
                                 .arg(m_stopped ? QStringLiteral("stopped (Ctrl C)") : QStringLiteral("cancelled"))
                                 .arg(m_offset)
                                 .arg(m_bin.size())
                                 .arg(heldProgram()));
    switch (m_step) {
    case Step::Identify: m_waiting = m_session.send('V', {}, true); return;
    case Step::Begin: {
        const QString crc = QStringLiteral("%1").arg(sc::crc32(m_bin), 8, 16, QLatin1Char('0')).toUpper();
        m_waiting = m_session.send('D', QString::number(m_bin.size()) + QLatin1Char(',') + crc, true);
        return;
    }
    case Step::Write: {
        if (m_offset >= m_bin.size()) {
            m_step = Step::End;
            return sendStep();
        }
        const std::size_t n = std::min(m_chunk, m_bin.size() - m_offset);
        const std::string chunk(m_bin.begin() + long(m_offset), m_bin.begin() + long(m_offset + n));
        m_waiting = m_session.send(
            'W', QString::number(m_offset) + QLatin1Char(',') + QString::fromStdString(sc::toHex(chunk)), true);
        return;
    }
    case Step::End:
        m_endSent = true;
        m_waiting = m_session.send('Z', {}, true);
        return;
    }
}

void Sc750Download::onFinished(quint64 id, const Sc750Reply& reply) {
    if (id != m_waiting || m_done) return;
    m_failures = 0;
    if (reply.letter == 'V') {
        const int version = reply.payload.section(QLatin1Char(','), 2, 2).toInt();
        if (version != sc::kBinVersion)
            return finish(false, QStringLiteral("the SC750 takes .BIN version %1, this is version %2")
                                     .arg(version)
                                     .arg(sc::kBinVersion));
        m_step = Step::Begin;
        return sendStep();
    }
    if (reply.letter == 'D') {
        m_step = Step::Write;
        m_offset = 0;
        emit progress(0, qint64(m_bin.size()));
        return sendStep();
    }
    if (reply.letter == 'W') {
        m_offset = std::min<std::size_t>(std::size_t(reply.payload.toULongLong()), m_bin.size());
        if (++m_successes >= kGrowAfter && m_chunk < kMaxChunk) {
            m_chunk *= 2;
            m_successes = 0;
        }
        emit progress(qint64(m_offset), qint64(m_bin.size()));
        return sendStep();
    }
    if (reply.letter == 'Z')
        finish(true,
               QStringLiteral("downloaded: %1 bytes of code, %2 of data")
                   .arg(reply.payload.section(QLatin1Char(','), 0, 0), reply.payload.section(QLatin1Char(','), 1, 1)));
}

void Sc750Download::onFailed(quint64 id, const QString& reason) {
    if (id != m_waiting || m_done) return;
    // "04 OFFSET n": an acknowledgement was lost and the chunk resent; go on from where the drive is.
    if (reason.startsWith(QLatin1String("04 OFFSET ")) && m_step == Step::Write) {
        m_offset = std::min<std::size_t>(std::size_t(reason.mid(10).toULongLong()), m_bin.size());
        return sendStep();
    }
    // The transfer no longer adds up: bytes damaged on the way (the CRC check failed), or no transfer open
    // after a Z whose answer was lost (the image may be loaded already). Start again from D.
    const bool inTransfer = m_step == Step::Write || m_step == Step::End;
    if (inTransfer && (reason.startsWith(QLatin1String("04 ")) || reason == QLatin1String("05 CHECKSUM")))
        return restart(reason);
    if (refusal(reason, m_step == Step::End)) return finish(false, reason);
    if (!m_session.link().isOpen())
        return finish(false, QStringLiteral("the connection closed at byte %1 of %2 (%3); %4")
                                 .arg(m_offset)
                                 .arg(m_bin.size())
                                 .arg(reason, heldProgram()));
    // Anything else is the wire's doing: the frame or its answer was lost or damaged (a time-out, "01 BAD
    // FRAME", an answer damaged past recognition). Sending the same frame again is safe: the drive either
    // did nothing or answers with where it is.
    if (++m_failures >= kMaxFailuresInARow)
        return finish(false, QStringLiteral("%1 tries in a row failed (last: %2) at byte %3 of %4; %5")
                                 .arg(m_failures)
                                 .arg(reason)
                                 .arg(m_offset)
                                 .arg(m_bin.size())
                                 .arg(heldProgram()));
    m_successes = 0;
    m_chunk = std::max(kMinChunk, m_chunk / 2);
    sendStep();
}

void Sc750Download::restart(const QString& reason) {
    if (++m_restarts > kMaxRestarts)
        return finish(false, QStringLiteral("the SC750 answered %1 again after %2 fresh starts; %3")
                                 .arg(reason)
                                 .arg(kMaxRestarts)
                                 .arg(heldProgram()));
    m_step = Step::Begin;
    m_failures = 0;
    m_chunk = kMinChunk;
    sendStep();
}

QString Sc750Download::heldProgram() const {
    return m_endSent ? QStringLiteral("the SC750 holds either its old program or this one — download again")
                     : QStringLiteral("the SC750 keeps its old program");
}

void Sc750Download::finish(bool ok, const QString& message) {
    m_done = true;
    emit finished(ok, message);
}

} // namespace serialport
