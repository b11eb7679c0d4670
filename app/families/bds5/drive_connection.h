// DriveConnection: the one live connection to a BDS5 — a Link and the Bds5DriveSession that speaks over it:
// the family-neutral DriveSession the generic tools use, with its Bds5Session inside for what only the BDS5
// has (quiet polls, RECORD/PLAY, the terminal's modes).
// Replacing the connection tears the old one down first. Re-emits what the views need as plain signals,
// so views never hold a pointer to a link or session that may be replaced. GUI thread only.
#pragma once

#include "drive/connection_choice.h"
#include "drive/link_reconnector.h"

#include "serialport/bds5_drive_session.h"
#include "serialport/link.h"

#include <QObject>

#include <memory>

namespace app {

class DriveConnection final : public QObject {
    Q_OBJECT
public:
    explicit DriveConnection(QObject* parent = nullptr);
    ~DriveConnection() override;

    // Closes any current connection, then creates and opens the link for choice. Errors arrive through
    // errorOccurred(); the connection stays (closed) so the status bar can still name it. When an open
    // link closes by itself (the cable pulled, the device gone), it is reopened every second until it
    // answers or the user disconnects; editors and queued work outside the session are untouched.
    void connectTo(const ConnectionChoice& choice);
    void disconnectDrive();

    bool isConnected() const { return m_link && m_link->isOpen(); }
    bool isReconnecting() const { return m_reconnector.isReconnecting(); }
    bool hasLink() const { return m_link != nullptr; }
    ConnectionChoice choice() const { return m_choice; }
    QString linkDescription() const;
    serialport::Bds5Session* session() const { return m_session ? &m_session->bds5() : nullptr; }
    // The same session behind the contract every family meets (serialport/drive_session.h).
    serialport::DriveSession* driveSession() const { return m_session.get(); }
    serialport::Link* link() const { return m_link.get(); }

    // Bytes typed by the user, passed to the drive untouched. Dropped (with errorOccurred) when closed.
    void sendRaw(const QByteArray& bytes);
    // ^X or Esc from the user: written at once, ahead of anything queued (Bds5Session::sendUrgent).
    void sendUrgent(const QByteArray& bytes);
    // Queues one instruction at the drive's prompt (Bds5Session::send); 0 when not connected.
    quint64 sendCommand(const QString& line);

signals:
    void linkChanged(); // a new link was made or the link went away: refresh its description
    void connectedChanged(bool connected);
    void rawReceived(const QByteArray& bytes);
    void shownReceived(const QByteArray& bytes); // for the terminal: without quiet polls (Bds5Session::Echo)
    void rawSent(const QByteArray& bytes);
    void modeChanged(serialport::Bds5Mode mode, const QString& prompt);
    void sessionStateChanged(serialport::Bds5Session::State state);
    void errorOccurred(const QString& message);

private:
    void teardown();
    bool checkConnected(); // says "not connected" once, not on every key press

    ConnectionChoice m_choice;
    // Declared link first: the session refers to the link, so it must be destroyed before it.
    std::unique_ptr<serialport::Link> m_link;
    std::unique_ptr<serialport::Bds5DriveSession> m_session;
    bool m_reportedNotConnected = false; // say "not connected" once, not on every key press
    LinkReconnector m_reconnector;       // reopens the link when it closes by itself
};

} // namespace app
