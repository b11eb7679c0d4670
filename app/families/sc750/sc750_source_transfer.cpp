// Sc750SourceTransfer: the T/t/Q and u exchanges, one frame at a time.
#include "sc750_source_transfer.h"

#include "sc750_workspace.h"

#include "drive_core/sc750/sc750_bin.h"

#include <span>

namespace app {

Sc750SourceTransfer::Sc750SourceTransfer(Sc750Workspace& workspace) : QObject(&workspace), m_workspace(workspace) {}

void Sc750SourceTransfer::download(const QByteArray& source) {
    m_bytes = source;
    const auto* data = reinterpret_cast<const std::uint8_t*>(m_bytes.constData());
    const std::uint32_t crc = drive_core::sc750::crc32(std::span(data, std::size_t(m_bytes.size())));
    const QString payload = QStringLiteral("%1,%2").arg(m_bytes.size()).arg(crc, 8, 16, QLatin1Char('0')).toUpper();
    m_workspace.send('T', payload, [this](const serialport::Sc750Reply&) { sendChunk(); },
                     [this](const QString& why) { finish(false, why); });
}

void Sc750SourceTransfer::sendChunk() {
    if (m_cancelled) return finish(false, tr("cancelled; the controller keeps its old source"));
    emit progress(m_offset, m_bytes.size());
    if (m_offset >= m_bytes.size()) {
        m_workspace.send('Q', {}, [this](const serialport::Sc750Reply&) { finish(true, tr("Source stored in the controller")); },
                         [this](const QString& why) { finish(false, why); });
        return;
    }
    const QByteArray chunk = m_bytes.mid(m_offset, kChunkBytes);
    const QString payload = QStringLiteral("%1,%2").arg(m_offset).arg(QString::fromLatin1(chunk.toHex().toUpper()));
    m_workspace.send(
        't', payload,
        [this](const serialport::Sc750Reply& reply) {
            m_offset = reply.payload.toLongLong(); // the bytes the controller holds
            sendChunk();
        },
        [this](const QString& why) { finish(false, why); });
}

void Sc750SourceTransfer::upload() {
    m_bytes.clear();
    m_offset = 0;
    askChunk();
}

void Sc750SourceTransfer::askChunk() {
    if (m_cancelled) return finish(false, tr("cancelled"));
    m_workspace.send(
        'u', QString::number(m_offset),
        [this](const serialport::Sc750Reply& reply) {
            const QByteArray chunk = QByteArray::fromHex(reply.payload.section(QLatin1Char(','), 1).toLatin1());
            if (chunk.isEmpty()) return finish(true, tr("Source read from the controller"));
            m_bytes += chunk;
            m_offset += chunk.size();
            emit progress(m_offset, 0);
            askChunk();
        },
        [this](const QString& why) { finish(false, why); });
}

void Sc750SourceTransfer::cancel() {
    m_cancelled = true;
}

void Sc750SourceTransfer::finish(bool ok, const QString& message) {
    emit finished(ok, ok ? m_bytes : QByteArray(), message);
    deleteLater();
}

} // namespace app
