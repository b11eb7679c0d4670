// SessionWatchSource: the polled chart's values from any family's DriveSession, through the one
// serialport::WatchPoller the CLI's watch uses too — the names and units are the family's watch choices
// (watch_choices.h), one sample is one poll in the family's way (BDS5 one quiet P for all the names, SC750 a
// G frame per variable, PMC-960 its out-of-band status polls). Its host (a family's workspace, or the main
// window for the BDS5) gives the session of the moment and says when the link may take no poll (a transfer
// under way, a BDS5 program running). GUI thread only.
#pragma once

#include "session_host.h"
#include "watch_source.h"

#include <QPointer>

namespace serialport {
class DriveSession;
class WatchPoller;
} // namespace serialport

namespace app {

class SessionWatchSource final : public WatchSource {
    Q_OBJECT
public:
    explicit SessionWatchSource(SessionHost host, QObject* parent = nullptr);
    ~SessionWatchSource() override;

    QString familyName() const override;
    QList<Choice> choices() const override;
    QString method() const override;
    QString notReady() const override;
    void poll(const QStringList& names) override;
    void cancel() override;
    int minimumIntervalMs() const override;

private:
    serialport::WatchPoller* poller();

    SessionHost m_host;
    QPointer<serialport::DriveSession> m_session; // the session m_poller reads through
    serialport::WatchPoller* m_poller = nullptr;  // rebuilt when the workspace connects anew
};

} // namespace app
