// AxesDock: the line form, the axes table, and the machine's jobs over the line.
#include "axes_dock.h"

#include "machine_compare_dialog.h"

#include "machine/axis_errand.h"
#include "machine/axis_status.h"
#include "serialport/axis_link.h"
#include "serialport/port_link.h"
#include "serialport/simulator_link.h"

#include <QAction>
#include <QComboBox>
#include <QDateTime>
#include <QDir>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QInputDialog>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QProgressBar>
#include <QPushButton>
#include <QStandardPaths>
#include <QTableWidget>
#include <QTimer>
#include <QToolButton>
#include <QVBoxLayout>

namespace app {

using drive_core::DriveFamily;
using machine::AxisReport;
using machine::MachineJob;
using machine::MachineProject;

namespace {
constexpr int kScanWaitMs = 100; // how long a called ID may take to answer (a BDS5 answers in ~10 ms)
enum Column { kId, kFamily, kAnswer, kStatus, kLastJob, kColumns };

QString simulatedIds(DriveFamily f) {
    return f == DriveFamily::Sc750 ? QStringLiteral("1,2,3,4") : QStringLiteral("A,B,C,D");
}
QString callIds(DriveFamily f) {
    switch (f) {
    case DriveFamily::Bds5: return QStringLiteral("0-9,A-Z");
    case DriveFamily::Sc750: return QStringLiteral("0-31");
    case DriveFamily::Pmc960: return QStringLiteral("A-Z,0-9");
    }
    return {};
}
QString readText(const QString& path) {
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? QString::fromLatin1(f.readAll()) : QString();
}
} // namespace

AxesDock::AxesDock(QWidget* parent) : QDockWidget(tr("Axes"), parent) {
    setObjectName(QStringLiteral("AxesDock"));
    m_table = new QTableWidget(0, kColumns);
    m_table->setHorizontalHeaderLabels({tr("ID"), tr("Family"), tr("Answer"), tr("Status"), tr("Last job")});
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_table->verticalHeader()->hide();
    m_table->verticalHeader()->setDefaultSectionSize(m_table->fontMetrics().height() + 6);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setSelectionMode(QAbstractItemView::SingleSelection);
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setToolTip(tr("Double-click an axis to point every tool at it"));
    m_progress = new QProgressBar;
    m_progress->setVisible(false);
    m_status = new QLabel(tr("Set up the line, then Scan."));
    m_status->setWordWrap(true);
    m_cancel = new QPushButton(tr("Cancel"));
    m_cancel->setVisible(false);

    m_scanAction = new QAction(tr("&Scan Line"), this);
    m_scanAction->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_L));
    m_scanAction->setToolTip(tr("Call every ID on the line and list the axes that answer"));
    m_useAction = new QAction(tr("&Use Axis"), this);
    m_useAction->setToolTip(tr("Point the editor, terminal, variables and every other tool at the selected axis"));
    m_backUpAction = new QAction(tr("&Back Up Machine..."), this);
    m_compareAction = new QAction(tr("&Compare with Backup..."), this);
    m_compareBackupsAction = new QAction(tr("Compare &Two Backups..."), this);
    m_restoreAction = new QAction(tr("&Restore Machine..."), this);
    m_openAction = new QAction(tr("&Open Machine Project..."), this);
    m_openAction->setToolTip(tr("Set the line up as a backup's machine.sdm names it, and list its axes"));
    m_broadcastAction = new QAction(tr("Broa&dcast..."), this);
    m_broadcastAction->setToolTip(tr("Send one command line to every axis at once; none answers (BDS5)"));
    connect(m_scanAction, &QAction::triggered, this, &AxesDock::scan);
    connect(m_useAction, &QAction::triggered, this, [this] {
        const int row = m_table->currentRow();
        if (row < 0) return setStatus(tr("Select an axis in the table first."));
        useAxis(m_table->item(row, kId)->text());
    });
    connect(m_backUpAction, &QAction::triggered, this, [this] { chooseFolderAnd(&AxesDock::backUpTo, false); });
    connect(m_compareAction, &QAction::triggered, this, [this] { chooseFolderAnd(&AxesDock::compareWith, true); });
    connect(m_restoreAction, &QAction::triggered, this, [this] { chooseFolderAnd(&AxesDock::restoreFrom, true); });
    connect(m_compareBackupsAction, &QAction::triggered, this, &AxesDock::chooseBackupsToCompare);
    connect(m_openAction, &QAction::triggered, this, [this] { chooseFolderAnd(&AxesDock::openProject, true); });
    connect(m_broadcastAction, &QAction::triggered, this, [this] {
        bool ok = false;
        const QString line = QInputDialog::getText(this, tr("Broadcast"),
                                                   tr("A command line every axis executes (none answers):"),
                                                   QLineEdit::Normal, QString(), &ok);
        if (ok && !line.trimmed().isEmpty()) broadcast(line.trimmed());
    });
    connect(m_table, &QTableWidget::cellDoubleClicked, this, [this](int row) { useAxis(m_table->item(row, kId)->text()); });
    connect(m_cancel, &QPushButton::clicked, this, &AxesDock::cancel);

    auto* buttons = new QHBoxLayout;
    for (QAction* a : {m_scanAction, m_useAction, m_backUpAction, m_compareAction, m_restoreAction}) {
        auto* b = new QToolButton;
        b->setDefaultAction(a);
        buttons->addWidget(b);
    }
    buttons->addStretch();
    auto* body = new QWidget;
    auto* layout = new QVBoxLayout(body);
    layout->addWidget(makeLineForm());
    layout->addLayout(buttons);
    layout->addWidget(m_table, 1);
    auto* bottom = new QHBoxLayout;
    bottom->addWidget(m_progress, 1);
    bottom->addWidget(m_cancel);
    layout->addLayout(bottom);
    layout->addWidget(m_status);
    setWidget(body);
}

