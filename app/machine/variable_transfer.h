// VariableTransfer: a drive's variables as its family's file — the BDS5's .VAR (DUMP, then NAME value lines;
// serialport/bds5_variables_*), the SC750's .PRM and the PMC-960's parameter lines (parameter_line_transfer.h)
// — read from the drive or sent to it, through the one DriveSession. What the machine's backup, compare and
// restore use for every axis. GUI thread; the session must outlive the transfer.
#pragma once

#include "parameter_line_transfer.h"

#include <QObject>
#include <QPointer>

#include <functional>

namespace app::machine {

class VariableTransfer final : public QObject {
    Q_OBJECT
public:
    explicit VariableTransfer(serialport::DriveSession& session, QObject* parent = nullptr);

    // finished() follows once, never from inside the call.
    void dump();
    void send(const QString& fileText);
    void cancel();

    // The file name suffix of the family's variable file ("var", "prm", "par").
    static QString fileSuffix(drive_core::DriveFamily family);

signals:
    void progress(int done, int total);
    void finished(const app::machine::VariableResult& result);

private:
    void bds5(bool sending, const QString& fileText);
    void lines(const std::function<void(ParameterLineTransfer&)>& begin);

    serialport::DriveSession& m_session;
    QPointer<QObject> m_running;
};

} // namespace app::machine
