// DriveConnection: owns and wires the link and the session.
#include "drive_connection.h"

#include <utility>

namespace app {

DriveConnection::DriveConnection(QObject* parent) : QObject(parent) {
    connect(&m_reconnector, &LinkReconnector::lost, this, [this](const QString& description) {
        emit errorOccurred(tr("The connection to the drive was lost (%1). Reconnecting every second; nothing "
                              "in the editors is affected. Drive > Disconnect stops trying.")
                               .arg(description));
    });
}

DriveConnection::~DriveConnection() {
    blockSignals(true); // whoever listens may be half destroyed already
    teardown();
}

void DriveConnection::connectTo(const ConnectionChoice& choice) {
    teardown();
    m_choice = choice;
    m_reportedNotConnected = false;
    m_link = choice.makeLink();
    m_session = std::make_unique<serialport::Bds5DriveSession>(*m_link);
    serialport::Bds5Session* session = &m_session->bds5();
    serialport::Link* link = m_link.get();
    // Said closed before the reconnector says lost; the reconnector stops before opened is said.
    connect(link, &serialport::Link::closed, this, [this] { emit connectedChanged(false); });
    m_reconnector.watch(link);
    connect(link, &serialport::Link::opened, this, [this] { emit connectedChanged(true); });
    connect(link, &serialport::Link::errorOccurred, this, [this](const QString& message) {
        if (!isReconnecting()) emit errorOccurred(message); // not once a second while it is away
    });
    connect(session, &serialport::Bds5Session::rawReceived, this, &DriveConnection::rawReceived);
    connect(session, &serialport::Bds5Session::shownReceived, this, &DriveConnection::shownReceived);
    connect(session, &serialport::Bds5Session::rawSent, this, &DriveConnection::rawSent);
    connect(session, &serialport::Bds5Session::modeChanged, this, &DriveConnection::modeChanged);
    connect(session, &serialport::Bds5Session::stateChanged, this, &DriveConnection::sessionStateChanged);
    emit linkChanged();
    link->open();
}

void DriveConnection::disconnectDrive() {
    m_reconnector.close();
}

QString DriveConnection::linkDescription() const {
    return m_link ? m_link->description() : QString();
}

void DriveConnection::sendRaw(const QByteArray& bytes) {
    if (!checkConnected()) return;
    m_session->bds5().sendRaw(bytes);
}

void DriveConnection::sendUrgent(const QByteArray& bytes) {
    if (!checkConnected()) return;
    m_session->bds5().sendUrgent(bytes);
}

quint64 DriveConnection::sendCommand(const QString& line) {
    if (!checkConnected()) return 0;
    return m_session->bds5().send(line);
}

bool DriveConnection::checkConnected() {
    if (isConnected()) return true;
    if (!std::exchange(m_reportedNotConnected, true))
        emit errorOccurred(tr("Not connected to a drive: nothing was sent. Use Drive > Connect."));
    return false;
}

void DriveConnection::teardown() {
    if (!m_link) return;
    m_reconnector.close(); // emits closed() while the session still listens, so pending commands fail cleanly
    m_reconnector.watch(nullptr);
    m_session.reset();
    m_link->disconnect(this);
    m_link.reset();
    emit linkChanged();
}

} // namespace app
