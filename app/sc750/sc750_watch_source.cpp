// Sc750WatchSource: a G frame per variable.
#include "sc750_watch_source.h"

#include "sc750_debugger.h"
#include "sc750_workspace.h"

#include "drive_core/catalog/sc750_catalog.h"
#include "serialport/sc750_session.h"

namespace app {

namespace {
QString text(std::string_view s) {
    return QString::fromUtf8(s.data(), qsizetype(s.size()));
}
} // namespace

Sc750WatchSource::Sc750WatchSource(Sc750Workspace& workspace, QObject* parent)
    : WatchSource(parent), m_workspace(workspace) {}

QList<WatchSource::Choice> Sc750WatchSource::choices() const {
    namespace catalog = drive_core::catalog::sc750;
    // The values that move are the interesting ones: read-only state first (POSITION, VELOCITY, POS.ERROR,
    // ICMD...), then the settable variables and the parameters, each group in the catalog's order.
    QList<Choice> state, settable;
    for (const catalog::VariableInfo& v : catalog::variables()) {
        if (v.type == catalog::ValueType::String) continue;
        (v.access == catalog::Access::ReadOnly ? state : settable).append({text(v.name), text(v.name), text(v.units)});
    }
    return state + settable;
}

QString Sc750WatchSource::method() const {
    return tr("Each is read with a G frame in turn, as fast as the controller answers; a running program "
              "keeps running.");
}

QString Sc750WatchSource::notReady() const {
    if (!m_workspace.session()) return tr("the controller is not connected");
    if (m_workspace.debugger().state() == Sc750Debugger::State::Downloading) return tr("a download is under way");
    return {};
}

void Sc750WatchSource::poll(const QStringList& names) {
    m_names = names;
    m_values.clear();
    readNext(++m_generation);
}

void Sc750WatchSource::readNext(quint64 generation) {
    const QString name = m_names.at(m_values.size());
    m_workspace.send(
        'G', name,
        [this, generation, name](const serialport::Sc750Reply& reply) {
            if (generation != m_generation) return;
            // "NAME=value", numbers as PRINT shows them without spaces
            const qsizetype eq = reply.payload.indexOf(QLatin1Char('='));
            const std::optional<double> value = number(reply.payload.mid(eq + 1));
            if (!value) return emit failed(tr("%1 is not a number (%2)").arg(name, reply.payload), true);
            m_values.append(*value);
            if (m_values.size() < m_names.size()) return readNext(generation);
            emit answered(m_values);
        },
        [this, generation, name](const QString& why) {
            if (generation != m_generation) return;
            // "13 UNKNOWN VARIABLE" and the like will not change; a time-out or damaged answer may
            const bool refused = !why.isEmpty() && why.at(0).isDigit();
            emit failed(refused ? tr("the controller answered !%1 to G%2").arg(why, name) : why, refused);
        });
}

} // namespace app