AxesDock::~AxesDock() {
    m_scan.reset();
    m_job.reset();
    delete m_errand.data();
}

QWidget* AxesDock::makeLineForm() {
    m_familyBox = new QComboBox;
    for (DriveFamily f : {DriveFamily::Bds5, DriveFamily::Sc750, DriveFamily::Pmc960})
        m_familyBox->addItem(ConnectionChoice::familyName(f), int(f));
    m_kindBox = new QComboBox;
    m_kindBox->addItems({tr("Simulated line"), tr("Serial port or device server")});
    m_where = new QLineEdit(simulatedIds(DriveFamily::Bds5));
    m_baudBox = new QComboBox;
    for (int b : ConnectionChoice::baudRates()) m_baudBox->addItem(QString::number(b), b);
    m_baudBox->setCurrentText(QStringLiteral("9600"));
    m_callIds = new QLineEdit(callIds(DriveFamily::Bds5));
    m_callIds->setToolTip(tr("The IDs a scan calls: a list (A,B,D) or ranges (0-31, A-Z)"));
    auto* form = new QWidget;
    auto* f = new QFormLayout(form);
    f->setContentsMargins(0, 0, 0, 0);
    auto* kindRow = new QHBoxLayout;
    kindRow->addWidget(m_familyBox);
    kindRow->addWidget(m_kindBox, 1);
    kindRow->addWidget(m_baudBox);
    f->addRow(tr("Line:"), kindRow);
    f->addRow(tr("Axes on it:"), m_where);
    f->addRow(tr("Scan calls:"), m_callIds);
    connect(m_familyBox, &QComboBox::currentIndexChanged, this, [this] {
        m_callIds->setText(callIds(family()));
        m_broadcastAction->setEnabled(!serialport::axisBroadcastBytes(family(), QStringLiteral("P")).isEmpty());
        if (m_kindBox->currentIndex() == 0) m_where->setText(simulatedIds(family()));
    });
    connect(m_kindBox, &QComboBox::currentIndexChanged, this, &AxesDock::showLineKind);
    showLineKind();
    return form;
}

void AxesDock::showLineKind() {
    const bool simulated = m_kindBox->currentIndex() == 0;
    auto* form = qobject_cast<QFormLayout*>(m_where->parentWidget()->layout());
    if (form) form->labelForField(m_where)->setProperty("text", simulated ? tr("Axes on it:") : tr("Port:"));
    m_where->setPlaceholderText(simulated ? tr("A,B,C,D") : tr("/dev/ttyUSB0, tcp://host:port, rfc2217://host:port"));
    if (simulated && m_where->text().isEmpty()) m_where->setText(simulatedIds(family()));
    if (!simulated && m_where->text() == simulatedIds(family())) m_where->clear();
}

DriveFamily AxesDock::family() const {
    return DriveFamily(m_familyBox->currentData().toInt());
}

