// SummaryPage: review, send and save the wizard's changes.
#include "summary_page.h"

#include "variables/variable_sync.h"
#include "wizard_changes.h"

#include <QFile>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QTreeWidget>
#include <QVBoxLayout>

namespace app {

SummaryPage::SummaryPage(WizardContext context, QWidget* parent) : QWizardPage(parent), m_context(context) {
    setTitle(tr("Send Variables"));
    setSubTitle(tr("What the previous pages changed. Nothing has been sent to the drive yet."));
    auto* layout = new QVBoxLayout(this);
    m_table = new QTreeWidget(this);
    m_table->setRootIsDecorated(false);
    m_table->setHeaderLabels({tr("Variable"), tr("On the drive"), tr("New value"), tr("Result")});
    m_table->header()->setStretchLastSection(true);
    for (int column = 0; column < 3; ++column) m_table->setColumnWidth(column, 140);
    layout->addWidget(m_table, 1);
    auto* row = new QHBoxLayout;
    m_send = new QPushButton(tr("Send to Drive"), this);
    auto* save = new QPushButton(tr("Save as .VAR..."), this);
    auto* discard = new QPushButton(tr("Discard Changes"), this);
    row->addWidget(m_send);
    row->addWidget(save);
    row->addWidget(discard);
    row->addStretch(1);
    layout->addLayout(row);
    m_note = new QLabel(this);
    m_note->setWordWrap(true);
    layout->addWidget(m_note);
    connect(m_send, &QPushButton::clicked, this, &SummaryPage::send);
    connect(save, &QPushButton::clicked, this, &SummaryPage::saveWithDialog);
    connect(discard, &QPushButton::clicked, &m_context.changes, &WizardChanges::discard);
    connect(&m_context.changes, &WizardChanges::changed, this, &SummaryPage::refresh);
    connect(&m_context.sync, &VariableSync::writeFinished, this,
            [this](const QString& name, bool accepted, const QString& message) {
                if (!m_status.contains(name)) return; // not one of ours
                m_status[name] = accepted ? tr("sent") : message;
                if (accepted) m_context.changes.markApplied(name);
                refresh();
            });
}

void SummaryPage::initializePage() {
    m_status.clear();
    refresh();
}

void SummaryPage::refresh() {
    QStringList names = m_context.changes.changedNames();
    for (const QString& name : m_status.keys()) // keep the sent ones on the list, with their result
        if (!names.contains(name)) names << name;
    m_table->clear();
    for (const QString& name : names) {
        const WizardChanges::Change c = m_context.changes.change(name);
        auto* item = new QTreeWidgetItem(
            m_table, {name, c.original, c.edited.isEmpty() ? c.original : c.edited, m_status.value(name)});
        if (m_status.value(name).startsWith(tr("The drive refused"))) item->setForeground(3, QColor(0xb3, 0x26, 0x1e));
    }
    const int pending = int(m_context.changes.changedNames().size());
    m_send->setEnabled(pending > 0);
    m_note->setText(pending ? tr("%n change(s) waiting. Send them, save them as .VAR, or go back.", nullptr, pending)
                            : tr("No changes waiting."));
}

void SummaryPage::send() {
    for (const QString& name : m_context.changes.changedNames()) {
        m_status[name] = tr("sending...");
        m_context.sync.write(name, {name + QLatin1Char(' ') + m_context.changes.change(name).edited});
    }
    refresh();
}

bool SummaryPage::saveVar(const QString& path) {
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Truncate | QIODevice::Text) ||
        file.write(m_context.changes.toVar().toLatin1()) < 0) {
        m_note->setText(tr("Cannot write %1: %2").arg(path, file.errorString()));
        return false;
    }
    m_note->setText(tr("Saved the changes to %1").arg(path));
    return true;
}

void SummaryPage::saveWithDialog() {
    auto* dialog = new QFileDialog(this, tr("Save Variables"), QString(), tr("Variable sets (*.var *.VAR)"));
    dialog->setAcceptMode(QFileDialog::AcceptSave);
    dialog->setDefaultSuffix(QStringLiteral("VAR"));
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    connect(dialog, &QFileDialog::fileSelected, this, [this](const QString& path) { saveVar(path); });
    dialog->open();
}

} // namespace app
