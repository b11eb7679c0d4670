// DriveSession: the one asynchronous contract every drive family's session meets (issue 17), so a tool
// written once (servodesk-cli today; the IDE's generic tools and the machine's axes next) works for the
// BDS5, the SC750 and the PMC-960 alike. Each family implements it over its own session and transfers
// (bds5_drive_session.h, sc750_drive_session.h, pmc960_drive_session.h); makeDriveSession() picks one.
// GUI thread; never blocks and never spins a nested event loop. The session keeps a reference to its link:
// whoever owns both destroys the session first.
#pragma once

#include "drive_core/drive.h"

#include <QList>
#include <QMetaType>
#include <QObject>
#include <QString>
#include <QStringList>

#include <memory>

namespace serialport {

class Link;

// The drive's answer to one command line.
struct LineAnswer {
    QString command;
    QStringList lines; // what the drive printed, without line ends or the prompt
    int errorCode = 0; // the drive's own code (BDS5 ERR nn, SC750 !nn, PMC-960 #xx), 0 if accepted
    QString error;     // the drive's own words for it ("ERR 92 ZERO DIVIDE", "#B6 ..."), "" if accepted
    bool garbled = false; // the answer came back damaged on the wire (BDS5: no echo): its words may be wrong
    bool ok() const { return error.isEmpty(); }
};

// A drive error tied to a line of the user's program.
struct TransferLineError {
    int sourceLine = 0; // 1-based line of the text sent; 0 when it belongs to no line
    int code = 0;
    QString text; // the drive's words, with its code ("ERR 83 BAD OR OUT OF RANGE")
};

// What a download or an upload did, the same for every family.
struct TransferResult {
    enum class Status { Done, Cancelled, Failed };
    Status status = Status::Failed;
    QString message;    // one line for a status bar or a terminal: what happened, and why when it failed
    QString driveHolds; // what the drive holds now ("the new program", "its old program", "the first 4 of
                        // 9 lines"): said, never left unknown, so a machine's restore can report each axis
    QString verified;   // how a download was checked ("P CHECKSUM 1A2B", "CRC-32 ..."), "" if not
    QList<TransferLineError> errors;
    QStringList lines; // upload: the program as the drive holds it
    bool ok() const { return status == Status::Done; }
};

class DriveSession : public QObject {
    Q_OBJECT
public:
    using QObject::QObject;

    virtual drive_core::DriveFamily family() const = 0;
    // The drive has answered since the link opened (its prompt, or its identification) and nothing of
    // ours is in flight.
    virtual bool isReady() const = 0;
    // One command line as a user of that drive types it: a BDS5 or PMC-960 command, or on the SC750
    // (which has no command line) "NAME" to read a variable, "NAME=VALUE" to write one, or a real-time
    // function ("GO.VEL"). answered() or lost() follows with the id returned.
    virtual quint64 sendLine(const QString& line) = 0;
    // The same, for a poll the user did not type (a watch, a browser's read): kept out of the terminal where
    // the family echoes what is sent there (the BDS5's quiet P); elsewhere the same as sendLine.
    virtual quint64 sendQuiet(const QString& line) { return sendLine(line); }
    // The program text, verified on the drive; transferFinished() follows once. SC750: compiled to its
    // .BIN first (a compile error fails the download with its line), and the source stored beside it.
    virtual void download(const QString& programText) = 0;
    // The program the drive holds, as text (SC750: the stored source); transferFinished() with lines.
    virtual void upload() = 0;
    // Ends a download or upload as soon as the drive allows; transferFinished() says what it holds.
    virtual void cancelTransfer() = 0;
    // Starts the drive's program: BDS5 RUN [label], SC750 R (from the top; no label), PMC-960 B<label>.
    // Its output arrives through programOutput(), its end through programEnded().
    virtual void run(const QString& label) = 0;
    // Urgent, ahead of anything queued (BDS5 ^X, SC750 Ctrl C, PMC-960 ESC): stops the program and motion.
    virtual void stop() = 0;

signals:
    void readyChanged(bool ready);
    void answered(quint64 id, const serialport::LineAnswer& answer);
    void lost(quint64 id, const QString& reason); // no answer in time, or the link closed
    void programStarted(); // the drive took the run command
    void programOutput(const QString& text);
    // The program ended (error false) or stopped with a drive error (error true, message the drive's words).
    void programEnded(bool error, const QString& message);
    void transferProgress(qint64 done, qint64 total); // total 0 when not known in advance (an upload)
    void transferFinished(const serialport::TransferResult& result);
    void linkFailed(const QString& reason);
};

std::unique_ptr<DriveSession> makeDriveSession(drive_core::DriveFamily family, Link& link);

} // namespace serialport

Q_DECLARE_METATYPE(serialport::LineAnswer)
Q_DECLARE_METATYPE(serialport::TransferResult)