void AxesDock::followFamily(DriveFamily f) {
    if (!m_line && !isBusy()) m_familyBox->setCurrentIndex(m_familyBox->findData(int(f)));
}

void AxesDock::setSimulatedLine(DriveFamily f, const QString& ids) {
    m_familyBox->setCurrentIndex(m_familyBox->findData(int(f)));
    m_kindBox->setCurrentIndex(0);
    m_where->setText(ids);
}

void AxesDock::setPortLine(DriveFamily f, const QString& port, int baud) {
    m_familyBox->setCurrentIndex(m_familyBox->findData(int(f)));
    m_kindBox->setCurrentIndex(1);
    m_where->setText(port);
    m_baudBox->setCurrentText(QString::number(baud));
}

QList<QAction*> AxesDock::menuActions() const {
    return {m_openAction, m_scanAction, m_useAction, m_broadcastAction, m_backUpAction, m_compareAction, m_compareBackupsAction,
            m_restoreAction};
}

QString AxesDock::statusText() const {
    return m_status->text();
}

void AxesDock::setStatus(const QString& text) {
    m_status->setText(text);
}

bool AxesDock::ensureLine() {
    const bool simulated = m_kindBox->currentIndex() == 0;
    const int baud = m_baudBox->currentData().toInt();
    const QString key = QStringLiteral("%1|%2|%3|%4").arg(int(family())).arg(simulated).arg(m_where->text()).arg(baud);
    if (m_line && key == m_lineKey) return true;
    std::unique_ptr<serialport::Link> link;
    if (simulated) {
        QString error;
        const QStringList ids = serialport::parseAxisIds(family(), m_where->text(), error);
        if (ids.isEmpty()) {
            setStatus(tr("Axes on the simulated line: %1").arg(error));
            return false;
        }
        serialport::SimulatorLink::Options options;
        options.baudRate = baud;
        options.speedFactor = m_speed;
        for (const QString& id : ids) options.axes.push_back(id.toStdString());
        link = std::make_unique<serialport::SimulatorLink>(family(), options);
    } else {
        if (m_where->text().trimmed().isEmpty()) {
            setStatus(tr("Name the port the line is on (a serial port or a device server's URL)."));
            return false;
        }
        link = serialport::makePortLink(m_where->text().trimmed(), baud, family());
    }
    if (m_line) emit lineNeeded(m_line); // the IDE leaves the old line before it goes
    connect(link.get(), &serialport::Link::errorOccurred, this, [this](const QString& why) { setStatus(why); });
    m_line = std::shared_ptr<serialport::Link>(link.release(), [](serialport::Link* l) { l->deleteLater(); });
    m_lineKey = key;
    m_table->setRowCount(0);
    return true;
}

void AxesDock::setBusy(bool busy) {
    for (QAction* a : menuActions()) a->setEnabled(!busy);
    m_broadcastAction->setEnabled(!busy && !serialport::axisBroadcastBytes(family(), QStringLiteral("P")).isEmpty());
    m_progress->setVisible(busy);
    m_cancel->setVisible(busy);
    if (busy) m_progress->setValue(0);
    emit busyChanged(busy);
}

void AxesDock::openProject(const QString& dir) {
    if (saidBusy()) return;
    QString error;
    const auto project = machine::readMachineProject(dir, error);
    if (!project) return setStatus(error);
    QStringList ids;
    for (const machine::MachineAxis& a : project->axes) ids << a.id;
    if (project->port.isEmpty()) setSimulatedLine(project->family(), ids.join(QLatin1Char(',')));
    else setPortLine(project->family(), project->port, project->baud);
    m_callIds->setText(ids.join(QLatin1Char(',')));
    if (!ensureLine()) return;
    QList<machine::FoundAxis> axes;
    for (const machine::MachineAxis& a : project->axes) axes.append({a.id, a.family, tr("in the project")});
    showScan(axes);
    m_projectDir = dir;
    setStatus(tr("%1: %2 on %3%4. Scan to see which answer.")
                  .arg(QDir::toNativeSeparators(dir), machine::counted(axes.size(), tr("axis"), tr("axes")),
                       m_line->description(),
                       project->backedUp.isEmpty() ? QString() : tr(", backed up %1").arg(project->backedUp)));
}

bool AxesDock::saidBusy() {
    if (!isBusy()) return false;
    setStatus(tr("Wait for the scan or the job under way to finish (or cancel it)."));
    return true;
}

