// Sc750Session: talks to one SC750 over any Link with the Motion Dialogue protocol (drive_core/sc750/
// PROTOCOL.md). One command frame in flight at a time (stop and wait), each with a time-out derived from
// the baud rate and one automatic retry (after a time-out, or at once when the drive answers "!01 BAD FRAME":
// it saw the frame damaged and did nothing); the program's own output and the drive's events (breakpoint
// hit, program end, run-time error) are signalled separately. GUI thread; never blocks and never spins a
// nested event loop. The session keeps a reference to its link: whoever owns both destroys it first.
#pragma once

#include "drive_timeout.h"
#include "link.h"

#include <QObject>
#include <QTimer>

#include <deque>
#include <optional>

namespace serialport {

struct Sc750Reply {
    char letter = 0; // the command's letter ('S' answers '?'), or '!' for an error
    QString payload;
    bool isError() const { return letter == '!'; }
    int errorCode() const { return isError() ? payload.left(2).toInt() : 0; }
};

class Sc750Session final : public QObject {
    Q_OBJECT
public:
    explicit Sc750Session(Link& link, QObject* parent = nullptr);

    // Queues one command frame (letter and payload as PROTOCOL.md gives them). Returns an id that
    // finished() or failed() carries; a drive error reply ("!nn TEXT") arrives through failed().
    // repeatable: the command may safely reach the drive twice (V, ?, the download's D, W and Z): a damaged
    // answer frame sends it again at once instead of after the time-out, or fails it when the retry is
    // spent. Not for others: a damaged frame might be an event's, and the real answer still on its way.
    quint64 send(char letter, const QString& payload = {}, bool repeatable = false);
    // Ctrl C, written at once ahead of the queue: stops the program and motion; programStopped follows,
    // stopSent() at once (a download in progress stops too).
    void sendStop();
    // Bytes for the running program's INPUT/INKEY$ (the output window), passed through untouched.
    void sendProgramInput(const QByteArray& bytes);
    // Multidrop logon "/nnn" (not for axis 255), written at once.
    void logOn(int axis);
    // Drops every queued command not yet sent (each gets failed()).
    void cancelPending();
    bool busy() const { return m_current.has_value() || !m_queue.empty(); }
    Link& link() { return m_link; }

signals:
    void finished(quint64 id, const serialport::Sc750Reply& reply);
    void failed(quint64 id, const QString& reason);
    void programOutput(const QByteArray& bytes); // PRINT output and INPUT echo, for the output window
    void breakpointHit(int line);
    void programEnded(int line);
    void programStopped(int line); // Ctrl C or a STOP statement
    void runTimeError(int faultCode, int line, const QString& text);
    void rawReceived(const QByteArray& bytes);
    void rawSent(const QByteArray& bytes);
    void stopSent(); // sendStop() wrote Ctrl C

private:
    struct Pending {
        quint64 id = 0;
        char letter = 0;
        QByteArray frame;
        int retries = 1;
        bool repeatable = false;
    };

    void onBytes(const QByteArray& bytes);
    void onFrame(const QByteArray& body);
    void onTimeout();
    void pump();
    void write(const QByteArray& bytes);
    int timeoutMs(const QByteArray& frame) const;

    Link& m_link;
    std::deque<Pending> m_queue;
    std::optional<Pending> m_current;
    QByteArray m_frame;
    bool m_inFrame = false;
    QByteArray m_output; // program bytes of one read, emitted together
    quint64 m_nextId = 1;
    DriveTimeout m_timeout{m_link};
};

} // namespace serialport

Q_DECLARE_METATYPE(serialport::Sc750Reply)
