// Pmc960WatchSource: status polls, one letter per value.
#include "pmc960_watch_source.h"

#include "pmc960_workspace.h"

#include "serialport/pmc960_session.h"

namespace app {

Pmc960WatchSource::Pmc960WatchSource(Pmc960Workspace& workspace, QObject* parent)
    : WatchSource(parent), m_workspace(workspace) {
    connect(&workspace, &Pmc960Workspace::busyChanged, this, [this](bool busy) { m_busy = busy; });
}

QList<WatchSource::Choice> Pmc960WatchSource::choices() const {
    // The name is the poll letter; V! counts in the velocity range's units (100 Hz in the 192 kHz range).
    return {{QStringLiteral("g"), tr("Position (G!)"), tr("counts")},
            {QStringLiteral("f"), tr("Following error (SF!)"), tr("counts")},
            {QStringLiteral("v"), tr("Velocity (V!)"), tr("V units")},
            {QStringLiteral("i"), tr("Distance to go (I!)"), tr("counts")}};
}

QString Pmc960WatchSource::method() const {
    return tr("Each is an out-of-band status poll (<attn> g, f, v, i), answered even while a program runs.");
}

QString Pmc960WatchSource::notReady() const {
    if (!m_workspace.session()) return tr("the controller is not connected");
    if (m_busy) return tr("the program buffer is being transferred");
    return {};
}

void Pmc960WatchSource::poll(const QStringList& names) {
    serialport::Pmc960Session* session = m_workspace.session();
    if (!session) return emit failed(tr("the controller is not connected"), false);
    if (session != m_connected) {
        m_connected = session;
        connect(session, &serialport::Pmc960Session::pollAnswered, this, &Pmc960WatchSource::onAnswered);
        connect(session, &serialport::Pmc960Session::failed, this, &Pmc960WatchSource::onFailed);
        connect(session, &QObject::destroyed, this, [this] { m_connected = nullptr; });
    }
    m_names = names;
    m_values.clear();
    pollNext();
}

void Pmc960WatchSource::pollNext() {
    serialport::Pmc960Session* session = m_workspace.session();
    if (!session) return emit failed(tr("the controller is not connected"), false);
    m_pollId = session->poll(m_names.at(m_values.size()).at(0).toLatin1());
}

void Pmc960WatchSource::onAnswered(quint64 id, char letter, const QString& value) {
    if (id != m_pollId || !m_pollId) return;
    m_pollId = 0;
    bool ok = false;
    const double v = value.trimmed().toDouble(&ok);
    if (!ok) {
        const QString label = choice(QString(QLatin1Char(letter))).value_or(Choice{}).label;
        return emit failed(tr("%1 answered \"%2\", not a decimal number (set the controller's output format "
                              "to decimal)")
                               .arg(label, value.trimmed()),
                           true);
    }
    m_values.append(v);
    if (m_values.size() < m_names.size()) return pollNext();
    emit answered(m_values);
}

void Pmc960WatchSource::onFailed(quint64 id, const QString& reason) {
    if (id != m_pollId || !m_pollId) return;
    m_pollId = 0;
    emit failed(reason, false);
}

} // namespace app