void AxesDock::scan() {
    if (saidBusy() || !ensureLine()) return;
    QString error;
    const QStringList ids = serialport::parseAxisIds(family(), m_callIds->text(), error);
    if (ids.isEmpty()) return setStatus(tr("Scan calls: %1").arg(error));
    emit lineNeeded(m_line);
    m_scan = std::make_unique<machine::AxisScan>(*m_line, family(), ids, kScanWaitMs);
    connect(m_scan.get(), &machine::AxisScan::progress, this, [this, ids](int called, int total) {
        m_progress->setRange(0, total);
        m_progress->setValue(called);
        setStatus(tr("Calling axis %1 (%2 of %3)...").arg(ids.value(called)).arg(called + 1).arg(total));
    });
    connect(m_scan.get(), &machine::AxisScan::finished, this, [this, ids](const QList<machine::FoundAxis>& axes) {
        QTimer::singleShot(0, this, [this, axes, n = ids.size()] {
            m_scan.reset();
            showScan(axes);
            const QString found =
                axes.isEmpty() ? tr("No axis answered on %1 (%2 IDs called).").arg(m_line->description()).arg(n)
                               : tr("%1 answered on %2 (%3 IDs called). Double-click one to use it.")
                                     .arg(machine::counted(axes.size(), tr("axis"), tr("axes")))
                                     .arg(m_line->description())
                                     .arg(n);
            readStatus(0, found);
        });
    });
    setBusy(true);
    setStatus(tr("Scanning %1...").arg(m_line->description()));
    if (m_line->isOpen()) return m_scan->start();
    auto* once = new QObject(this);
    connect(m_line.get(), &serialport::Link::opened, once, [this, once] {
        delete once;
        if (m_scan) m_scan->start();
    });
    m_line->open();
}

// Each axis's status after a scan, one axis at a time; the scan is finished when the last has answered.
void AxesDock::readStatus(int row, const QString& found) {
    if (row >= m_table->rowCount()) {
        setBusy(false);
        setStatus(found);
        return emit scanFinished(m_table->rowCount());
    }
    const QString id = m_table->item(row, kId)->text();
    setStatus(tr("Reading the status of axis %1...").arg(id));
    auto* errand = new machine::AxisErrand(*m_line, family(), id, this);
    m_errand = errand;
    connect(errand, &machine::AxisErrand::finished, this, [this, errand, row, found](bool ok, const QString& why) {
        errand->deleteLater();
        m_errand = nullptr;
        const QString text = ok ? machine::statusText(family(), errand->answers()) : tr("no status: %1").arg(why);
        auto* item = new QTableWidgetItem(text);
        item->setToolTip(text);
        m_table->setItem(row, kStatus, item);
        readStatus(row + 1, found);
    });
    errand->sendLines(machine::statusQueries(family()));
}

void AxesDock::showScan(const QList<machine::FoundAxis>& axes) {
    m_table->setRowCount(0);
    for (const machine::FoundAxis& a : axes) {
        const int row = m_table->rowCount();
        m_table->insertRow(row);
        const QStringList cells{a.id, ConnectionChoice::familyName(a.family), a.answer, QString(), QString()};
        for (int c = 0; c < kColumns; ++c) m_table->setItem(row, c, new QTableWidgetItem(cells[c]));
    }
    if (!axes.isEmpty()) m_table->selectRow(0);
}

void AxesDock::useAxis(const QString& id) {
    if (saidBusy()) return;
    if (!ensureLine()) return;
    emit axisChosen(ConnectionChoice::onAxis(m_line, family(), id));
    setStatus(tr("Every tool now talks to axis %1 on %2.").arg(id, m_line->description()));
}

MachineProject AxesDock::scannedProject() const {
    MachineProject p;
    p.name = m_line ? m_line->description() : QString();
    if (m_kindBox->currentIndex() == 1) {
        p.port = m_where->text().trimmed();
        p.baud = m_baudBox->currentData().toInt();
    }
    for (int row = 0; row < m_table->rowCount(); ++row)
        p.axes.append(MachineProject::axisNamed(m_table->item(row, kId)->text(), family()));
    return p;
}

void AxesDock::backUpTo(const QString& dir) {
    if (m_table->rowCount() == 0) return setStatus(tr("Scan the line first: a backup reads every axis the scan found."));
    if (saidBusy()) return;
    runJob(MachineJob::Kind::Backup, scannedProject(), dir);
    m_projectDir = dir;
}

