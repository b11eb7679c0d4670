// Pmc960Session: talks to one ORMEC PMC-960 over any Link. An asynchronous state machine: a queued command
// is written only at the ready prompt (CR LF <axis> }), its response collected up to the next prompt,
// #xx error codes decoded from the catalog. Status polls (<attn> + b f g h i m s v) go out between commands, so
// a poll timer never disturbs command traffic, and while a command typed in the terminal runs (a routine, B<label>:
// its prompt comes when it ends), which the controller allows at any time (5.3.3, L821, L2554). Keeps the sum of
// every byte written (polls excluded), to compare with the controller's communications checksum (<attn>h, 5.3.6).
// GUI thread; never blocks, no nested event loops. The link must outlive the session.
#pragma once

#include "drive_timeout.h"
#include "link.h"

#include <QByteArray>
#include <QElapsedTimer>
#include <QObject>
#include <QString>
#include <QTimer>

#include <deque>
#include <optional>
#include <vector>

namespace serialport {

struct Pmc960Response {
    QByteArray command; // as written
    QByteArray text;    // everything between the echo and the prompt
    QString value;      // text without error codes and CR LF: "3500" for A?
    int error = 0;      // the command's own #xx code (0x80..0xDF), 0 if none
    QString errorText;  // the catalog's message for error
    std::vector<int> asynchronous; // E-codes that arrived while it was on the line (also sent as asyncError)
};

class Pmc960Session final : public QObject {
    Q_OBJECT
public:
    enum class State { Closed, WaitingForPrompt, Ready, Busy };

    explicit Pmc960Session(Link& link, QObject* parent = nullptr);

    // Queues bytes that end in a prompt: "A3500\r", "A?" (a display character ends the command), "P{}".
    // timeoutMs: how long the prompt may take, counted from the write; 0 derives it from the link's baud
    // rate and the command's time (Pmc960Timing). Returns an id that finished()/failed() carry.
    quint64 send(const QByteArray& command, int timeoutMs = 0);
    // Queues a status poll; pollAnswered(id, letter, value) carries the reply (decimal or hex output). Polls go
    // ahead of queued commands while a typed command runs (see sendTyped()).
    quint64 poll(char letter, int timeoutMs = 0);
    // Queues bytes that produce no prompt (program text in the P editor): written in turn, finished()
    // follows once `expect` has arrived (the editor's echo), or at once if expect is empty.
    quint64 sendExpecting(const QByteArray& bytes, const QByteArray& expect, int timeoutMs = 0);
    // Bytes typed in the terminal, written as they are (in the checksum) once no request is in flight. From
    // the first typed byte until the controller's next prompt the line is the user's: queued requests wait, so
    // neither the user's command nor ours is cut in two. Polls wait too until the typed command is complete
    // (CR or a display character) and the line has been quiet for kTypedQuietMs: then the command is running
    // (a routine, a dwell) and a poll, answered at once between its steps, cuts in — never into a half-typed
    // command, a % display (any character ends it, L775), or after one went unanswered in this command.
    void sendTyped(const QByteArray& bytes);
    // Drops every queued request not yet written (each gets failed()).
    void cancelPending();
    // Back to the prompt from wherever the controller is (in the P editor, deselected by a damaged
    // <attn><ID>): the request in flight fails, and `first` (e.g. ESC) + CR go out now and again every
    // 300 ms until a prompt comes, with <attn><ID> once the controller stays silent. For transfers that failed
    // part-way; queued requests wait for the prompt.
    void resynchronise(const QByteArray& first);
    // Polls letters (e.g. "gfvm") every intervalMs while the session is ready and idle, or a typed command runs;
    // 0 stops.
    void setStatusPolling(int intervalMs, const QByteArray& letters);

    State state() const { return m_state; }
    char axisId() const { return m_axisId; }
    // Sum of the bytes written since resetChecksum(), mod 65536 — what <attn>h should answer.
    quint16 sentChecksum() const { return m_sentSum; }
    void resetChecksum() { m_sentSum = 0; }

