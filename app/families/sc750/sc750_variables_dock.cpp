// Sc750VariablesDock: G and P frames for a list of watched names.
#include "sc750_variables_dock.h"

#include "sc750_debugger.h"
#include "sc750_workspace.h"
#include "session_host.h"
#include "theme.h"
#include "variables/variable_browser.h"

#include "drive_core/catalog/sc750_catalog.h"

#include <QCompleter>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QStringListModel>
#include <QTabWidget>
#include <QTableWidget>
#include <QVBoxLayout>

namespace app {

namespace catalog = drive_core::catalog::sc750;

Sc750VariablesDock::Sc750VariablesDock(Sc750Workspace& workspace, QWidget* parent)
    : QDockWidget(tr("Variables"), parent), m_workspace(workspace), m_name(new QLineEdit),
      m_completer(new QCompleter(this)), m_table(new QTableWidget(0, 2)), m_refresh(new QPushButton(tr("&Refresh"))),
      m_message(new QLabel) {
    setObjectName(QStringLiteral("sc750VariablesDock"));
    auto* body = new QWidget(this);
    auto* layout = new QVBoxLayout(body);
    layout->setContentsMargins(4, 4, 4, 4);
    m_name->setPlaceholderText(tr("Variable name, then Enter (RUN.SPEED, Count, A(3))"));
    m_completer->setCaseSensitivity(Qt::CaseInsensitive);
    m_completer->setModel(new QStringListModel(m_completer));
    m_name->setCompleter(m_completer);
    auto* read = new QPushButton(tr("Re&ad"));
    auto* row = new QHBoxLayout;
    row->addWidget(m_name, 1);
    row->addWidget(read);
    row->addWidget(m_refresh);
    m_table->setHorizontalHeaderLabels({tr("Name"), tr("Value")});
    m_table->horizontalHeader()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_table->verticalHeader()->hide();
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_message->setWordWrap(true);
    layout->addLayout(row);
    layout->addWidget(m_table, 1);
    layout->addWidget(m_message);
    // Two tabs: Motion Dialogue's list of typed names, and every predefined variable of the catalog.
    m_tabs = new QTabWidget(this);
    m_tabs->addTab(body, tr("&Watch"));
    m_browser = new VariableBrowser(SessionHost::of(workspace));
    m_browser->setListAction(tr("Add \"%1\" to the &Watch Tab"));
    m_tabs->addTab(m_browser, tr("All &Variables"));
    setWidget(m_tabs);
    connect(m_browser, &VariableBrowser::listRequested, this, [this](const QString& name) {
        readVariable(name);
        m_tabs->setCurrentIndex(0);
    });
    showMessage(tr("Values can be changed while no program executes (after Stop or at a breakpoint)."), false);

    auto readTyped = [this] {
        const QString name = m_name->text().trimmed();
        if (name.isEmpty()) return;
        readVariable(name);
        m_name->clear();
    };
    connect(m_name, &QLineEdit::returnPressed, this, readTyped);
    connect(read, &QPushButton::clicked, this, readTyped);
    connect(m_refresh, &QPushButton::clicked, this, &Sc750VariablesDock::refresh);
    connect(m_table, &QTableWidget::itemChanged, this, [this](QTableWidgetItem* item) {
        if (m_filling || item->column() != 1) return;
        writeVariable(m_table->item(item->row(), 0)->text(), item->text());
    });
    connect(&workspace.debugger(), &Sc750Debugger::stateChanged, this, &Sc750VariablesDock::updateCompletions);
    // Stopped at a breakpoint (or by Stop, STOP, END, an error): the watched values are read as they now stand.
    connect(&workspace.debugger(), &Sc750Debugger::halted, this, &Sc750VariablesDock::refresh);
    updateCompletions();
}

void Sc750VariablesDock::showAllVariables() {
    show();
    raise();
    m_tabs->setCurrentWidget(m_browser);
}

void Sc750VariablesDock::updateCompletions() {
    QStringList names;
    for (const auto& v : m_workspace.debugger().lastCompile().program.variables)
        if (!v.name.empty() && v.name.front() != '#') names << QString::fromStdString(v.name);
    for (const catalog::VariableInfo& v : catalog::variables())
        names << QString::fromLatin1(v.name.data(), qsizetype(v.name.size()));
    static_cast<QStringListModel*>(m_completer->model())->setStringList(names);
}

int Sc750VariablesDock::rowOf(const QString& name) const {
    for (int row = 0; row < m_table->rowCount(); ++row)
        if (m_table->item(row, 0)->text().compare(name, Qt::CaseInsensitive) == 0) return row;
    return -1;
}

int Sc750VariablesDock::ensureRow(const QString& name) {
    int row = rowOf(name);
    if (row >= 0) return row;
    m_filling = true;
    row = m_table->rowCount();
    m_table->insertRow(row);
    auto* nameItem = new QTableWidgetItem(name.toUpper());
    nameItem->setFlags(nameItem->flags() & ~Qt::ItemIsEditable);
    m_table->setItem(row, 0, nameItem);
    auto* valueItem = new QTableWidgetItem;
    if (!m_writable) valueItem->setFlags(valueItem->flags() & ~Qt::ItemIsEditable);
    m_table->setItem(row, 1, valueItem);
    m_filling = false;
    return row;
}

void Sc750VariablesDock::setValue(const QString& name, const QString& value) {
    m_filling = true;
    m_table->item(ensureRow(name), 1)->setText(value);
    m_filling = false;
    emit valueRead(name, value);
}

void Sc750VariablesDock::readVariable(const QString& name) {
    const QString upper = name.toUpper();
    ensureRow(upper);
    m_workspace.send(
        'G', upper,
        [this, upper](const serialport::Sc750Reply& reply) {
            // "NAME=value"; a string's value keeps its quotes
            const qsizetype eq = reply.payload.indexOf(QLatin1Char('='));
            setValue(upper, eq < 0 ? reply.payload : reply.payload.mid(eq + 1));
            showMessage(tr("%1 read").arg(upper), false);
        },
        [this, upper](const QString& why) { showMessage(tr("%1: %2").arg(upper, why), true); });
}

void Sc750VariablesDock::writeVariable(const QString& name, const QString& value) {
    const QString upper = name.toUpper();
    m_workspace.send(
        'P', QStringLiteral("%1=%2").arg(upper, value.trimmed()),
        [this, upper](const serialport::Sc750Reply& reply) {
            const qsizetype eq = reply.payload.indexOf(QLatin1Char('='));
            setValue(upper, reply.payload.mid(eq + 1));
            showMessage(tr("%1 written").arg(upper), false);
        },
        [this, upper](const QString& why) {
            showMessage(tr("%1 not written: %2").arg(upper, why), true);
            readVariable(upper); // show what the controller still holds
        });
}

void Sc750VariablesDock::refresh() {
    for (int row = 0; row < m_table->rowCount(); ++row) readVariable(m_table->item(row, 0)->text());
}

void Sc750VariablesDock::setWritable(bool writable) {
    m_writable = writable;
    m_filling = true;
    for (int row = 0; row < m_table->rowCount(); ++row) {
        QTableWidgetItem* item = m_table->item(row, 1);
        item->setFlags(writable ? item->flags() | Qt::ItemIsEditable : item->flags() & ~Qt::ItemIsEditable);
    }
    m_filling = false;
}

void Sc750VariablesDock::focusName() {
    m_tabs->setCurrentIndex(0);
    m_name->setFocus();
}

QString Sc750VariablesDock::value(const QString& name) const {
    const int row = rowOf(name);
    return row < 0 ? QString() : m_table->item(row, 1)->text();
}

QString Sc750VariablesDock::lastMessage() const {
    return m_message->text();
}

void Sc750VariablesDock::showMessage(const QString& text, bool error) {
    Theme::showStatus(*m_message, text, error);
}

} // namespace app