void AxesDock::compareWith(const QString& dir) {
    if (const auto project = projectOfThisLine(dir)) runJob(MachineJob::Kind::Compare, *project, dir);
}

void AxesDock::restoreFrom(const QString& dir) {
    if (const auto project = projectOfThisLine(dir)) runJob(MachineJob::Kind::Restore, *project, dir);
}

std::optional<MachineProject> AxesDock::projectOfThisLine(const QString& dir) {
    QString error;
    const auto project = machine::readMachineProject(dir, error);
    if (!project) {
        setStatus(error);
        return std::nullopt;
    }
    if (project->family() != family()) {
        setStatus(tr("%1 is a %2 machine; the line is set up for the %3.")
                      .arg(QDir::toNativeSeparators(dir), ConnectionChoice::familyName(project->family()),
                           ConnectionChoice::familyName(family())));
        return std::nullopt;
    }
    return project;
}

void AxesDock::broadcast(const QString& line) {
    if (saidBusy() || !ensureLine()) return;
    const QByteArray bytes = serialport::axisBroadcastBytes(family(), line);
    if (bytes.isEmpty())
        return setStatus(tr("The %1's line has no broadcast: send to each axis in turn.").arg(ConnectionChoice::familyName(family())));
    emit lineNeeded(m_line);
    const auto send = [this, bytes, line] {
        m_line->write(bytes);
        setStatus(tr("Broadcast \"%1\" to every axis on %2 (none answers a broadcast).").arg(line, m_line->description()));
    };
    if (m_line->isOpen()) return send();
    auto* once = new QObject(this);
    connect(m_line.get(), &serialport::Link::opened, once, [once, send] {
        delete once;
        send();
    });
    m_line->open();
}

void AxesDock::cancel() {
    if (m_job) m_job->cancel();
    if (m_scan) m_scan->cancel();
}

void AxesDock::runJob(MachineJob::Kind kind, MachineProject project, const QString& dir) {
    if (saidBusy() || !ensureLine()) return;
    emit lineNeeded(m_line);
    m_job = std::make_unique<MachineJob>(kind, *m_line, std::move(project), dir);
    connect(m_job.get(), &MachineJob::stageChanged, this, &AxesDock::setStatus);
    connect(m_job.get(), &MachineJob::progress, this, [this](int done, int total) {
        m_progress->setRange(0, total);
        m_progress->setValue(done);
    });
    connect(m_job.get(), &MachineJob::axisFinished, this, &AxesDock::showAxisResult);
    connect(m_job.get(), &MachineJob::finished, this, [this, kind, dir](bool ok, const QString& summary) {
        QTimer::singleShot(0, this, [this, kind, dir, ok, summary] {
            const QList<AxisReport> reports = m_job->reports();
            const MachineProject project = m_job->project();
            m_job.reset();
            setBusy(false);
            setStatus(summary);
            if (kind == MachineJob::Kind::Compare) {
                delete m_compare.data();
                m_compare = new MachineCompareDialog(reports, project, dir, tr("Drive"), true, this);
                m_compare->setAttribute(Qt::WA_DeleteOnClose);
                connect(m_compare, &MachineCompareDialog::sendToDrive, this,
                        [this](const QString& id, const QStringList& lines) { startErrand(id, lines, nullptr); });
                connect(m_compare, &MachineCompareDialog::downloadToDrive, this,
                        [this](const QString& id, const QString& text) { startErrand(id, {}, &text); });
                m_compare->show();
            }
            emit jobFinished(ok, summary);
        });
    });
    setBusy(true);
    m_job->start();
}

void AxesDock::showAxisResult(const AxisReport& r) {
    QString text = machine::outcomeWord(r.outcome) + QStringLiteral(": ") + r.message;
    if (!r.driveHolds.isEmpty()) text += tr(" \u2014 the drive holds %1").arg(r.driveHolds);
    for (int row = 0; row < m_table->rowCount(); ++row) {
        if (m_table->item(row, kId)->text() != r.id) continue;
        auto* item = new QTableWidgetItem(text);
        item->setToolTip(text);
        if (!r.ok()) item->setBackground(QColor(255, 226, 204));
        m_table->setItem(row, kLastJob, item);
        return;
    }
    const int row = m_table->rowCount(); // an axis of the project the scan did not list
    m_table->insertRow(row);
    const QStringList cells{r.id, ConnectionChoice::familyName(r.family), QString(), QString(), text};
    for (int c = 0; c < kColumns; ++c) m_table->setItem(row, c, new QTableWidgetItem(cells[c]));
}

