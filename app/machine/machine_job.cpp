// MachineJob: select, read or send, check, release; axis after axis.
#include "machine_job.h"

#include "variable_transfer.h"

#include "serialport/axis_link.h"
#include "serialport/drive_timeout.h"

#include <QDateTime>
#include <QDir>
#include <QFile>
#include <QSaveFile>
#include <QTimer>

namespace app::machine {

namespace {
constexpr int kSelectTimeoutMs = 5000; // a selected axis answers (its prompt, its identification) within this
constexpr int kStepsPerAxis = 4;       // select, program, variables, check

QStringList linesOf(const QString& text) {
    QString t = text;
    t.remove(QLatin1Char('\r'));
    QStringList lines = t.split(QLatin1Char('\n'));
    if (!lines.isEmpty() && lines.last().isEmpty()) lines.removeLast();
    return lines;
}
} // namespace

QString outcomeWord(AxisReport::Outcome outcome) {
    switch (outcome) {
    case AxisReport::Outcome::Done: return QStringLiteral("done");
    case AxisReport::Outcome::Differs: return QStringLiteral("differs");
    case AxisReport::Outcome::Failed: return QStringLiteral("failed");
    case AxisReport::Outcome::Cancelled: return QStringLiteral("cancelled");
    }
    return {};
}

MachineJob::MachineJob(Kind kind, serialport::Link& line, MachineProject project, QString dir, QObject* parent)
    : QObject(parent), m_kind(kind), m_line(line), m_project(std::move(project)), m_dir(std::move(dir)) {
    connect(&m_line, &serialport::Link::bytesReceived, this, [this](const QByteArray& b) {
        if (m_axisLink) m_received += b.size();
    });
}

MachineJob::~MachineJob() {
    releaseAxis();
}

void MachineJob::start() {
    QTimer::singleShot(0, this, &MachineJob::nextAxis);
}

void MachineJob::cancel() {
    if (m_finished || m_cancelled) return;
    m_cancelled = true;
    if (m_variables) m_variables->cancel();
    if (m_session && (m_step == Step::Program)) m_session->cancelTransfer();
    if (m_step == Step::Select) endAxis(AxisReport::Outcome::Cancelled, tr("cancelled before the axis answered"));
}

void MachineJob::stage(const QString& what) {
    emit stageChanged(tr("Axis %1 (%2 of %3): %4").arg(m_report.id).arg(m_at + 1).arg(m_project.axes.size()).arg(what));
    emit progress(m_at * kStepsPerAxis + int(m_step), int(m_project.axes.size()) * kStepsPerAxis);
}

// The session goes before its link, and the link releases the axis before the next is selected.
void MachineJob::releaseAxis() {
    m_wait.reset();
    m_variables.reset();
    m_session.reset();
    if (m_axisLink) {
        m_axisLink->close();
        m_sent += m_axisLink->bytesWritten();
    }
    m_axisLink.reset();
}

void MachineJob::nextAxis() {
    releaseAxis();
    if (++m_at >= m_project.axes.size() || m_cancelled) return finishJob();
    beginAxis();
}

void MachineJob::beginAxis() {
    const MachineAxis& axis = m_project.axes[m_at];
    m_report = AxisReport{};
    m_report.id = axis.id;
    m_report.family = axis.family;
    m_step = Step::Select;
    m_fileProgram.clear();
    m_fileVariables.clear();
    if (m_kind != Kind::Backup) {
        QString error;
        if ((!axis.programFile.isEmpty() && !readFile(axis.programFile, m_fileProgram, error)) ||
            !readFile(axis.variablesFile, m_fileVariables, error))
            return endAxis(AxisReport::Outcome::Failed, error);
    }
    stage(tr("selecting it"));
    m_axisLink = std::make_unique<serialport::AxisLink>(m_line, axis.family, axis.id);
    m_session = serialport::makeDriveSession(axis.family, *m_axisLink);
    m_wait = std::make_unique<serialport::DriveTimeout>(m_line);
    connect(m_wait.get(), &serialport::DriveTimeout::timeout, this, [this] {
        endAxis(AxisReport::Outcome::Failed,
                tr("no answer from axis %1 within %2 s (is it on the line, with this ID?); nothing was changed")
                    .arg(m_report.id)
                    .arg(kSelectTimeoutMs / 1000));
    });
    connect(m_session.get(), &serialport::DriveSession::readyChanged, this, [this](bool ready) {
        if (ready && m_step == Step::Select) onReady();
    });
    connect(m_session.get(), &serialport::DriveSession::linkFailed, this, [this](const QString& why) {
        if (m_step != Step::Next) endAxis(AxisReport::Outcome::Failed, why);
    });
    connect(m_session.get(), &serialport::DriveSession::transferFinished, this, &MachineJob::onTransfer);
    m_wait->start(kSelectTimeoutMs);
    m_axisLink->open();
}

void MachineJob::onReady() {
    m_wait->stop();
    if (m_cancelled) return endAxis(AxisReport::Outcome::Cancelled, tr("cancelled; nothing was changed"));
    step(Step::Program);
}

void MachineJob::step(Step s) {
    m_step = s;
    switch (s) {
    case Step::Program:
        if (m_kind == Kind::Restore) {
            if (m_fileProgram.trimmed().isEmpty()) { // the drive held none when backed up: nothing to send
                m_report.driveHolds = tr("its own program (the project keeps none)");
                return step(Step::Variables);
            }
            stage(tr("sending the program"));
            return m_session->download(m_fileProgram);
        }
        stage(tr("reading the program"));
        return m_session->upload();
    case Step::Variables:
    case Step::Check:
        stage(s == Step::Check ? tr("reading the variables back")
                               : m_kind == Kind::Restore ? tr("sending the variables") : tr("reading the variables"));
        m_variables = std::make_unique<VariableTransfer>(*m_session);
        connect(m_variables.get(), &VariableTransfer::finished, this, &MachineJob::onVariables);
        if (m_kind == Kind::Restore && s == Step::Variables)
            m_variables->send(withoutVariables(m_report.family, m_fileVariables, linkSettings(m_report.family)));
        else
            m_variables->dump();
        return;
    case Step::Select:
    case Step::Next: return;
    }
}

void MachineJob::onTransfer(const serialport::TransferResult& r) {
    if (m_step != Step::Program) return;
    if (m_kind == Kind::Restore) m_report.driveHolds = r.driveHolds;
    if (r.status == serialport::TransferResult::Status::Cancelled)
        return endAxis(AxisReport::Outcome::Cancelled, r.message);
    if (!r.ok()) {
        QString why = r.message;
        if (!r.errors.isEmpty())
            why += tr(" (%1 line %2: %3)").arg(m_project.axes[m_at].programFile).arg(r.errors.first().sourceLine).arg(r.errors.first().text);
        return endAxis(AxisReport::Outcome::Failed, why);
    }
    if (m_kind != Kind::Restore) m_report.program = r.lines;
    if (m_cancelled) return endAxis(AxisReport::Outcome::Cancelled, tr("cancelled after the program"));
    step(Step::Variables);
}

void MachineJob::onVariables(const VariableResult& r) {
    const bool sending = m_kind == Kind::Restore && m_step == Step::Variables;
    if (r.status != VariableResult::Status::Done) {
        QString why = r.summary;
        if (!r.errors.isEmpty())
            why += tr(" (%1 line %2: %3)").arg(m_project.axes[m_at].variablesFile).arg(r.errors.first().sourceLine).arg(r.errors.first().text);
        if (sending) m_report.driveHolds += tr("; its variables are only partly the file's");
        return endAxis(m_cancelled ? AxisReport::Outcome::Cancelled : AxisReport::Outcome::Failed, why);
    }
    if (sending) {
        if (m_cancelled) return endAxis(AxisReport::Outcome::Cancelled, tr("cancelled before the check"));
        return QTimer::singleShot(0, this, [this] { step(Step::Check); });
    }
    m_report.variables = r.text;
    switch (m_kind) {
    case Kind::Backup:
        return endAxis(AxisReport::Outcome::Done,
                       m_report.program.isEmpty() ? tr("read its variables (it holds no program)")
                                                  : tr("read %1 and its variables")
                                                        .arg(counted(m_report.program.size(), tr("program line"), tr("program lines"))));
    case Kind::Compare: {
        m_report.rows = compareVariables(m_report.family, m_fileVariables, m_report.variables);
        if (!m_project.axes[m_at].programFile.isEmpty())
            m_report.rows += compareProgram(linesOf(m_fileProgram), m_report.program);
        const qsizetype n = differences(m_report.rows).size();
        return endAxis(n == 0 ? AxisReport::Outcome::Done : AxisReport::Outcome::Differs,
                       n == 0 ? tr("the drive matches the files") : tr("%1 from the files").arg(counted(n, tr("difference"), tr("differences"))));
    }
    case Kind::Restore: {
        m_report.rows = compareVariables(m_report.family, m_fileVariables, m_report.variables);
        const qsizetype n = differences(m_report.rows).size();
        m_report.driveHolds += n == 0 ? tr("; the file's variables, read back the same")
                                      : tr("; variables read back with %1 from the file").arg(counted(n, tr("difference"), tr("differences")));
        return endAxis(n == 0 ? AxisReport::Outcome::Done : AxisReport::Outcome::Differs,
                       n == 0 ? tr("restored and checked") : tr("restored, but %1 read back differently").arg(counted(n, tr("variable"), tr("variables"))));
    }
    }
}

void MachineJob::endAxis(AxisReport::Outcome outcome, const QString& message) {
    if (m_step == Step::Next) return;
    m_step = Step::Next;
    if (m_wait) m_wait->stop();
    m_report.outcome = outcome;
    m_report.message = message;
    if (m_kind == Kind::Restore && m_report.driveHolds.isEmpty()) m_report.driveHolds = tr("what it held before");
    m_reports.append(m_report);
    emit axisFinished(m_report);
    QTimer::singleShot(0, this, &MachineJob::nextAxis); // not from inside the session's own signal
}

void MachineJob::finishJob() {
    if (m_finished) return;
    m_finished = true;
    emit progress(1, 1);
    int good = 0;
    for (const AxisReport& r : m_reports) good += r.ok() ? 1 : 0;
    QString error;
    if (m_kind == Kind::Backup && good > 0 && !writeBackup(error)) {
        for (AxisReport& r : m_reports)
            if (r.ok()) r.outcome = AxisReport::Outcome::Failed, r.message = error;
        return emit finished(false, tr("The backup could not be written: %1").arg(error));
    }
    const int all = int(m_project.axes.size());
    const QString verb = m_kind == Kind::Backup ? tr("backed up") : m_kind == Kind::Compare ? tr("match their files") : tr("restored and checked");
    QString summary = tr("%1 of %2 axes %3").arg(good).arg(all).arg(verb);
    if (m_cancelled) summary += tr("; cancelled");
    if (m_kind == Kind::Backup && good > 0) summary += tr(" into %1").arg(QDir::toNativeSeparators(m_dir));
    emit finished(good == all && !m_cancelled, summary + QLatin1Char('.'));
}

bool MachineJob::readFile(const QString& name, QString& text, QString& error) const {
    QFile f(QDir(m_dir).filePath(name));
    if (!f.open(QIODevice::ReadOnly)) {
        error = tr("%1: %2; the axis was not touched").arg(f.fileName(), f.errorString());
        return false;
    }
    const QByteArray bytes = f.readAll();
    if (bytes.contains('\0')) {
        error = tr("%1 is not a text file; the axis was not touched").arg(f.fileName());
        return false;
    }
    text = QString::fromLatin1(bytes);
    return true;
}

// Each axis's files, then the project naming the axes read (an axis that failed is left out, with why).
bool MachineJob::writeBackup(QString& error) {
    if (!QDir().mkpath(m_dir)) {
        error = tr("cannot create the folder %1").arg(m_dir);
        return false;
    }
    const auto write = [this, &error](const QString& name, const QString& text) {
        QSaveFile f(QDir(m_dir).filePath(name));
        if (f.open(QIODevice::WriteOnly) && f.write(text.toLatin1()) >= 0 && f.commit()) return true;
        error = tr("%1: %2").arg(f.fileName(), f.errorString());
        return false;
    };
    MachineProject backup = m_project;
    backup.axes.clear();
    backup.backedUp = QDateTime::currentDateTime().toString(Qt::ISODate);
    QString notes;
    for (const AxisReport& r : m_reports) {
        if (!r.ok()) {
            notes += QStringLiteral("# axis %1 was not backed up: %2\n").arg(r.id, r.message);
            continue;
        }
        const MachineAxis axis = MachineProject::axisNamed(r.id, r.family);
        const QString program = r.program.isEmpty() ? QString() : r.program.join(QLatin1Char('\n')) + QLatin1Char('\n');
        if (!write(axis.programFile, program) || !write(axis.variablesFile, r.variables)) return false;
        backup.axes.append(axis);
    }
    return write(MachineProject::fileName(), backup.toText() + notes);
}

} // namespace app::machine
