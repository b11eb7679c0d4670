// SessionWorkspace: what every family's workspace does alike — the link and the DriveSession on it from
// Drive > Connect to Disconnect, reopening the link every second when it is lost (LinkReconnector), the
// family's Tuning dock attached to the session while connected, and Watch Variables over the session
// (SessionWatchSource). A family's workspace derives from it, makes its menus and docks, and follows the
// session through the hooks below. GUI thread only.
//
//   class Sc750Workspace final : public SessionWorkspace { ... sessionCreated(), sessionOpened() ... };
#pragma once

#include "family_workspace.h"
#include "link_reconnector.h"
#include "tuning/family_tuning_dock.h"

#include <QPointer>

#include <memory>

namespace app {

class MainWindow;
class WatchView;

class SessionWorkspace : public FamilyWorkspace {
    Q_OBJECT
public:
    SessionWorkspace(MainWindow& window, drive_core::DriveFamily family);
    ~SessionWorkspace() override;

    drive_core::DriveFamily family() const final { return m_family; }
    void activate(const ConnectionChoice& choice) final;
    void deactivate() final;
    bool isConnected() const final { return m_connected; }
    serialport::DriveSession* driveSession() const final { return m_connected ? m_drive.get() : nullptr; }
    serialport::Link* link() const final { return m_connected ? m_link.get() : nullptr; }
    // Connect made a link (open, opening or being reopened); false after Disconnect.
    bool hasLink() const { return m_link != nullptr; }
    // The link closed by itself and is reopened every second (LinkReconnector) until the device is back.
    bool isReconnecting() const { return m_reconnector.isReconnecting(); }
    MainWindow& window() const { return m_window; }
    // Watch Variables: the scope's polled rolling chart of this family's values (one window, reused).
    WatchView* watchVariables();

protected:
    // The session exists and the link is about to open: connect to the family's own session here.
    virtual void sessionCreated(serialport::DriveSession& session) = 0;
    // The link opened (also after it was lost); isConnected() is true.
    virtual void sessionOpened() {}
    // The link closed or failed while connected; the session is still there and opens again with the link.
    virtual void sessionClosed() {}
    // Drive > Disconnect or another connection: the session and the link go right after this.
    virtual void sessionEnding() {}
    virtual void updateActions() {}

    const FamilyTuningDock& tuning() const { return m_tuning; }
    // What the status bar calls the connection: the link's description until the family names the drive.
    const QString& linkText() const { return m_linkText; }
    // The axis's ID when the link is one axis of a multidrop line (Machine > Use Axis); "" otherwise.
    const QString& lineAxis() const { return m_lineAxis; }
    void setLinkText(const QString& text) { m_linkText = text; }
    // For the derived destructor, first: the link and the session go and nothing from them reaches it.
    void releaseLink();

private:
    void onOpened();
    void onClosed();
    void onLinkError(const QString& text);
    void attachTuning(bool on);

    MainWindow& m_window;
    const drive_core::DriveFamily m_family;
    std::unique_ptr<serialport::Link> m_link;
    std::unique_ptr<serialport::DriveSession> m_drive; // keeps a reference to m_link: goes first
    FamilyTuningDock m_tuning;
    QPointer<WatchView> m_watch;
    QString m_linkText;
    QString m_lineAxis;
    bool m_connected = false;
    LinkReconnector m_reconnector;
};

} // namespace app
