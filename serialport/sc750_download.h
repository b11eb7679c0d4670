// Sc750Download: Options > Download BIN File, and the download half of Compile > Run Program. Checks the
// drive's .BIN version (V), sends D (size, CRC-32), the .BIN in 64-byte W frames, then Z; the drive checks
// CRC and version before it replaces its program. Progress per acknowledged chunk, cancel between chunks;
// a lost acknowledgement resumes at the offset the drive reports. Over a damaged wire: a lost or damaged
// frame is sent again (up to kMaxFailuresInARow in a row) and the chunks shrink to 8 bytes while frames get
// lost, growing back as they get through; when the drive's transfer no longer adds up (its CRC check at Z
// fails, or it has no transfer open after a Z whose answer was lost) the download starts again from D, up
// to kMaxRestarts times. The CRC-32 the drive checks before loading is what makes a damaged image
// impossible to load. Asynchronous; no nested event loop.
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
    // Takes effect at the next acknowledgement: no further frame goes out, and the drive keeps its old
    // program. A Ctrl C sent meanwhile (Sc750Session::sendStop, Stop Program) cancels too.
    void cancel();

    static constexpr int kMaxFailuresInARow = 12; // lost or damaged frames in a row before giving up
    static constexpr int kMaxRestarts = 3;        // fresh starts from D when the transfer no longer adds up

signals:
    void progress(qint64 sent, qint64 total);
    // ok: the drive holds the new program; otherwise message says why (the drive's error or a time-out).
    void finished(bool ok, const QString& message);

private:
    enum class Step { Identify, Begin, Write, End };
    void onFinished(quint64 id, const Sc750Reply& reply);
    void onFailed(quint64 id, const QString& reason);
    void sendStep();
    void restart(const QString& reason);
    void finish(bool ok, const QString& message);
    QString heldProgram() const;

    Sc750Session& m_session;
    std::vector<std::uint8_t> m_bin;
    Step m_step = Step::Identify;
    std::size_t m_offset = 0;
    std::size_t m_chunk = 64;
    int m_failures = 0;  // lost or damaged frames in a row
    int m_successes = 0; // acknowledged chunks in a row since the chunk size last changed
    int m_restarts = 0;
    bool m_endSent = false; // a Z went out: the drive may have loaded the image even if its answer was lost
    quint64 m_waiting = 0;
    bool m_cancelled = false;
    bool m_stopped = false; // cancelled by Ctrl C
    bool m_done = false;
};

} // namespace serialport
