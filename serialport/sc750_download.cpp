// The SC750 .BIN download (see sc750_download.h and PROTOCOL.md §4).
#include "sc750_download.h"

#include "drive_core/sc750/sc750_bin.h"
#include "drive_core/sc750/sc750_frame.h"
#include "drive_core/sc750/sc750_program.h"

namespace serialport {

namespace sc = drive_core::sc750;

namespace {
constexpr std::size_t kChunk = 64;
}

Sc750Download::Sc750Download(Sc750Session& session, std::vector<std::uint8_t> bin, QObject* parent)
    : QObject(parent), m_session(session), m_bin(std::move(bin)) {
    connect(&m_session, &Sc750Session::finished, this, &Sc750Download::onFinished);
    connect(&m_session, &Sc750Session::failed, this, &Sc750Download::onFailed);
}

void Sc750Download::start() {
    m_waiting = m_session.send('V'); // first make sure the drive takes this .BIN version (PROTOCOL.md §7)
}

void Sc750Download::begin() {
    const QString crc = QStringLiteral("%1").arg(sc::crc32(m_bin), 8, 16, QLatin1Char('0')).toUpper();
    m_waiting = m_session.send('D', QString::number(m_bin.size()) + QLatin1Char(',') + crc);
    emit progress(0, qint64(m_bin.size()));
}

void Sc750Download::cancel() {
    m_cancelled = true;
}

void Sc750Download::sendChunk() {
    if (m_cancelled) return finish(false, QStringLiteral("cancelled"));
    if (m_offset >= m_bin.size()) {
        m_waiting = m_session.send('Z');
        return;
    }
    const std::size_t n = std::min(kChunk, m_bin.size() - m_offset);
    const std::string chunk(m_bin.begin() + long(m_offset), m_bin.begin() + long(m_offset + n));
    m_waiting =
        m_session.send('W', QString::number(m_offset) + QLatin1Char(',') + QString::fromStdString(sc::toHex(chunk)));
}

void Sc750Download::onFinished(quint64 id, const Sc750Reply& reply) {
    if (id != m_waiting || m_done) return;
    if (reply.letter == 'V') {
        const int version = reply.payload.section(QLatin1Char(','), 2, 2).toInt();
        if (version != sc::kBinVersion)
            return finish(false, QStringLiteral("the SC750 takes .BIN version %1, this is version %2")
                                     .arg(version)
                                     .arg(sc::kBinVersion));
        return begin();
    }
    if (reply.letter == 'D') return sendChunk();
    if (reply.letter == 'W') {
        m_offset = std::size_t(reply.payload.toULongLong());
        emit progress(qint64(m_offset), qint64(m_bin.size()));
        return sendChunk();
    }
    if (reply.letter == 'Z')
        finish(true,
               QStringLiteral("downloaded: %1 bytes of code, %2 of data")
                   .arg(reply.payload.section(QLatin1Char(','), 0, 0), reply.payload.section(QLatin1Char(','), 1, 1)));
}

void Sc750Download::onFailed(quint64 id, const QString& reason) {
    if (id != m_waiting || m_done) return;
    // "04 OFFSET n": an acknowledgement was lost and the chunk resent; go on from where the drive is.
    if (reason.startsWith(QLatin1String("04 OFFSET "))) {
        m_offset = std::size_t(reason.mid(10).toULongLong());
        return sendChunk();
    }
    finish(false, reason);
}

void Sc750Download::finish(bool ok, const QString& message) {
    m_done = true;
    emit finished(ok, message);
}

} // namespace serialport
