// ErrorLogDock: one table, the chosen family's source behind it; read, clear and export.
#include "error_log_dock.h"

#include "error_log_model.h"
#include "error_source.h"

#include <QFile>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QTableView>
#include <QVBoxLayout>

namespace app {

ErrorLogDock::ErrorLogDock(QWidget* parent) : QDockWidget(tr("Error Log"), parent) {
    setObjectName(QStringLiteral("errorLogDock"));
    auto* body = new QWidget(this);
    auto* layout = new QVBoxLayout(body);
    layout->setContentsMargins(4, 4, 4, 4);
    auto* bar = new QHBoxLayout;
    m_read = new QPushButton(body);
    m_read->setObjectName(QStringLiteral("errorLogRead"));
    m_clear = new QPushButton(tr("Clear"), body);
    auto* save = new QPushButton(tr("Export..."), body);
    bar->addWidget(m_read);
    bar->addWidget(m_clear);
    bar->addWidget(save);
    bar->addStretch(1);
    layout->addLayout(bar);
    m_view = new QTableView(body);
    m_view->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_view->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_view->verticalHeader()->hide();
    m_view->horizontalHeader()->setStretchLastSection(true);
    m_view->setWordWrap(false);
    layout->addWidget(m_view, 1);
    m_status = new QLabel(body);
    m_status->setObjectName(QStringLiteral("errorLogStatus"));
    layout->addWidget(m_status);
    setWidget(body);

    connect(m_read, &QPushButton::clicked, this, &ErrorLogDock::readHistory);
    connect(m_clear, &QPushButton::clicked, this, &ErrorLogDock::clearHistory);
    connect(save, &QPushButton::clicked, this, &ErrorLogDock::exportWithDialog);
    connect(m_view, &QTableView::activated, this, &ErrorLogDock::activate);
}

void ErrorLogDock::addSource(ErrorSource* source) {
    m_sources.append(source);
    // A workspace's source may go before the dock.
    connect(source, &QObject::destroyed, this, [this, source] {
        m_sources.removeAll(source);
        if (m_current == source) {
            m_current = nullptr;
            if (!m_sources.isEmpty()) showSource(m_sources.first());
        }
    });
    connect(source, &ErrorSource::statusChanged, this, [this, source](const QString& text) {
        if (source == m_current) setStatus(text);
    });
    if (!m_current) showSource(source); // the first family's, until setFamily
}

ErrorSource* ErrorLogDock::source(drive_core::DriveFamily family) const {
    // The last one added for a family wins, as with workspaces.
    for (auto it = m_sources.crbegin(); it != m_sources.crend(); ++it)
        if ((*it)->family() == family) return *it;
    return nullptr;
}

void ErrorLogDock::setFamily(drive_core::DriveFamily family) {
    if (ErrorSource* s = source(family)) showSource(s);
}

void ErrorLogDock::showSource(ErrorSource* source) {
    if (source == m_current) return;
    m_current = source;
    m_view->setModel(&source->model());
    m_view->setColumnWidth(ErrorLogModel::Severity, 100);
    m_view->setColumnWidth(ErrorLogModel::Code, 50);
    m_view->setColumnWidth(ErrorLogModel::Message, 340); // room for a PMC-960 snapshot or an SC750 message
    m_view->setColumnWidth(ErrorLogModel::Line, 50);
    m_view->setColumnWidth(ErrorLogModel::Source, 90);
    const ErrorSource::Buttons& buttons = source->buttons();
    m_read->setText(buttons.readText);
    m_read->setToolTip(buttons.readToolTip);
    m_read->setVisible(!buttons.readText.isEmpty());
    m_clear->setToolTip(buttons.clearToolTip);
    setStatus(source->statusText().isEmpty() ? tr("Double-click an error that names a line to go there.")
                                             : source->statusText());
}

ErrorLogModel& ErrorLogDock::model() const {
    return m_current->model();
}

void ErrorLogDock::readHistory() {
    m_current->read();
}

void ErrorLogDock::clearHistory() {
    m_current->clear();
}

void ErrorLogDock::activate(const QModelIndex& index) {
    const int line = index.siblingAtColumn(0).data(ErrorLogModel::ProgramLineRole).toInt();
    if (line > 0 && !m_current->showLine(model().entry(index.row()))) emit goToProgramLine(line);
}

bool ErrorLogDock::exportTo(const QString& path) {
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Truncate | QIODevice::Text) ||
        file.write(model().toCsv().toUtf8()) < 0) {
        setStatus(tr("Cannot write %1: %2").arg(path, file.errorString()));
        return false;
    }
    setStatus(tr("Exported %n error(s) to %1", nullptr, model().rowCount()).arg(path));
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
