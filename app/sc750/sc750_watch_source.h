// Sc750WatchSource: the SC750's values for the polled chart — the predefined numeric variables of the
// catalog (POSITION, VELOCITY, POS.ERROR, ICMD, ...), each read with its own G frame in turn (PROTOCOL.md:
// G is answered while a program runs, so a running move can be watched). Waits while a program is being
// downloaded. GUI thread only.
#pragma once

#include "scope/watch_source.h"

namespace app {

class Sc750Workspace;

class Sc750WatchSource final : public WatchSource {
    Q_OBJECT
public:
    explicit Sc750WatchSource(Sc750Workspace& workspace, QObject* parent = nullptr);

    QString familyName() const override { return QStringLiteral("SC750"); }
    QList<Choice> choices() const override;
    QString method() const override;
    QString notReady() const override;
    void poll(const QStringList& names) override;
    void cancel() override { ++m_generation; }

private:
    void readNext(quint64 generation);

    Sc750Workspace& m_workspace;
    QStringList m_names;
    QList<double> m_values; // read so far in this poll
    quint64 m_generation = 0;
};

} // namespace app
