// Bds5WatchSource: the BDS5's values for the polled chart — "P VAR1 VAR2" through the session, quietly (no
// echo in the terminal), only at an interactive prompt: never while a program runs, a transfer (RECORD/PLAY,
// download) is under way, or the link is down. Any variable P prints can be watched, including those
// RECORD cannot take. GUI thread only.
#pragma once

#include "scope/watch_source.h"

namespace serialport {
struct Bds5Response;
}

namespace app {

class DriveConnection;

class Bds5WatchSource final : public WatchSource {
    Q_OBJECT
public:
    explicit Bds5WatchSource(DriveConnection& connection, QObject* parent = nullptr);

    QString familyName() const override { return QStringLiteral("BDS5"); }
    QList<Choice> choices() const override;
    QString method() const override;
    QString notReady() const override;
    void poll(const QStringList& names) override;
    void cancel() override { m_pollId = 0; }

private:
    void onAnswer(quint64 id, const serialport::Bds5Response& response);
    void onFailed(quint64 id, const QString& reason);

    DriveConnection& m_connection;
    quint64 m_pollId = 0;
    int m_expected = 0; // values the poll in flight asked for
};

} // namespace app
