// SessionWorkspace: one link lifecycle for every family's workspace.
#include "session_workspace.h"

#include "connection_choice.h"
#include "main_window.h"
#include "scope/session_watch_source.h"
#include "scope/watch_view.h"
#include "tuning/family_tuning_dock.h"
#include "tuning/tuning_panel.h"

#include "serialport/drive_session.h"
#include "serialport/link.h"

namespace app {

SessionWorkspace::SessionWorkspace(MainWindow& window, drive_core::DriveFamily family)
    : FamilyWorkspace(&window), m_window(window), m_family(family), m_tuning(makeFamilyTuningDock(window, family)) {
    connect(&m_reconnector, &LinkReconnector::lost, this, [this](const QString& description) {
        emit message(tr("The connection to the %1 was lost (%2). Reconnecting every second; nothing in the "
                        "editors is affected. Drive > Disconnect stops trying.")
                         .arg(ConnectionChoice::familyName(m_family), description));
        emit statusChanged();
    });
}

SessionWorkspace::~SessionWorkspace() {
    releaseLink();
}

void SessionWorkspace::releaseLink() {
    m_reconnector.watch(nullptr); // a link closed on purpose is not lost
    if (m_link) m_link->disconnect(this);
    if (m_drive) m_drive->disconnect(this);
    m_drive.reset();
    m_link.reset();
}

WatchView* SessionWorkspace::watchVariables() {
    if (!m_watch) m_watch = new WatchView(new SessionWatchSource(SessionHost::of(*this)), &m_window);
    m_watch->show();
    m_watch->raise();
    return m_watch;
}

void SessionWorkspace::attachTuning(bool on) {
    if (m_tuning.panel) app::attachTuning(*m_tuning.panel, on ? m_drive.get() : nullptr, on ? m_link.get() : nullptr);
}

void SessionWorkspace::activate(const ConnectionChoice& choice) {
    deactivate();
    m_link = choice.makeLink();
    m_linkText = m_link->description();
    m_lineAxis = choice.axis;
    m_drive = serialport::makeDriveSession(m_family, *m_link);
    connect(m_link.get(), &serialport::Link::opened, this, &SessionWorkspace::onOpened);
    connect(m_link.get(), &serialport::Link::errorOccurred, this, &SessionWorkspace::onLinkError);
    connect(m_link.get(), &serialport::Link::closed, this, &SessionWorkspace::onClosed);
    m_reconnector.watch(m_link.get()); // after the handlers above: lost is said once the state shows it
    sessionCreated(*m_drive);
    m_link->open();
    if (m_link->isOpen() && !m_connected) onOpened();
    emit statusChanged();
}

void SessionWorkspace::onOpened() {
    if (m_connected) return;
    m_connected = true;
    attachTuning(true);
    sessionOpened();
    updateActions();
    emit statusChanged();
    emit message(tr("Connected to %1").arg(m_link->description()));
}

void SessionWorkspace::onClosed() {
    if (m_connected) {
        m_connected = false;
        attachTuning(false);
        sessionClosed();
        updateActions();
    }
    emit statusChanged();
}

void SessionWorkspace::onLinkError(const QString& text) {
    emit message(tr("%1 link: %2").arg(ConnectionChoice::familyName(m_family), text));
    if (m_link && !m_link->isOpen()) return onClosed();
    emit statusChanged();
}

void SessionWorkspace::deactivate() {
    m_reconnector.watch(nullptr); // closed on purpose: not lost
    if (!m_link) return;
    const bool wasConnected = m_connected;
    m_connected = false;
    attachTuning(false);
    sessionEnding();
    m_link->disconnect(this);
    m_link->close();
    releaseLink();
    updateActions();
    emit statusChanged();
    if (wasConnected) emit message(tr("Disconnected from the %1").arg(ConnectionChoice::familyName(m_family)));
}

} // namespace app
