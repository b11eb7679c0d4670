// VariableTransfer: the BDS5's .VAR transfers or the parameter lines of the others, one result.
#include "variable_transfer.h"

#include "serialport/bds5_drive_session.h"
#include "serialport/bds5_variables_from_drive.h"
#include "serialport/bds5_variables_to_drive.h"

#include <QTimer>

namespace app::machine {

using drive_core::DriveFamily;

VariableTransfer::VariableTransfer(serialport::DriveSession& session, QObject* parent)
    : QObject(parent), m_session(session) {}

QString VariableTransfer::fileSuffix(DriveFamily family) {
    switch (family) {
    case DriveFamily::Bds5: return QStringLiteral("var");
    case DriveFamily::Sc750: return QStringLiteral("prm");
    case DriveFamily::Pmc960: return QStringLiteral("par"); // chosen: the manual names no parameter file
    }
    return QStringLiteral("txt");
}

void VariableTransfer::dump() {
    if (m_session.family() == DriveFamily::Bds5) return bds5(false, QString());
    lines([](ParameterLineTransfer& t) { t.dump(); });
}

void VariableTransfer::send(const QString& fileText) {
    if (m_session.family() == DriveFamily::Bds5) return bds5(true, fileText);
    lines([fileText](ParameterLineTransfer& t) { t.send(fileText); });
}

// The other families' files, line by line; begun on the next turn of the loop, as the BDS5's transfers are.
void VariableTransfer::lines(const std::function<void(ParameterLineTransfer&)>& begin) {
    auto* t = new ParameterLineTransfer(m_session, this);
    m_running = t;
    connect(t, &ParameterLineTransfer::progress, this, &VariableTransfer::progress);
    connect(t, &ParameterLineTransfer::finished, this, [this, t](const VariableResult& r) {
        t->deleteLater();
        emit finished(r);
    });
    QTimer::singleShot(0, t, [t, begin] { begin(*t); });
}

void VariableTransfer::cancel() {
    if (auto* bds5 = qobject_cast<serialport::Bds5Transfer*>(m_running.data())) bds5->cancel();
}

// DUMP needs the drive disabled (ERR 51): the result says so and nothing changes (bds5_variables_from_drive.h).
void VariableTransfer::bds5(bool sending, const QString& fileText) {
    auto& session = static_cast<serialport::Bds5DriveSession&>(m_session).bds5();
    serialport::Bds5Transfer* t = sending
                                      ? static_cast<serialport::Bds5Transfer*>(
                                            new serialport::Bds5VariablesToDrive(session, fileText, this))
                                      : new serialport::Bds5VariablesFromDrive(session, this);
    m_running = t;
    connect(t, &serialport::Bds5Transfer::progress, this, &VariableTransfer::progress);
    connect(t, &serialport::Bds5Transfer::finished, this, [this, t, sending](const serialport::Bds5TransferResult& r) {
        t->deleteLater();
        VariableResult result;
        result.summary = r.summary;
        for (const auto& e : r.errors)
            result.errors.append({e.sourceLine, e.error.code,
                                  QStringLiteral("ERR %1 '%2' %3").arg(e.error.code).arg(e.error.entry, e.error.message)});
        using S = serialport::Bds5TransferResult::Status;
        if (r.status == S::Failed || r.status == S::Cancelled)
            result.status = VariableResult::Status::Lost;
        else if (!r.ok() || !r.errors.isEmpty())
            result.status = VariableResult::Status::Refused;
        else
            result.status = VariableResult::Status::Done;
        if (!sending && r.ok()) result.text = r.lines.join(QLatin1Char('\n')) + QLatin1Char('\n');
        emit finished(result);
    });
    t->start();
}

} // namespace app::machine
