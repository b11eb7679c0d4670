// ParameterLineTransfer: the SC750's and the PMC-960's parameter files over sendLine, and the vars verb that
// picks it or the BDS5's .VAR transfers.
#include "parameter_line_transfer.h"

#include "drive_core/catalog/sc750_catalog.h"
#include "serialport/pmc960_parameter_file.h"
#include "serialport/sc750_parameter_file.h"

#include <algorithm>

namespace app::machine {

namespace {
using drive_core::DriveFamily;
using serialport::Pmc960ParameterFile;
using serialport::Sc750ParameterFile;

std::vector<std::string> sc750Parameters() {
    namespace catalog = drive_core::catalog::sc750;
    std::vector<std::string> names;
    for (const catalog::VariableInfo& v : catalog::variables())
        if (v.access == catalog::Access::Parameter) names.emplace_back(v.name);
    return names;
}
} // namespace

ParameterLineTransfer::ParameterLineTransfer(serialport::DriveSession& session, QObject* parent)
    : QObject(parent), m_session(session) {
    connect(&session, &serialport::DriveSession::answered, this, &ParameterLineTransfer::onAnswered);
    connect(&session, &serialport::DriveSession::lost, this, &ParameterLineTransfer::onLost);
}

bool ParameterLineTransfer::handles(DriveFamily family) {
    return family == DriveFamily::Sc750 || family == DriveFamily::Pmc960;
}

// The reads: each SC750 set-up parameter by name (G), each backed-up PMC-960 parameter's stored value (?).
void ParameterLineTransfer::dump() {
    m_dumping = true;
    if (m_session.family() == DriveFamily::Sc750) {
        for (const std::string& name : sc750Parameters()) m_steps.append({0, QString::fromStdString(name)});
    } else {
        for (const serialport::Pmc960Parameter* p : Pmc960ParameterFile::backedUp())
            m_steps.append({0, QString::fromLatin1(serialport::displayCommand(*p, '?'))});
    }
    next();
}

void ParameterLineTransfer::send(const QString& fileText) {
    m_dumping = false;
    if (m_session.family() == DriveFamily::Sc750) {
        const Sc750ParameterFile file = Sc750ParameterFile::parse(fileText);
        if (!file.hasBlock())
            return finish(VariableResult::Status::Refused,
                          tr("The file holds no PARAMS START ... PARAMS END block: nothing was sent."));
        for (const auto& p : file.problems())
            m_result.errors.append({p.sourceLine, 0, p.message + QStringLiteral(" '%1'").arg(p.text.trimmed())});
        for (const auto& a : file.assignments()) m_steps.append({a.sourceLine, a.name + QLatin1Char('=') + a.value});
    } else {
        const Pmc960ParameterFile file = Pmc960ParameterFile::parse(fileText);
        for (const auto& p : file.problems())
            m_result.errors.append({p.sourceLine, 0, p.message + QStringLiteral(" '%1'").arg(p.text.trimmed())});
        for (const auto& l : file.lines()) m_steps.append({l.sourceLine, l.command});
    }
    if (m_steps.isEmpty())
        return finish(VariableResult::Status::Refused,
                      tr("The file holds no parameter settings: nothing was sent."));
    next();
}

void ParameterLineTransfer::next() {
    emit progress(m_at, int(m_steps.size()));
    if (m_at >= m_steps.size()) return m_dumping ? finishDump() : finishSend(QString());
    m_retried = false;
    m_pending = m_session.sendLine(m_steps[m_at].line);
}

void ParameterLineTransfer::onAnswered(quint64 id, const serialport::LineAnswer& answer) {
    if (!m_pending || id != m_pending) return;
    m_pending = 0;
    const Step& step = m_steps[m_at++];
    if (!answer.ok())
        m_result.errors.append(
            {step.sourceLine, answer.errorCode, answer.error + QStringLiteral(" '%1'").arg(step.line)});
    m_answers.append(answer.ok() ? answer.lines.join(QLatin1Char(' ')) : QString());
    next();
}

// A line that went unanswered goes once more: each reads or sets an absolute value (NAME, NAME=VALUE, TGP?,
// TGP16, SW1), so reaching the drive twice does what once does.
void ParameterLineTransfer::onLost(quint64 id, const QString& reason) {
    if (!m_pending || id != m_pending) return;
    m_pending = 0;
    if (!m_retried) {
        m_retried = true;
        m_pending = m_session.sendLine(m_steps[m_at].line);
        return;
    }
    if (m_dumping)
        return finish(VariableResult::Status::Lost, tr("Reading stopped: %1; nothing was written.").arg(reason));
    finishSend(reason);
}

// The file from what the reads gave: the SC750's block, the PMC-960's setting lines.
void ParameterLineTransfer::finishDump() {
    if (!m_result.errors.isEmpty())
        return finish(VariableResult::Status::Refused, tr("The drive refused %n of the reads; nothing was written.",
                                                              nullptr, int(m_result.errors.size())));
    if (m_session.family() == DriveFamily::Sc750) {
        QList<QPair<QString, QString>> values;
        const std::vector<std::string> names = sc750Parameters();
        for (int i = 0; i < m_answers.size(); ++i) {
            bool number = false;
            const double v = m_answers[i].toDouble(&number);
            if (!number)
                return finish(
                    VariableResult::Status::Refused,
                    tr("%1 read as \"%2\", not a number; nothing was written.").arg(m_steps[i].line, m_answers[i]));
            values.append({m_steps[i].line, Sc750ParameterFile::formatValue(names[std::size_t(i)], v)});
        }
        m_result.text =
            Sc750ParameterFile::toText({tr("SC750 set-up parameters, read from the drive by ServoDesk")}, values);
    } else {
        QStringList comments{tr("PMC-960 parameter table read from the drive by ServoDesk")}, lines;
        const auto parameters = Pmc960ParameterFile::backedUp();
        for (int i = 0; i < m_answers.size(); ++i) {
            const serialport::Pmc960Parameter& p = *parameters[std::size_t(i)];
            const QString value = serialport::valueFromDisplay(p, m_answers[i]);
            const QString line = Pmc960ParameterFile::settingLine(p, value);
            if (!line.isEmpty())
                lines << line;
            else if (value.isEmpty()) // a label never set: TL has no way to clear one
                comments << tr("%1 not set").arg(serialport::parameterName(p));
            else
                return finish(VariableResult::Status::Refused,
                              tr("%1 answered \"%2\", which the table cannot write back; nothing was written.")
                                  .arg(m_steps[i].line, m_answers[i]));
        }
        m_result.text = Pmc960ParameterFile::toText(comments, lines);
    }
    finish(VariableResult::Status::Done,
           tr("Read %n parameter(s) from the drive.", nullptr, int(m_answers.size())));
}

void ParameterLineTransfer::finishSend(const QString& stoppedBecause) {
    int refused = 0;
    for (const auto& e : m_result.errors) refused += e.code != 0 ? 1 : 0;
    const int problems = int(m_result.errors.size()) - refused;
    const int total = int(m_steps.size());
    QString text = stoppedBecause.isEmpty()
                       ? tr("Sent %n parameter line(s)", nullptr, total)
                       : tr("Sending stopped (%1) after %2 of %3 parameter lines; the drive keeps the ones sent")
                             .arg(stoppedBecause)
                             .arg(m_at)
                             .arg(total);
    if (refused > 0) text += tr("; the drive refused %n of them", nullptr, refused);
    if (problems > 0) text += tr("; %n line(s) of the file were not sent", nullptr, problems);
    const auto status = !stoppedBecause.isEmpty()   ? VariableResult::Status::Lost
                        : m_result.errors.isEmpty() ? VariableResult::Status::Done
                                                    : VariableResult::Status::Refused;
    finish(status, text + QLatin1Char('.'));
}

void ParameterLineTransfer::finish(VariableResult::Status status, const QString& summary) {
    // The file's problems were found before anything went out, the refusals after: in file order together.
    std::stable_sort(m_result.errors.begin(), m_result.errors.end(),
                     [](const auto& a, const auto& b) { return a.sourceLine < b.sourceLine; });
    m_result.status = status;
    m_result.summary = summary;
    emit finished(m_result);
}

} // namespace app::machine
