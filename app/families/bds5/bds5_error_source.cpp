// Bds5ErrorSource: ERR HIST, ERR CLR and the errors the BDS5 reports by itself.
#include "bds5_error_source.h"

#include "bds5_error_text.h"
#include "drive_connection.h"

namespace app {

Bds5ErrorSource::Bds5ErrorSource(DriveConnection& connection, QObject* parent)
    : ErrorSource(drive_core::DriveFamily::Bds5,
                  {tr("Read History"), tr("ERR HIST: the drive's 20 most recent errors, newest first"),
                   tr("ERR CLR: clears the drive's error history")},
                  parent),
      m_connection(connection) {
    connect(&m_connection, &DriveConnection::rawReceived, this, &Bds5ErrorSource::onBytes);
}

void Bds5ErrorSource::follow() {
    serialport::Bds5Session* session = m_connection.session();
    if (session == m_session) return;
    m_session = session;
    if (session) connect(session, &serialport::Bds5Session::finished, this, &Bds5ErrorSource::onFinished);
}

void Bds5ErrorSource::read() {
    follow();
    if (!m_session || !m_connection.isConnected()) return setStatus(tr("Not connected: the history was not read."));
    m_historyId = m_session->send(QStringLiteral("ERR HIST"));
    setStatus(tr("Reading the error history (ERR HIST)..."));
}

void Bds5ErrorSource::clear() {
    follow();
    if (!m_session || !m_connection.isConnected()) return setStatus(tr("Not connected: nothing was cleared."));
    model().clear();
    m_session->send(QStringLiteral("ERR CLR"));
    read();
}

void Bds5ErrorSource::onFinished(quint64 id, const serialport::Bds5Response& response) {
    if (id != m_historyId) return;
    m_historyId = 0;
    // The listing's lines look like error lines, so the session may have filed them as errors: read the text.
    const QList<serialport::Bds5ErrorLine> history = ErrorStreamScanner::parseHistory(response.text);
    std::vector<ErrorLogModel::Entry> rows;
    for (const serialport::Bds5ErrorLine& error : history) rows.push_back(Bds5ErrorText::entry(error));
    model().setHistory(std::move(rows));
    setStatus(history.isEmpty() ? tr("The drive's error history is empty.")
                                : tr("ERR HIST: %n error(s), newest first.", nullptr, int(history.size())));
}

void Bds5ErrorSource::onBytes(const QByteArray& bytes) {
    for (const serialport::Bds5ErrorLine& error : m_scanner.feed(bytes))
        model().addReported(Bds5ErrorText::entry(error), QDateTime::currentDateTime());
}

} // namespace app
