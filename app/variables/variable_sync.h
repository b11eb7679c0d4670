// VariableSync: keeps a VariableModel in step with the drive through its family's DriveSession — polls the
// variables a view shows (a few at a time where the family reads several in one line), paced so the link
// stays at least half free for the user, and sends the user's edits, reading each back. Polls only when its
// host says the link may take one (a BDS5 at an interactive or monitor prompt; no transfer under way); the
// polls stay out of the terminal (DriveSession::sendQuiet), the user's edits show there. GUI thread.
#pragma once

#include "session_host.h"

#include "serialport/drive_session.h"

#include <QElapsedTimer>
#include <QHash>
#include <QObject>
#include <QPointer>
#include <QSet>
#include <QStringList>
#include <QTimer>

#include <functional>

namespace app {

class VariableModel;

class VariableSync final : public QObject {
    Q_OBJECT
public:
    VariableSync(SessionHost host, VariableModel& model, QObject* parent = nullptr);

    // Which variables to poll, asked afresh each round (the rows a view shows, the watch list).
    void setWanted(std::function<QStringList()> wanted) { m_wanted = std::move(wanted); }
    void setLive(bool live);
    bool isLive() const { return m_live; }
    // Reads names once, now (queued behind anything already in flight).
    void readNow(const QStringList& names);
    // Sends the edit's lines and reads the name back. writeFinished() says how it went.
    void write(const QString& name, const QStringList& lines);
    // Why polling waits, or empty while it runs: for the browser's status line.
    QString pauseReason() const { return m_pauseReason; }
    // Reads and writes sent and not yet answered (0 once a Refresh has finished).
    int pending() const { return int(m_requests.size()); }

signals:
    void writeFinished(const QString& name, bool accepted, const QString& message);
    void pauseReasonChanged(const QString& reason);
    void valueRead(const QString& name, const QString& value);
    void idle(); // the last request in flight was answered

private:
    enum class Kind { Poll, Write, ReadBack, Second };
    struct Request {
        Kind kind;
        QStringList names;
        bool last = true; // Write: the edit's last line
        QString edit;     // Write: the edit's lines, as the message names them
        qint64 sentAt = 0;
    };

    void poll();
    void follow();
    void read(const QStringList& names, Kind kind);
    void onAnswered(quint64 id, const serialport::LineAnswer& answer);
    void onLost(quint64 id, const QString& reason);
    void applyValues(const QStringList& names, const serialport::LineAnswer& answer);
    quint64 send(const QString& line, Request request);

    SessionHost m_host;
    VariableModel& m_model;
    QPointer<serialport::DriveSession> m_session;
    std::function<QStringList()> m_wanted;
    QHash<quint64, Request> m_requests;
    QSet<QString> m_refused; // edits whose earlier line the drive refused: their last line says nothing more
    QTimer m_timer;          // ticks often; m_notBefore paces the polls
    QElapsedTimer m_clock;
    qint64 m_notBefore = 0;
    int m_cursor = 0; // next position in the wanted list
    bool m_live = true;
    QString m_pauseReason;
};

} // namespace app
