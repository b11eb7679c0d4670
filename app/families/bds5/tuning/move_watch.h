// MoveWatch: stops a recording whose test move went wrong. Bds5RecordPlay sends the plan's commands and
// reads back whatever the drive recorded, so a J refused with ERR 50 (drive disabled) or a jog cut short by
// ERR 23 (software overtravel) would be read for seconds and shown as if the move had run. The watch reads
// the session while the recording runs — the answers to the plan's commands, and the errors the drive
// reports by itself — and on the first refusal or fault aborts the recording, saying which command and
// error, and what to do (the catalog's remedy). Scope > From Drive and every tuning run use one.
// GUI thread; a child of the recording it watches.
#pragma once

#include "serialport/bds5_record_play.h"

#include <QByteArray>
#include <QObject>
#include <QPointer>
#include <QStringList>

namespace app {

class MoveWatch final : public QObject {
    Q_OBJECT
public:
    MoveWatch(serialport::Bds5Session& session, serialport::Bds5RecordPlay& record);

    // Why the recording was stopped ("the drive refused J 1000: ERR 50 DRIVE INHIBITED — Enable the drive
    // with EN."), "" while nothing went wrong.
    QString reason() const { return m_reason; }
    // "Record stopped: <reason> Nothing was read back or shown.", "" while nothing went wrong.
    QString summary() const;

private:
    void onAnswer(quint64 id, const serialport::Bds5Response& response);
    void onBytes(const QByteArray& bytes);
    void onLine(const QByteArray& line);

    QPointer<serialport::Bds5Session> m_session;
    serialport::Bds5RecordPlay& m_record;
    QString m_recordLine;
    QStringList m_commands;
    bool m_recording = false; // RECORD accepted: from now on the drive's errors belong to the move
    bool m_held = false;      // the drive is printing errors it held back (ERROR MSG WAITING--COMMAND IGNORED)
    QString m_moving;         // the last of the plan's commands the drive accepted
    QByteArray m_line;        // the received line in progress
    QString m_reason;
};

} // namespace app
