// Pmc960ParameterDock: the table, its reads and its checked writes.
#include "pmc960_parameter_dock.h"

#include "pmc960_program_transfer.h"
#include "theme.h"

#include "serialport/pmc960_parameter_values.h"
#include "serialport/pmc960_session.h"

#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

namespace app {

namespace {
using serialport::displayCommand;
using serialport::isReadOnlyFromHost; // why some are left alone: see there
using serialport::parameterName;
using serialport::parameterWrite;
using serialport::Pmc960Parameter;
using serialport::rangeText;
using serialport::valueFromDisplay;

std::span<const Pmc960Parameter> parameters() {
    return drive_core::catalog::pmc960::parameters();
}
} // namespace

// The PMC-960's variable browser is its parameter table: the dock carries the family's "Variables" title.
Pmc960ParameterDock::Pmc960ParameterDock(QWidget* parent)
    : QDockWidget(tr("Variables \u2014 PMC-960 Parameter Table"), parent) {
    setObjectName(QStringLiteral("pmc960ParameterDock"));
    auto* body = new QWidget(this);
    auto* layout = new QVBoxLayout(body);
    m_filter = new QLineEdit(body);
    m_filter->setPlaceholderText(tr("Search parameters by name or description"));
    m_filter->setClearButtonEnabled(true);
    layout->addWidget(m_filter);
    connect(m_filter, &QLineEdit::textChanged, this, &Pmc960ParameterDock::setFilter);
    m_table = new QTableWidget(int(parameters().size()), ColumnCount, body);
    m_table->setObjectName(QStringLiteral("pmc960ParameterTable"));
    m_table->setHorizontalHeaderLabels(
        {tr("Parameter"), tr("Stored (?)"), tr("In use (!)"), tr("Range"), tr("Description")});
    m_table->verticalHeader()->hide();
    m_table->setAlternatingRowColors(true);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed |
                             QAbstractItemView::AnyKeyPressed);
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_table->verticalHeader()->setDefaultSectionSize(m_table->fontMetrics().height() + 8);
    m_updating = true;
    for (int row = 0; row < int(parameters().size()); ++row) {
        const Pmc960Parameter& p = parameters()[std::size_t(row)];
        const QString description = QString::fromUtf8(p.description.data(), qsizetype(p.description.size()));
        auto* name = new QTableWidgetItem(parameterName(p));
        QFont bold = name->font();
        bold.setBold(true);
        name->setFont(bold);
        name->setToolTip(tr("%1 \u2014 %2 (%3)")
                             .arg(description, p.nonVolatile ? tr("parameter table, non-volatile") : tr("volatile"),
                                  QString::fromLatin1(p.manualLines.data(), qsizetype(p.manualLines.size()))));
        m_table->setItem(row, NameColumn, name);
        for (int column : {StoredColumn, InUseColumn}) {
            auto* item = new QTableWidgetItem(QStringLiteral("\u2014"));
            item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
            m_table->setItem(row, column, item);
        }
        m_table->setItem(row, RangeColumn, new QTableWidgetItem(rangeText(p)));
        m_table->setItem(row, DescriptionColumn, new QTableWidgetItem(description));
        for (int column = 0; column < ColumnCount; ++column) {
            QTableWidgetItem* item = m_table->item(row, column);
            const bool editable = column == StoredColumn && !isReadOnlyFromHost(p);
            item->setFlags(editable ? item->flags() | Qt::ItemIsEditable : item->flags() & ~Qt::ItemIsEditable);
        }
        if (isReadOnlyFromHost(p)) m_table->item(row, StoredColumn)->setToolTip(tr("Read only in this table"));
    }
    m_updating = false;
    m_table->resizeColumnsToContents();
    for (int column : {StoredColumn, InUseColumn}) m_table->setColumnWidth(column, 96);
    layout->addWidget(m_table);

    auto* bottom = new QHBoxLayout;
    m_message = new QLabel(tr("Double-click a stored value to change it."), body);
    m_message->setWordWrap(true);
    m_refresh = new QPushButton(tr("&Refresh"), body);
    bottom->addWidget(m_message, 1);
    bottom->addWidget(m_refresh);
    layout->addLayout(bottom);
    setWidget(body);
    connect(m_refresh, &QPushButton::clicked, this, &Pmc960ParameterDock::refresh);
    connect(m_table, &QTableWidget::itemChanged, this, &Pmc960ParameterDock::onItemChanged);
    m_refresh->setEnabled(false);
}

void Pmc960ParameterDock::setSession(serialport::Pmc960Session* session) {
    if (m_session == session) return;
    if (m_session) m_session->disconnect(this);
    m_session = session;
    m_reads.clear();
    m_writes.clear();
    m_refresh->setEnabled(m_session && !m_paused);
    if (!m_session) return;
    connect(m_session, &serialport::Pmc960Session::finished, this, &Pmc960ParameterDock::onFinished);
    connect(m_session, &serialport::Pmc960Session::failed, this, &Pmc960ParameterDock::onFailed);
    connect(m_session, &serialport::Pmc960Session::destroyed, this, [this] { m_session = nullptr; });
    refresh();
}

void Pmc960ParameterDock::setPaused(bool paused) {
    m_paused = paused;
    m_refresh->setEnabled(m_session && !m_paused);
}

void Pmc960ParameterDock::refresh() {
    if (!m_session || m_paused) return;
    for (int row = 0; row < m_table->rowCount(); ++row) readRow(row);
}