void AxesDock::startErrand(const QString& id, const QStringList& lines, const QString* program) {
    if (saidBusy() || !ensureLine()) {
        if (m_compare) m_compare->drivesAnswer(id, false, statusText()); // the dialog says why nothing went
        return;
    }
    emit lineNeeded(m_line);
    auto* errand = new machine::AxisErrand(*m_line, family(), id, this);
    m_errand = errand;
    connect(errand, &machine::AxisErrand::finished, this, [this, errand, id](bool ok, const QString& message) {
        errand->deleteLater();
        m_errand = nullptr;
        setBusy(false);
        setStatus(message);
        if (m_compare) m_compare->drivesAnswer(id, ok, message);
    });
    setBusy(true);
    if (program) errand->download(*program);
    else errand->sendLines(lines);
}

// Backup: a new folder, named for the moment, inside the one chosen. Compare, Restore: a backup's folder.
void AxesDock::chooseFolderAnd(void (AxesDock::*then)(const QString&), bool existing) {
    // Beside the last backup for a new one, in it for the rest.
    const QString start = m_projectDir.isEmpty() ? QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation)
                          : existing             ? m_projectDir
                                                 : QFileInfo(m_projectDir).absolutePath();
    const QString dir = QFileDialog::getExistingDirectory(
        this, existing ? tr("A Machine Backup's Folder") : tr("Folder to Back Up Into"), start);
    if (dir.isEmpty()) return;
    if (existing) {
        if (then == &AxesDock::restoreFrom &&
            QMessageBox::question(this, tr("Restore Machine"),
                                  tr("Send every axis in %1 its program and variables? What the drives hold now is "
                                     "replaced.")
                                      .arg(QDir::toNativeSeparators(dir))) != QMessageBox::Yes)
            return;
        return (this->*then)(dir);
    }
    (this->*then)(QDir(dir).filePath(tr("backup %1").arg(QDateTime::currentDateTime().toString(QStringLiteral("yyyy-MM-dd HH.mm.ss")))));
}

// Two backups side by side, no drive: each axis of the first beside the same axis of the second.
void AxesDock::chooseBackupsToCompare() {
    const QString start = QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation);
    const QString a = QFileDialog::getExistingDirectory(this, tr("First Backup"), m_projectDir.isEmpty() ? start : m_projectDir);
    if (a.isEmpty()) return;
    const QString b = QFileDialog::getExistingDirectory(this, tr("Second Backup"), a);
    if (!b.isEmpty()) compareBackups(a, b);
}

void AxesDock::compareBackups(const QString& a, const QString& b) {
    QString error;
    const auto left = machine::readMachineProject(a, error);
    const auto right = left ? machine::readMachineProject(b, error) : std::nullopt;
    if (!left || !right) return setStatus(error);
    QList<AxisReport> reports;
    for (const machine::MachineAxis& axis : left->axes) {
        AxisReport r;
        r.id = axis.id;
        r.family = axis.family;
        const machine::MachineAxis* other = right->axis(axis.id);
        if (!other) {
            r.message = tr("axis %1 is not in %2").arg(axis.id, QDir::toNativeSeparators(b));
            reports << r;
            continue;
        }
        r.rows = machine::compareVariables(axis.family, readText(QDir(a).filePath(axis.variablesFile)),
                                           readText(QDir(b).filePath(other->variablesFile)));
        const auto lines = [](const QString& text) {
            QStringList l = QString(text).remove(QLatin1Char('\r')).split(QLatin1Char('\n'));
            if (!l.isEmpty() && l.last().isEmpty()) l.removeLast();
            return l;
        };
        r.rows += machine::compareProgram(lines(readText(QDir(a).filePath(axis.programFile))),
                                          lines(readText(QDir(b).filePath(other->programFile))));
        r.outcome = machine::differences(r.rows).isEmpty() ? AxisReport::Outcome::Done : AxisReport::Outcome::Differs;
        reports << r;
    }
    delete m_compare.data();
    m_compare = new MachineCompareDialog(reports, *left, a, QDir(b).dirName(), false, this);
    m_compare->setAttribute(Qt::WA_DeleteOnClose);
    m_compare->show();
}

} // namespace app
