// Bds5Session: talks to one BDS5 over any Link. An asynchronous state machine: it sends a queued command
// only at a prompt, collects the response up to the next prompt, and reports typed results and ERR lines.
// GUI thread; never blocks and never spins a nested event loop. The session keeps a reference to its
// link: whoever owns both destroys the session first.
#pragma once

#include "bds5_protocol.h"
#include "drive_timeout.h"
#include "link.h"

#include <QList>
#include <QObject>
#include <QStringList>
#include <QTimer>

#include <deque>
#include <optional>
#include <utility>

namespace serialport {

struct Bds5Response {
    QString command;
    QStringList lines;           // output lines without CR LF; ERR lines are in errors instead
    QList<Bds5ErrorLine> errors; // errors the drive reported for this command (and held ones it flushed)
    QString prompt;              // the prompt that ended the response
    QString text;                // everything between the echo and the prompt, CR LF and empty lines kept
    bool ignored = false;        // ERROR MSG WAITING--COMMAND IGNORED, still so after the one automatic retry
    bool garbled = false; // began with neither the echo nor a bare line end: damaged on the wire either way
};

class Bds5Session final : public QObject {
    Q_OBJECT
public:
    enum class State { Closed, WaitingForPrompt, Ready, Busy };
    // Whether a command and its answer appear in the terminal (shownReceived). Background polls (the
    // variable browser, the I/O panel) are quiet, so the terminal shows only what the user did.
    enum class Echo { Shown, Quiet };

    explicit Bds5Session(Link& link, QObject* parent = nullptr);

    // Queues one instruction (without CR). Returns an id that finished()/failed() carry.
    quint64 send(const QString& line, Echo echo = Echo::Shown);
    // Queues an Esc (no CR): leaves program-load mode (>BDS) at the next prompt; finished() carries the
    // prompt that follows (-->). Used by transfers to end a download.
    quint64 sendEscape();
    // Bytes typed in a terminal, passed through untouched; held while a queued command is in flight.
    void sendRaw(const QByteArray& bytes);
    // Attention characters from the user (^X, Esc): written at once, ahead of held terminal bytes and of
    // every queued command, even during a transfer; otherwise treated like sendRaw (mode and state).
    void sendUrgent(const QByteArray& bytes);
    // Drops every queued command that has not been sent yet (each gets failed()).
    void cancelPending();

    State state() const { return m_state; }
    Bds5Mode mode() const { return m_mode; }
    QString lastPrompt() const { return m_prompt; }
    Link& link() { return m_link; }
    // Answers the wire damaged (no echo where one belonged) and commands that timed out, since the link
    // opened. Bds5RecordPlay reads PLAY once while this is 0 and twice (and more) after.
    int linkTroubles() const { return m_linkTroubles; }

signals:
    void rawReceived(const QByteArray& bytes);   // every byte from the drive, for captures and watchers
    void shownReceived(const QByteArray& bytes); // the same, less the echo and answer of quiet commands
    void rawSent(const QByteArray& bytes);     // every byte written to the drive, as written (captures)
    void modeChanged(serialport::Bds5Mode mode, const QString& prompt);
    void stateChanged(serialport::Bds5Session::State state);
    void finished(quint64 id, const serialport::Bds5Response& response);
    void failed(quint64 id, const QString& reason);
    // sendUrgent() wrote a ^X (Stop Motion): a download in progress stops too (Bds5Download).
    void stopSent();

private:
    struct Pending {
        quint64 id;
        QString line;
        int retries = 1;
        QByteArray bytes; // written instead of line + CR when not empty (Esc)
        bool quiet = false;
    };

    void onBytes(const QByteArray& bytes);
    void onPromptConfirmed();
    void onTimeout();
    void fallAsleep();
    void onLinkOpened();
    void onLinkClosed();
    void pump();
    void passRaw(const QByteArray& bytes);
    void write(const QByteArray& bytes);
    void setState(State state);
    Bds5Response parseResponse(const Pending& command, QString text, const QString& prompt) const;
    int timeoutMsFor(const QString& line) const;
    static bool strayPromptBeforeEcho(const QString& text, const QString& line);

    Link& m_link;
    State m_state = State::Closed;
    Bds5Mode m_mode = Bds5Mode::Unknown;
    QString m_prompt;
    QString m_tail;     // the last bytes received, to recognise a prompt
    QString m_response; // everything received since the current command was sent
    std::deque<Pending> m_queue;
    std::optional<Pending> m_current;
    QByteArray m_heldRaw;      // terminal bytes waiting for the current command to finish
    bool m_rawLineOpen = false; // the terminal user has typed part of a line
    bool m_resyncing = false;   // a command timed out: asking for a prompt until one comes
    quint64 m_nextId = 1;
    int m_linkTroubles = 0;
    QTimer m_silence;
    DriveTimeout m_timeout{m_link};
    QTimer m_wake;
    QTimer m_runDetect;
};

} // namespace serialport

Q_DECLARE_METATYPE(serialport::Bds5Response)