void Pmc960ParameterDock::readRow(int row) {
    const Pmc960Parameter& p = parameters()[std::size_t(row)];
    for (auto [column, kind] : {std::pair{int(StoredColumn), '?'}, std::pair{int(InUseColumn), '!'}}) {
        const QByteArray command = displayCommand(p, kind);
        if (!command.isEmpty()) m_reads.insert(m_session->send(command), {row, column});
    }
}

void Pmc960ParameterDock::onFinished(quint64 id, const serialport::Pmc960Response& response) {
    if (auto read = m_reads.find(id); read != m_reads.end()) {
        const Read r = *read;
        m_reads.erase(read);
        const Pmc960Parameter& p = parameters()[std::size_t(r.row)];
        setCell(r.row, r.column,
                response.error ? QStringLiteral("#%1").arg(response.error, 2, 16).toUpper()
                               : valueFromDisplay(p, response.value));
        markDifference(r.row);
        if (m_reads.isEmpty()) emit refreshed();
        return;
    }
    if (auto write = m_writes.find(id); write != m_writes.end()) {
        const Write w = *write;
        m_writes.erase(write);
        const QString name = parameterName(parameters()[std::size_t(w.row)]);
        if (response.error != 0)
            showMessage(tr("The PMC-960 refused %1 = %2: %3")
                            .arg(name, w.text, Pmc960ProgramTransfer::describeError(response.error)),
                        true);
        else
            showMessage(tr("%1 set to %2.").arg(name, w.text), false);
        readRow(w.row); // the cell shows what the controller holds, refused or not
        emit writeFinished(name, response.error == 0);
    }
}

void Pmc960ParameterDock::onFailed(quint64 id, const QString& reason) {
    if (m_reads.remove(id) && m_reads.isEmpty()) emit refreshed();
    if (auto write = m_writes.find(id); write != m_writes.end()) {
        const QString name = parameterName(parameters()[std::size_t(write->row)]);
        m_writes.erase(write);
        showMessage(tr("%1 was not written: %2").arg(name, reason), true);
        emit writeFinished(name, false);
    }
}

void Pmc960ParameterDock::onItemChanged(QTableWidgetItem* item) {
    if (m_updating || item->column() != StoredColumn) return;
    const QString name = m_table->item(item->row(), NameColumn)->text();
    if (!setStoredValue(name, item->text())) readRow(item->row()); // put the controller's value back
}

bool Pmc960ParameterDock::setStoredValue(const QString& name, const QString& text) {
    const int row = rowOf(name);
    if (row < 0 || !m_session) return false;
    const Pmc960Parameter& p = parameters()[std::size_t(row)];
    if (isReadOnlyFromHost(p)) {
        showMessage(tr("%1 is read only in this table.").arg(name), true);
        return false;
    }
    const serialport::ParameterWrite write = parameterWrite(p, text);
    if (!write.error.isEmpty()) {
        showMessage(write.error, true);
        return false;
    }
    if (write.needsWriteEnable) m_session->send("SW1\r");
    m_writes.insert(m_session->send(write.command), {row, text.trimmed()});
    if (write.needsWriteEnable) m_session->send("SW0\r");
    showMessage(tr("Writing %1 = %2\u2026").arg(name, text.trimmed()), false);
    return true;
}

void Pmc960ParameterDock::setFilter(const QString& text) {
    if (m_filter->text() != text) m_filter->setText(text); // comes back here through textChanged
    const QString wanted = text.trimmed();
    for (int row = 0; row < m_table->rowCount(); ++row) {
        const bool match = wanted.isEmpty() ||
                           m_table->item(row, NameColumn)->text().contains(wanted, Qt::CaseInsensitive) ||
                           m_table->item(row, DescriptionColumn)->text().contains(wanted, Qt::CaseInsensitive);
        m_table->setRowHidden(row, !match);
    }
}

int Pmc960ParameterDock::visibleRows() const {
    int shown = 0;
    for (int row = 0; row < m_table->rowCount(); ++row) shown += !m_table->isRowHidden(row);
    return shown;
}

int Pmc960ParameterDock::rowOf(const QString& name) const {
    for (int row = 0; row < m_table->rowCount(); ++row)
        if (m_table->item(row, NameColumn)->text().compare(name, Qt::CaseInsensitive) == 0) return row;
    return -1;
}

QString Pmc960ParameterDock::stored(const QString& name) const {
    const int row = rowOf(name);
    return row < 0 ? QString() : m_table->item(row, StoredColumn)->text();
}

QString Pmc960ParameterDock::inUse(const QString& name) const {
    const int row = rowOf(name);
    return row < 0 ? QString() : m_table->item(row, InUseColumn)->text();
}

QString Pmc960ParameterDock::message() const {
    return m_message->text();
}

void Pmc960ParameterDock::setCell(int row, int column, const QString& text) {
    m_updating = true;
    m_table->item(row, column)->setText(text);
    m_updating = false;
}

void Pmc960ParameterDock::markDifference(int row) {
    // Stored and in-use values differ after a generic power-up, or for the motion buffer while moving.
    QTableWidgetItem* inUse = m_table->item(row, InUseColumn);
    const bool differs =
        inUse->text() != m_table->item(row, StoredColumn)->text() && inUse->text() != QStringLiteral("\u2014");
    m_updating = true;
    inUse->setBackground(differs ? QColor(0xff, 0xf4, 0xce) : QBrush());
    inUse->setToolTip(differs ? tr("The value in use differs from the stored one") : QString());
    m_updating = false;
}

void Pmc960ParameterDock::showMessage(const QString& text, bool error) {
    Theme::showStatus(*m_message, text, error);
}

} // namespace app
