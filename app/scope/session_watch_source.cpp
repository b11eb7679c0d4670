// SessionWatchSource: a WatchPoller over the workspace's session of the moment.
#include "session_watch_source.h"

#include "connection_choice.h"

#include "serialport/watch_choices.h"
#include "serialport/watch_poller.h"

namespace app {

SessionWatchSource::SessionWatchSource(SessionHost host, QObject* parent)
    : WatchSource(parent), m_host(std::move(host)) {}

SessionWatchSource::~SessionWatchSource() {
    delete m_poller;
}

QString SessionWatchSource::familyName() const {
    return ConnectionChoice::familyName(m_host.family);
}

QList<WatchSource::Choice> SessionWatchSource::choices() const {
    QList<Choice> list;
    for (const serialport::WatchChoice& c : serialport::watchChoices(m_host.family))
        list.append({c.name, c.label, c.unit});
    return list;
}

QString SessionWatchSource::method() const {
    return serialport::watchMethod(m_host.family);
}

QString SessionWatchSource::notReady() const {
    if (!m_host.session()) return m_host.notConnected;
    return m_host.busyReason();
}

serialport::WatchPoller* SessionWatchSource::poller() {
    serialport::DriveSession* session = m_host.session();
    if (session != m_session || !m_poller) {
        delete m_poller; // its session is gone (a reconnection) or another one took its place
        m_poller = nullptr;
        m_session = session;
        if (!session) return nullptr;
        m_poller = new serialport::WatchPoller(*session);
        connect(m_poller, &serialport::WatchPoller::answered, this, &WatchSource::answered);
        connect(m_poller, &serialport::WatchPoller::failed, this, &WatchSource::failed);
    }
    return m_poller;
}

void SessionWatchSource::poll(const QStringList& names) {
    serialport::WatchPoller* p = poller();
    if (!p) return emit failed(m_host.notConnected, false);
    p->poll(names);
}

void SessionWatchSource::cancel() {
    if (m_poller && m_session) m_poller->cancel();
}

int SessionWatchSource::minimumIntervalMs() const {
    return serialport::WatchPoller::minimumIntervalMs(m_host.family);
}

} // namespace app
