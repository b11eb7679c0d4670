// LinkReconnector: when a link closes by itself (the cable pulled, the pty's simulator killed, the USB
// adapter unplugged) it is reopened every second until it answers or the user disconnects. One mechanism
// for every family: DriveConnection (BDS5), Sc750Workspace and Pmc960Workspace. The session on the link
// stays; editors and everything outside the link are untouched. GUI thread only.
#pragma once

#include "serialport/link.h"

#include <QObject>
#include <QPointer>
#include <QTimer>

namespace app {

class LinkReconnector final : public QObject {
    Q_OBJECT
public:
    static constexpr int kIntervalMs = 1000;

    explicit LinkReconnector(QObject* parent = nullptr);

    // Watches link (nullptr: none). Closing it through close() below is deliberate and not retried.
    void watch(serialport::Link* link);
    // The user (or a new connection) closes the link: no reconnect.
    void close();
    void stop() { m_timer.stop(); }
    bool isReconnecting() const { return m_timer.isActive(); }

signals:
    // The link closed by itself; reconnecting has begun. description: the link's, for the message.
    void lost(const QString& description);
    // The link opened again after being lost.
    void reconnected();

private:
    void onClosed();
    void retry();

    QPointer<serialport::Link> m_link;
    QTimer m_timer;
    bool m_closing = false;
};

} // namespace app
