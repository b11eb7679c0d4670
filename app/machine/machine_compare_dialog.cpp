// MachineCompareDialog: the axes on the left, their rows on the right.
#include "machine_compare_dialog.h"

#include <QCheckBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QFile>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QSaveFile>
#include <QSplitter>
#include <QTableWidget>
#include <QVBoxLayout>

namespace app {

using machine::AxisReport;
using machine::CompareRow;

namespace {
const QColor kDiffers(255, 226, 204); // a changed value: soft orange, readable in light and dark text

QString readText(const QString& path) {
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? QString::fromLatin1(f.readAll()) : QString();
}
bool writeText(const QString& path, const QString& text, QString& error) {
    QSaveFile f(path);
    if (f.open(QIODevice::WriteOnly) && f.write(text.toLatin1()) >= 0 && f.commit()) return true;
    error = f.errorString();
    return false;
}
} // namespace

MachineCompareDialog::MachineCompareDialog(QList<AxisReport> reports, machine::MachineProject project, QString dir,
                                           QString rightTitle, bool withDrive, QWidget* parent)
    : QDialog(parent), m_reports(std::move(reports)), m_project(std::move(project)), m_dir(std::move(dir)),
      m_withDrive(withDrive) {
    setWindowTitle(tr("Compare \u2014 %1").arg(QDir::toNativeSeparators(m_dir)));
    m_axes = new QListWidget;
    m_table = new QTableWidget(0, 3);
    m_table->setHorizontalHeaderLabels({tr("Variable / line"), tr("File"), rightTitle});
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    m_table->horizontalHeader()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
    m_table->verticalHeader()->hide();
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_onlyDifferences = new QCheckBox(tr("Only &differences"));
    m_onlyDifferences->setChecked(true);
    m_takeDrives = new QPushButton(withDrive ? tr("Take &Drive's") : tr("Take &Right"));
    m_takeDrives->setToolTip(tr("Write the selected rows' right-hand values into the axis's files"));
    m_takeFiles = new QPushButton(tr("Take &File's"));
    m_takeFiles->setToolTip(tr("Send the selected rows' file values to the drive (a program line: the file's whole "
                               "program, downloaded and verified)"));
    m_takeFiles->setVisible(withDrive);
    m_status = new QLabel;
    m_status->setWordWrap(true);

    auto* splitter = new QSplitter;
    splitter->addWidget(m_axes);
    splitter->addWidget(m_table);
    splitter->setStretchFactor(1, 4);
    auto* row = new QHBoxLayout;
    row->addWidget(m_onlyDifferences);
    row->addStretch();
    row->addWidget(m_takeDrives);
    row->addWidget(m_takeFiles);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(splitter, 1);
    layout->addLayout(row);
    layout->addWidget(m_status);
    layout->addWidget(buttons);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(m_axes, &QListWidget::currentRowChanged, this, &MachineCompareDialog::fillTable);
    connect(m_onlyDifferences, &QCheckBox::toggled, this, &MachineCompareDialog::fillTable);
    connect(m_takeDrives, &QPushButton::clicked, this, &MachineCompareDialog::takeDrives);
    connect(m_takeFiles, &QPushButton::clicked, this, &MachineCompareDialog::takeFiles);
    resize(900, 520);
    fillAxes();
    for (int i = 0; i < m_reports.size(); ++i) // open at the first axis that differs
        if (!machine::differences(m_reports[i].rows).isEmpty() || !m_reports[i].ok()) {
            m_axes->setCurrentRow(i);
            break;
        }
    if (m_axes->currentRow() < 0 && m_axes->count() > 0) m_axes->setCurrentRow(0);
    setStatus(differenceCount() == 0 ? tr("Every axis matches its files.")
                                     : tr("%1 in all.").arg(machine::counted(differenceCount(), tr("difference"), tr("differences"))));
}

void MachineCompareDialog::fillAxes() {
    const int keep = m_axes->currentRow();
    m_axes->blockSignals(true);
    m_axes->clear();
    for (const AxisReport& r : m_reports) {
        const qsizetype n = machine::differences(r.rows).size();
        QString text = r.outcome == AxisReport::Outcome::Failed ? tr("Axis %1 \u2014 failed").arg(r.id)
                       : n == 0                                 ? tr("Axis %1 \u2014 matches").arg(r.id)
                                                                : tr("Axis %1 \u2014 %2").arg(r.id, machine::counted(n, tr("difference"), tr("differences")));
        auto* item = new QListWidgetItem(text, m_axes);
        item->setToolTip(r.message);
        if (n > 0 || r.outcome == AxisReport::Outcome::Failed) item->setBackground(kDiffers);
    }
    m_axes->setCurrentRow(keep);
    m_axes->blockSignals(false);
}

AxisReport* MachineCompareDialog::current() {
    const int i = m_axes->currentRow();
    return i >= 0 && i < m_reports.size() ? &m_reports[i] : nullptr;
}

void MachineCompareDialog::fillTable() {
    m_table->setRowCount(0);
    m_shown.clear();
    const AxisReport* r = current();
    if (!r) return;
    if (r->outcome == AxisReport::Outcome::Failed) setStatus(tr("Axis %1: %2").arg(r->id, r->message));
    for (int i = 0; i < r->rows.size(); ++i) {
        const CompareRow& row = r->rows[i];
        if (m_onlyDifferences->isChecked() && !row.differs) continue;
        const int t = m_table->rowCount();
        m_table->insertRow(t);
        m_shown << i;
        const QString key = row.kind == CompareRow::Kind::Variable ? row.key
                            : row.leftLine > 0 ? tr("line %1").arg(row.leftLine)
                                               : tr("(line %1 right)").arg(row.rightLine);
        const QStringList cells{key, row.left, row.right};
        for (int c = 0; c < 3; ++c) {
            auto* item = new QTableWidgetItem(cells[c]);
            if (row.differs) item->setBackground(kDiffers);
            m_table->setItem(t, c, item);
        }
    }
}

QList<int> MachineCompareDialog::selectedRows() const {
    QList<int> rows;
    for (const QModelIndex& i : m_table->selectionModel()->selectedRows()) rows << m_shown.value(i.row(), -1);
    rows.removeAll(-1);
    std::sort(rows.begin(), rows.end());
    return rows;
}

// The right value into the file: a variable's line rewritten in place; a program line replaced (or added,
// or removed) as the right side has it.
void MachineCompareDialog::takeDrives() {
    AxisReport* r = current();
    const QList<int> rows = selectedRows();
    if (!r || rows.isEmpty()) return setStatus(tr("Select the rows to take first."));
    const machine::MachineAxis* axis = m_project.axis(r->id);
    if (!axis) return;
    const QString varPath = QDir(m_dir).filePath(axis->variablesFile);
    QString vars = readText(varPath);
    bool programChanged = false;
    for (int i : rows) {
        CompareRow& row = r->rows[i];
        if (row.kind == CompareRow::Kind::Variable && !row.right.isEmpty())
            vars = machine::withValue(r->family, vars, row.key, row.right);
        programChanged = programChanged || row.kind == CompareRow::Kind::ProgramLine;
    }
    QString error;
    if (!writeText(varPath, vars, error)) return setStatus(tr("%1: %2").arg(varPath, error));
    if (programChanged && !axis->programFile.isEmpty()) {
        // The program rebuilt from the rows: a taken row gives the right side, the others the left.
        QStringList lines;
        for (int i = 0; i < r->rows.size(); ++i) {
            const CompareRow& row = r->rows[i];
            const bool take = rows.contains(i) && row.kind == CompareRow::Kind::ProgramLine;
            if (row.kind != CompareRow::Kind::ProgramLine) continue;
            if (take ? row.rightLine > 0 : row.leftLine > 0) lines << (take ? row.right : row.left);
        }
        const QString path = QDir(m_dir).filePath(axis->programFile);
        if (!writeText(path, lines.isEmpty() ? QString() : lines.join(QLatin1Char('\n')) + QLatin1Char('\n'), error))
            return setStatus(tr("%1: %2").arg(path, error));
    }
    for (int i : rows) {
        r->rows[i].left = r->rows[i].right;
        r->rows[i].differs = false;
    }
    setStatus(tr("Wrote %1 of axis %2 into its files.").arg(machine::counted(rows.size(), tr("row"), tr("rows")), r->id));
    fillAxes();
    fillTable();
}

void MachineCompareDialog::takeFiles() {
    AxisReport* r = current();
    const QList<int> rows = selectedRows();
    if (!r || rows.isEmpty()) return setStatus(tr("Select the rows to send first."));
    QList<machine::NamedValue> values;
    bool program = false;
    for (int i : rows) {
        const CompareRow& row = r->rows[i];
        if (row.kind == CompareRow::Kind::ProgramLine) program = true;
        else if (!row.left.isEmpty()) values.append({row.key, row.left, row.leftLine});
    }
    const QStringList lines = machine::settingLines(r->family, values);
    m_sending = rows;
    if (program) { // the file's whole program: every program row matches once it is on the drive
        const machine::MachineAxis* axis = m_project.axis(r->id);
        const QString text = axis ? readText(QDir(m_dir).filePath(axis->programFile)) : QString();
        m_sending.clear();
        for (int i = 0; i < r->rows.size(); ++i)
            if (r->rows[i].kind == CompareRow::Kind::ProgramLine) m_sending << i;
        setStatus(tr("Downloading axis %1's program from its file...").arg(r->id) +
                  (lines.isEmpty() ? QString() : tr(" Take the selected variables once it is done.")));
        emit downloadToDrive(r->id, text);
        return;
    }
    setStatus(tr("Sending %1 to axis %2...").arg(machine::counted(values.size(), tr("value"), tr("values")), r->id));
    emit sendToDrive(r->id, lines);
}

void MachineCompareDialog::drivesAnswer(const QString& id, bool ok, const QString& message) {
    AxisReport* r = current();
    if (!r || r->id != id) return setStatus(message);
    if (!ok) return setStatus(tr("Axis %1: %2").arg(id, message));
    for (auto it = m_sending.crbegin(); it != m_sending.crend(); ++it) { // from the end: rows may go
        CompareRow& row = r->rows[*it];
        if (row.kind == CompareRow::Kind::ProgramLine && row.leftLine == 0) {
            r->rows.removeAt(*it); // a line only the drive had is gone with the file's program
            continue;
        }
        row.right = row.left;
        row.rightLine = row.leftLine;
        row.differs = false;
    }
    m_sending.clear();
    setStatus(tr("Axis %1 took the file's values: %2").arg(id, message));
    fillAxes();
    fillTable();
}

void MachineCompareDialog::showAxis(const QString& id) {
    for (int i = 0; i < m_reports.size(); ++i)
        if (m_reports[i].id == id) m_axes->setCurrentRow(i);
}

int MachineCompareDialog::differenceCount() const {
    int n = 0;
    for (const AxisReport& r : m_reports) n += int(machine::differences(r.rows).size());
    return n;
}

QString MachineCompareDialog::statusText() const {
    return m_status->text();
}

void MachineCompareDialog::setStatus(const QString& text) {
    m_status->setText(text);
}

} // namespace app
