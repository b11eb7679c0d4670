// Bds5VariablesToDrive: assignments, one per prompt, errors per line.
#include "bds5_variables_to_drive.h"

namespace serialport {

Bds5VariablesToDrive::Bds5VariablesToDrive(Bds5Session& session, const QString& varText, QObject* parent)
    : Bds5Transfer(session, parent), m_variables(Bds5VariableFile::parse(varText)) {}

void Bds5VariablesToDrive::begin() {
    m_result = {};
    for (const Bds5VariableProblem& p : m_variables.problems())
        m_result.errors.append({p.sourceLine, 0, p.text, Bds5ErrorLine{0, 0, QString(), p.message}});
    if (!sessionAtInteractivePrompt()) {
        m_result.status = Bds5TransferResult::Status::Refused;
        m_result.summary = tr("The drive is not at its --> prompt (mode: %1): no variables were sent.")
                               .arg(session() ? modeName(session()->mode()) : tr("not connected"));
        return finish(m_result);
    }
    if (m_variables.assignments().isEmpty()) {
        m_result.status = Bds5TransferResult::Status::Refused;
        m_result.summary = tr("The file holds no assignments (NAME value): nothing was sent.");
        return finish(m_result);
    }
    emit stageChanged(tr("Sending the variables"));
    emit progress(0, int(m_variables.assignments().size()));
    sendNext();
}

void Bds5VariablesToDrive::sendNext() {
    send(m_variables.assignments().at(m_sent).instruction());
}

void Bds5VariablesToDrive::answered(const Bds5Response& response) {
    const Bds5Assignment& a = m_variables.assignments().at(m_sent);
    for (const Bds5ErrorLine& e : response.errors)
        m_result.errors.append({a.sourceLine, 0, a.instruction(), e});
    ++m_sent;
    const int total = int(m_variables.assignments().size());
    emit progress(m_sent, total);
    if (modeOfPrompt(response.prompt) != Bds5Mode::Interactive)
        return finishSent(Bds5TransferResult::Status::Failed,
                          tr("the drive left its --> prompt (it answered with \"%1\")").arg(response.prompt));
    if (isCancelling()) return finishSent(Bds5TransferResult::Status::Cancelled, tr("cancelled"));
    if (m_sent == total) return finishSent(Bds5TransferResult::Status::Ok, QString());
    sendNext();
}

void Bds5VariablesToDrive::finishSent(Bds5TransferResult::Status status, const QString& why) {
    const int total = int(m_variables.assignments().size());
    m_result.status = status;
    m_result.linesDone = m_sent;
    int refused = 0;
    for (const Bds5LineError& e : m_result.errors)
        refused += e.error.code != 0 ? 1 : 0;
    const int problems = int(m_result.errors.size()) - refused;
    QString text =
        status == Bds5TransferResult::Status::Ok
            ? tr("Sent %n variable line(s)", nullptr, total)
            : tr("Sending stopped (%1) after %2 of %3 variable lines; the drive keeps the ones sent")
                  .arg(why)
                  .arg(m_sent)
                  .arg(total);
    if (refused > 0) {
        const Bds5LineError* first = nullptr;
        for (const Bds5LineError& e : m_result.errors)
            if (e.error.code != 0 && !first) first = &e;
        text += tr("; the drive refused %n of them (first at line %1: %2)", nullptr, refused)
                    .arg(first->sourceLine)
                    .arg(describeError(first->error));
    }
    if (problems > 0) text += tr("; %n line(s) were not assignments and were not sent", nullptr, problems);
    m_result.summary = text + QLatin1Char('.');
    finish(m_result);
}

void Bds5VariablesToDrive::lost(const QString& reason) {
    finishSent(Bds5TransferResult::Status::Failed, reason);
}

} // namespace serialport