    static QString errorText(int code);
    static bool isAsynchronous(int code); // E0-EF: the controller's own, whatever command was on the line

signals:
    void rawReceived(const QByteArray& bytes);
    // The same, less the answers to the session's own requests and polls: what the terminal shows.
    void shownReceived(const QByteArray& bytes);
    void stateChanged(serialport::Pmc960Session::State state);
    void finished(quint64 id, const serialport::Pmc960Response& response);
    void pollAnswered(quint64 id, char letter, const QString& value);
    void statusPolled(char letter, const QString& value); // from the status timer
    void failed(quint64 id, const QString& reason);
    // A #xx at the prompt outside any request (a typed command's refusal, or an E-code), or an asynchronous
    // E-code that arrived while one of our commands was on the line: never that command's error.
    void asyncError(int code, const QString& text);

private:
    enum class Kind { Command, Poll, Expect };
    struct Request {
        quint64 id = 0;
        Kind kind = Kind::Command;
        QByteArray bytes;
        QByteArray expect;
        int timeoutMs = 0;   // 0: derived (Pmc960Timing)
        bool status = false; // from the status timer
        bool cutIn = false;  // a poll written while a typed command runs
    };

    void onBytes(const QByteArray& bytes);
    void take(const QByteArray& bytes);
    void takeUnsolicited();
    void takePollAnswer(bool settled);
    void finishPoll(qsizetype start, qsizetype cr);
    void pollUnanswered();
    int cutInWaitMs() const;
    void onLinkOpened();
    void onTimeout();
    void askForPrompt();
    void learnAxisId(char id);
    void pump();
    void complete();
    void write(const QByteArray& bytes, bool counted);
    void setState(State state);
    bool endsInPrompt() const;
    Pmc960Response parse(const Request& request) const;
    int timeoutMsFor(const Request& request) const;

    Link& m_link;
    State m_state = State::Closed;
    std::deque<Request> m_queue;
    std::optional<Request> m_current;
    QByteArray m_buffer;
    char m_axisId = '=';
    char m_axisCandidate = '='; // a different ID seen in the last prompts, taken when three in a row show it
    int m_axisCandidateSeen = 0;
    quint16 m_sentSum = 0;
    quint64 m_nextId = 1;
    DriveTimeout m_timeout{m_link};
    QTimer m_wake;
    QTimer m_settle; // a prompt while resynchronising: ready once the line stays quiet
    QTimer m_statusTimer;
    QByteArray m_statusLetters;
    int m_statusIndex = 0;
    bool m_inEditor = false; // an Expect request left the controller in the P editor: no prompt to wait for
    QByteArray m_resync;     // resynchronise(): written before each CR that asks for a prompt
    int m_silentAsks = 0;    // prompts asked for since the controller last sent anything
    QByteArray m_heldTyped;  // sendTyped() bytes waiting for the request in flight

    qsizetype m_pollFrom = 0; // where the bytes after the poll in flight begin in m_buffer
    QTimer m_pollSettle;      // a poll's answer ends in a CR that may be a CR LF cut short: wait for the next byte
    bool m_replaying = false; // finishPoll() hands the bytes that came with an answer on: no request starts meanwhile
    // The user's line: commands typed and ended (CR, or a display character ? ! &) whose prompt has not come,
    // and a command typed in part. While either holds, our requests wait (polls: cutInWaitMs()). A prompt owed that
    // never comes (a '?' the controller took as part of something else) is forgotten after kTypedSettleMs.
    static constexpr int kTypedSettleMs = 1000;
    // A typed command that runs: a poll cuts in once the line has carried nothing for this long, so the echo of
    // the user's line and a routine's last output have arrived and its answer is not read into them.
    static constexpr int kTypedQuietMs = 100;
    bool typedLineOpen() const { return m_typedPrompts > 0 || m_typedPartial; }
    void noteTyped(const QByteArray& bytes);
    void typedLineClosed();
    int m_typedPrompts = 0;
    bool m_typedPartial = false;
    bool m_typedStream = false;     // a % display typed: any character would end it (L775)
    bool m_cutInUnanswered = false; // a poll went unanswered in this typed command: no more until its prompt
    QElapsedTimer m_lineActive;     // since the user's bytes or the controller's own last crossed the line
    QTimer m_cutIn;                 // a poll waits for the quiet of a running typed command
    QTimer m_typedSettle;
};

} // namespace serialport

Q_DECLARE_METATYPE(serialport::Pmc960Response)
