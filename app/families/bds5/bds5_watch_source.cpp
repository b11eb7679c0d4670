// Bds5WatchSource: P polls.
#include "bds5_watch_source.h"

#include "drive_connection.h"
#include "scope/scope_catalog.h"
#include "transfer_dialog.h"

#include "serialport/bds5_session.h"
#include "serialport/bds5_transfer.h"
#include "serialport/watch_choices.h"

namespace app {

Bds5WatchSource::Bds5WatchSource(DriveConnection& connection, QObject* parent)
    : WatchSource(parent), m_connection(connection) {}

QList<WatchSource::Choice> Bds5WatchSource::choices() const {
    QList<Choice> list;
    for (const QString& name : pollableVariables())
        list.append({name, name, QString::fromStdString(unitOf(name.toUpper().toStdString()))});
    return list;
}

QString Bds5WatchSource::method() const {
    return serialport::watchMethod(drive_core::DriveFamily::Bds5);
}

QString Bds5WatchSource::notReady() const {
    serialport::Bds5Session* session = m_connection.session();
    if (!session || !m_connection.isConnected()) return tr("the drive is not connected");
    if (TransferDialog::active()) return tr("a transfer is under way");
    if (session->mode() != serialport::Bds5Mode::Interactive) return tr("the drive is not at an interactive prompt");
    return {};
}

void Bds5WatchSource::poll(const QStringList& names) {
    serialport::Bds5Session* session = m_connection.session();
    if (!session) return emit failed(tr("the drive is not connected"), false);
    connect(session, &serialport::Bds5Session::finished, this, &Bds5WatchSource::onAnswer, Qt::UniqueConnection);
    connect(session, &serialport::Bds5Session::failed, this, &Bds5WatchSource::onFailed, Qt::UniqueConnection);
    m_expected = int(names.size());
    m_pollId = session->send(QStringLiteral("P ") + names.join(QLatin1Char(' ')), serialport::Bds5Session::Echo::Quiet);
}

void Bds5WatchSource::onAnswer(quint64 id, const serialport::Bds5Response& response) {
    if (id != m_pollId) return;
    m_pollId = 0;
    if (!response.errors.isEmpty())
        return emit failed(tr("the drive answered %1").arg(serialport::describeError(response.errors.first())), true);
    const QStringList words = response.lines.join(QLatin1Char(' ')).split(QLatin1Char(' '), Qt::SkipEmptyParts);
    QList<double> values;
    if (words.size() >= m_expected && !response.garbled) {
        for (int i = 0; i < m_expected; ++i) {
            const std::optional<double> v = number(words[i]);
            if (!v) return emit answered({}); // a damaged line: no sample this time
            values.append(*v);
        }
    }
    emit answered(values);
}

void Bds5WatchSource::onFailed(quint64 id, const QString& reason) {
    if (id != m_pollId) return;
    m_pollId = 0;
    emit failed(reason, false);
}

} // namespace app
