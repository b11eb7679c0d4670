// LinkReconnector: reopen a lost link every second (see link_reconnector.h).
#include "link_reconnector.h"

namespace app {

LinkReconnector::LinkReconnector(QObject* parent) : QObject(parent) {
    m_timer.setInterval(kIntervalMs);
    connect(&m_timer, &QTimer::timeout, this, &LinkReconnector::retry);
}

void LinkReconnector::watch(serialport::Link* link) {
    m_timer.stop();
    if (m_link) m_link->disconnect(this);
    m_link = link;
    if (!link) return;
    connect(link, &serialport::Link::opened, this, [this] {
        if (!m_timer.isActive()) return;
        m_timer.stop();
        emit reconnected();
    });
    connect(link, &serialport::Link::closed, this, &LinkReconnector::onClosed);
}

void LinkReconnector::close() {
    m_timer.stop();
    if (!m_link) return;
    m_closing = true;
    m_link->close();
    m_closing = false;
}

void LinkReconnector::onClosed() {
    if (m_closing || m_timer.isActive()) return;
    m_timer.start();
    emit lost(m_link ? m_link->description() : QString());
}

void LinkReconnector::retry() {
    if (!m_link || m_link->isOpen()) return m_timer.stop();
    m_link->open(); // opened() stops the timer; a failure stays quiet and is tried again
}

} // namespace app
