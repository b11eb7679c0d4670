// ErrorLogDock: ERR HIST, live errors, clear and export.
#include "error_log_dock.h"

#include "drive_connection.h"
#include "error_log_model.h"

#include <QDateTime>
#include <QFile>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QTableView>
#include <QVBoxLayout>

namespace app {

ErrorLogDock::ErrorLogDock(DriveConnection& connection, QWidget* parent)
    : QDockWidget(tr("Error Log"), parent), m_connection(connection), m_model(new ErrorLogModel(this)) {
    setObjectName(QStringLiteral("errorLogDock"));
    auto* body = new QWidget(this);
    auto* layout = new QVBoxLayout(body);
    layout->setContentsMargins(4, 4, 4, 4);
    auto* bar = new QHBoxLayout;
    auto* read = new QPushButton(tr("Read History"), body);
    read->setToolTip(tr("ERR HIST: the drive's 20 most recent errors, newest first"));
    auto* clear = new QPushButton(tr("Clear"), body);
    clear->setToolTip(tr("ERR CLR: clears the drive's error history"));
    auto* save = new QPushButton(tr("Export..."), body);
    bar->addWidget(read);
    bar->addWidget(clear);
    bar->addWidget(save);
    bar->addStretch(1);
    layout->addLayout(bar);
    m_view = new QTableView(body);
    m_view->setModel(m_model);
    m_view->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_view->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_view->verticalHeader()->hide();
    m_view->horizontalHeader()->setStretchLastSection(true);
    m_view->setWordWrap(false);
    m_view->setColumnWidth(ErrorLogModel::Severity, 100);
    m_view->setColumnWidth(ErrorLogModel::Code, 50);
    m_view->setColumnWidth(ErrorLogModel::Message, 260);
    m_view->setColumnWidth(ErrorLogModel::Line, 50);
    m_view->setColumnWidth(ErrorLogModel::Source, 90);
    layout->addWidget(m_view, 1);
    m_status = new QLabel(body);
    m_status->setObjectName(QStringLiteral("errorLogStatus"));
    layout->addWidget(m_status);
    setWidget(body);

    connect(read, &QPushButton::clicked, this, &ErrorLogDock::readHistory);
    connect(clear, &QPushButton::clicked, this, &ErrorLogDock::clearHistory);
    connect(save, &QPushButton::clicked, this, &ErrorLogDock::exportWithDialog);
    connect(m_view, &QTableView::activated, this, &ErrorLogDock::activate);
    connect(&m_connection, &DriveConnection::rawReceived, this, &ErrorLogDock::onBytes);
    setStatus(tr("Double-click an error that names a line to go there."));
}

void ErrorLogDock::follow() {
    serialport::Bds5Session* session = m_connection.session();
    if (session == m_session) return;
    m_session = session;
    if (session) connect(session, &serialport::Bds5Session::finished, this, &ErrorLogDock::onFinished);
}

void ErrorLogDock::readHistory() {
    follow();
    if (!m_session || !m_connection.isConnected()) return setStatus(tr("Not connected: the history was not read."));
    m_historyId = m_session->send(QStringLiteral("ERR HIST"));
    setStatus(tr("Reading the error history (ERR HIST)..."));
}

void ErrorLogDock::clearHistory() {
    follow();
    if (!m_session || !m_connection.isConnected()) return setStatus(tr("Not connected: nothing was cleared."));
    m_model->clear();
    m_session->send(QStringLiteral("ERR CLR"));
    readHistory();
}

void ErrorLogDock::onFinished(quint64 id, const serialport::Bds5Response& response) {
    if (id != m_historyId) return;
    m_historyId = 0;
    // The listing's lines look like error lines, so the session may have filed them as errors: read the text.
    const QList<serialport::Bds5ErrorLine> history = ErrorStreamScanner::parseHistory(response.text);
    m_model->setHistory(history);
    setStatus(history.isEmpty() ? tr("The drive's error history is empty.")
                                : tr("ERR HIST: %n error(s), newest first.", nullptr, int(history.size())));
}

void ErrorLogDock::onBytes(const QByteArray& bytes) {
    for (const serialport::Bds5ErrorLine& error : m_scanner.feed(bytes))
        m_model->addReported(error, QDateTime::currentDateTime());
}

void ErrorLogDock::activate(const QModelIndex& index) {
    const int line = index.siblingAtColumn(0).data(ErrorLogModel::ProgramLineRole).toInt();
    if (line > 0) emit goToProgramLine(line);
}

bool ErrorLogDock::exportTo(const QString& path) {
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Truncate | QIODevice::Text) ||
        file.write(m_model->toCsv().toUtf8()) < 0) {
        setStatus(tr("Cannot write %1: %2").arg(path, file.errorString()));
        return false;
    }
    setStatus(tr("Exported %n error(s) to %1", nullptr, m_model->rowCount()).arg(path));
    return true;
}

void ErrorLogDock::exportWithDialog() {
    auto* dialog = new QFileDialog(this, tr("Export Error Log"), QString(), tr("CSV files (*.csv)"));
    dialog->setAcceptMode(QFileDialog::AcceptSave);
    dialog->setDefaultSuffix(QStringLiteral("csv"));
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    connect(dialog, &QFileDialog::fileSelected, this, [this](const QString& path) { exportTo(path); });
    dialog->open();
}

QString ErrorLogDock::statusText() const {
    return m_status->text();
}

void ErrorLogDock::setStatus(const QString& text) {
    m_status->setText(text);
}

} // namespace app
