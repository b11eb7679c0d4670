// Bds5Transfer: the common face of the BDS5 transfers (program download, upload, verify; variables from and
// to the drive) — an asynchronous operation on a Bds5Session with progress, cancel, and a typed result whose
// summary says what state the drive is left in. GUI thread; never blocks.
#pragma once

#include "bds5_protocol.h"
#include "bds5_session.h"

#include <QList>
#include <QObject>
#include <QPointer>
#include <QStringList>

#include <optional>

namespace serialport {

// One drive error tied to a line of the user's text (program or .VAR file).
struct Bds5LineError {
    int sourceLine = 0; // 1-based line of the editor text; 0 when the error belongs to no line
    int driveLine = 0;  // the drive's program line (downloads), 0 otherwise
    QString sent;       // the line as sent
    Bds5ErrorLine error;
};

struct Bds5TransferResult {
    enum class Status {
        Ok,        // done (variables: every line was sent; errors lists the ones the drive refused)
        Refused,   // the drive refused before changing anything (ERR 110, ERR 51, not at the --> prompt)
        Failed,    // stopped part-way or lost the drive; summary says what the drive holds now
        Mismatch,  // verify: the drive's program differs from what was sent
        Cancelled, // the user cancelled; summary says what the drive holds now
    };
    Status status = Status::Ok;
    QString summary; // for the status bar and terminal: what happened and the state the drive is left in
    QList<Bds5LineError> errors;
    // Verify: the first line that differs (0 when the drive holds fewer/more lines than were sent).
    int mismatchSourceLine = 0;
    int mismatchDriveLine = 0;
    QString expected;                // what was sent at that line ("" if the drive holds extra lines)
    QString actual;                  // what the drive holds there ("" if it holds fewer lines)
    std::optional<quint32> checksum; // P CHECKSUM after a verified download
    QStringList lines;               // upload: the drive's program; variables from drive: the .VAR lines
    int linesDone = 0;               // lines the drive acknowledged

    bool ok() const { return status == Status::Ok; }
};

class Bds5Transfer : public QObject {
    Q_OBJECT
public:
    explicit Bds5Transfer(Bds5Session& session, QObject* parent = nullptr);
    ~Bds5Transfer() override;

    // Begins; returns at once. finished() follows exactly once, never from inside start().
    void start();
    // Stops as soon as the drive allows; finished() then reports Cancelled and what the drive holds.
    virtual void cancel();
    bool isRunning() const { return m_running; }
    bool isCancelling() const { return m_cancelled; }

signals:
    void stageChanged(const QString& stage); // "Sending program", "Verifying", ...
    void progress(int done, int total);      // lines; total 0 when not known in advance (an upload)
    void finished(const serialport::Bds5TransferResult& result);

protected:
    // Subclasses: the first step (called from the event loop), each answer, and a lost command.
    virtual void begin() = 0;
    virtual void answered(const Bds5Response& response) = 0;
    virtual void lost(const QString& reason) = 0;

    // One command at a time: the answer comes to answered(), a time-out or closed link to lost().
    void send(const QString& line);
    void sendEscape();
    // Counts the CR LFs of the answer in flight into progress(base + lines, total), for long listings.
    void countLinesInto(int base, int total);
    void finish(Bds5TransferResult result);
    Bds5Session* session() const { return m_session; }
    bool sessionAtInteractivePrompt() const;

private:
    void onFinished(quint64 id, const serialport::Bds5Response& response);
    void onFailed(quint64 id, const QString& reason);
    void onRaw(const QByteArray& bytes);

    QPointer<Bds5Session> m_session;
    std::optional<quint64> m_pending;
    bool m_running = false;
    bool m_cancelled = false;
    bool m_counting = false;
    int m_countBase = 0;
    int m_countTotal = 0;
    int m_counted = 0;
};

// "line 12" / "lines 1-3" text helpers for summaries.
QString describeError(const Bds5ErrorLine& error);

} // namespace serialport

Q_DECLARE_METATYPE(serialport::Bds5TransferResult)
