// VariableSync: keeps a VariableModel in step with the drive through the session — polls the variables
// a view shows ("P A B C", a few at a time, paced to the link's baud rate) and sends the user's edits,
// reading each back. Polls only at an interactive or monitor prompt: a running program has no prompt and
// the IDE never interrupts it. GUI thread; never blocks.
#pragma once

#include "serialport/bds5_session.h"

#include <QElapsedTimer>
#include <QHash>
#include <QObject>
#include <QPointer>
#include <QStringList>
#include <QTimer>

#include <functional>

namespace app {

class DriveConnection;
class VariableModel;

class VariableSync final : public QObject {
    Q_OBJECT
public:
    VariableSync(DriveConnection& connection, VariableModel& model, QObject* parent = nullptr);

    // Which variables to poll, asked afresh each round (the rows a view shows, the watch list).
    void setWanted(std::function<QStringList()> wanted) { m_wanted = std::move(wanted); }
    void setLive(bool live);
    bool isLive() const { return m_live; }
    // Reads names once, now (queued behind anything already in flight).
    void readNow(const QStringList& names);
    // Sends "NAME value" and reads NAME back. writeFinished() says how it went.
    void write(const QString& name, const QString& instruction);
    // Why polling waits, or empty while it runs: for the dock's status line.
    QString pauseReason() const;

    static constexpr int kBatch = 8; // variables per P: well inside the 15-entry line limit

signals:
    void writeFinished(const QString& name, bool accepted, const QString& message);
    void pauseReasonChanged(const QString& reason);

private:
    enum class Kind { Poll, Write, ReadBack };
    struct Request {
        Kind kind;
        QStringList names;
    };

    void poll();
    void follow();
    void onFinished(quint64 id, const serialport::Bds5Response& response);
    void onFailed(quint64 id, const QString& reason);
    void applyValues(const QStringList& names, const serialport::Bds5Response& response);
    quint64 send(const QString& line, Request request);
    int intervalMsFor(int names) const;

    DriveConnection& m_connection;
    VariableModel& m_model;
    QPointer<serialport::Bds5Session> m_session;
    std::function<QStringList()> m_wanted;
    QHash<quint64, Request> m_requests;
    QTimer m_timer; // ticks every kMinIntervalMs; m_notBefore paces the polls
    QElapsedTimer m_clock;
    qint64 m_notBefore = 0;
    int m_cursor = 0; // next position in the wanted list
    bool m_live = true;
    QString m_pauseReason;
};

} // namespace app
