// Pmc960WatchSource: the PMC-960's values for the polled chart — position (G!), following error (SF!),
// velocity (V!) and distance to go (I!), read with the controller's out-of-band status polls (<attn> g f
// v i, digest §4.7), which it answers at any time, a program running or not. One poll per value, in turn.
// Waits while the program buffer is being transferred. Decimal output is assumed (the power-up format): a
// hex or binary answer stops the chart with a message. GUI thread only.
#pragma once

#include "scope/watch_source.h"

namespace serialport {
class Pmc960Session;
}

namespace app {

class Pmc960Workspace;

class Pmc960WatchSource final : public WatchSource {
    Q_OBJECT
public:
    explicit Pmc960WatchSource(Pmc960Workspace& workspace, QObject* parent = nullptr);

    QString familyName() const override { return QStringLiteral("PMC-960"); }
    QList<Choice> choices() const override;
    QString method() const override;
    QString notReady() const override;
    void poll(const QStringList& names) override;
    void cancel() override { m_pollId = 0; }
    // The status panel's own polls go out only while the line is idle: leave it idle half the time.
    int minimumIntervalMs() const override { return 25; }

private:
    void pollNext();
    void onAnswered(quint64 id, char letter, const QString& value);
    void onFailed(quint64 id, const QString& reason);

    Pmc960Workspace& m_workspace;
    serialport::Pmc960Session* m_connected = nullptr; // the session whose signals reach us
    QStringList m_names;
    QList<double> m_values;
    quint64 m_pollId = 0;
    bool m_busy = false; // a transfer of the program buffer runs
};

} // namespace app
