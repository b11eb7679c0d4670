// Pmc960Download: Program > Download to the PMC-960's program buffer, verified by the communications
// checksum: <attn>h (reset), SW1, P{} (erase), P<cr> (append), the text line by line (spaces dropped, CR
// endings, each line's echo awaited), ESC, SW0, <attn>h — whose answer must equal the sum of every byte
// written since the first poll (digest §4.8, §4.12). Progress per line; cancel (the user's Stop) writes ESC
// at once, ahead of anything queued, leaves the editor and write-protects the buffer again.
// Over a damaged wire: a line whose echo differs, a command answered with an error or not at all, or a
// checksum that differs ends the attempt; the session gets back to the prompt (ESC out of the editor) and
// the whole download starts again, erasing first, up to kMaxAttempts times. A failure says what the buffer
// holds (a partial program) and leaves the controller at its prompt, write-protected when it can.
#pragma once

#include "pmc960_session.h"

#include <QObject>
#include <QStringList>
#include <QTimer>

namespace serialport {

struct Pmc960DownloadResult {
    bool ok = false;
    bool cancelled = false;
    int error = 0;             // a #xx the controller reported, 0 if none
    QString reason;            // why it failed
    quint16 hostChecksum = 0;  // what was written
    quint16 driveChecksum = 0; // what <attn>h answered
};

class Pmc960Download final : public QObject {
    Q_OBJECT
public:
    Pmc960Download(Pmc960Session& session, const QString& programText, QObject* parent = nullptr);

    void start();
    // ESC + CR go out now (Pmc960Session::resynchronise), SW0 follows at the prompt; done() then reports
    // the download cancelled.
    void cancel();
    static constexpr int kMaxAttempts = 8; // whole attempts before giving up (a clean wire needs one)
    // The lines sent, as the controller stores them (no spaces, no empty lines).
    const QStringList& lines() const { return m_lines; }
    static QStringList programLines(const QString& text);

signals:
    void progress(int linesSent, int linesTotal);
    void done(const serialport::Pmc960DownloadResult& result);

private:
    enum class Step { ResetChecksum, Enable, Erase, Enter, Lines, Leave, Protect, Verify, Cancelling, Done };

    void onFinished(quint64 id, const Pmc960Response& response);
    void onPoll(quint64 id, char letter, const QString& value);
    void onFailed(quint64 id, const QString& reason);
    void next();
    void finish(bool ok, const QString& reason, int error = 0);
    void attemptFailed(const QString& reason, int error = 0);
    void beginAttempt();

    Pmc960Session& m_session;
    QStringList m_lines;
    Step m_step = Step::ResetChecksum;
    int m_line = 0;
    int m_attempt = 0;
    QTimer m_noPrompt; // getting back to the prompt between attempts takes too long: give up
    quint64 m_waiting = 0;
    bool m_cancelled = false;
    Pmc960DownloadResult m_result;
    QString m_cancelReason;
};

} // namespace serialport

Q_DECLARE_METATYPE(serialport::Pmc960DownloadResult)
