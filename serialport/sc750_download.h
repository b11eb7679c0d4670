// Sc750Download: Options > Download BIN File, and the download half of Compile > Run Program. Checks the
// drive's .BIN version (V), sends D (size, CRC-32), the .BIN in 64-byte W frames, then Z; the drive checks
// CRC and version before it replaces its program. Progress per acknowledged chunk, cancel between chunks;
// a lost acknowledgement resumes at the offset the drive reports. Asynchronous; no nested event loop.
#pragma once

#include "sc750_session.h"

#include <QObject>

#include <cstdint>
#include <vector>

namespace serialport {

class Sc750Download final : public QObject {
    Q_OBJECT
public:
    Sc750Download(Sc750Session& session, std::vector<std::uint8_t> bin, QObject* parent = nullptr);

    void start();
    void cancel(); // takes effect at the next acknowledgement; the drive keeps its old program

signals:
    void progress(qint64 sent, qint64 total);
    // ok: the drive holds the new program; otherwise message says why (the drive's error or a time-out).
    void finished(bool ok, const QString& message);

private:
    void onFinished(quint64 id, const Sc750Reply& reply);
    void onFailed(quint64 id, const QString& reason);
    void begin();
    void sendChunk();
    void finish(bool ok, const QString& message);

    Sc750Session& m_session;
    std::vector<std::uint8_t> m_bin;
    std::size_t m_offset = 0;
    quint64 m_waiting = 0;
    bool m_cancelled = false;
    bool m_done = false;
};

} // namespace serialport
