// Bds5VariablesToDrive: Variables > Send to Drive, and Reset to STANDARD.VAR. One "NAME value" per --> prompt
// (L9994-10009); comment lines are never sent. Every line the drive refuses (ERR 51, 83, 111, ...) is kept
// with its file line, and sending goes on (chosen: one bad value should not leave the rest of the set
// unsent). Lines that are not assignments are reported at their line and not sent.
#pragma once

#include "bds5_transfer.h"
#include "bds5_variable_file.h"

namespace serialport {

class Bds5VariablesToDrive final : public Bds5Transfer {
    Q_OBJECT
public:
    Bds5VariablesToDrive(Bds5Session& session, const QString& varText, QObject* parent = nullptr);

    const Bds5VariableFile& variables() const { return m_variables; }

protected:
    void begin() override;
    void answered(const Bds5Response& response) override;
    void lost(const QString& reason) override;

private:
    void sendNext();
    void finishSent(Bds5TransferResult::Status status, const QString& why);

    Bds5VariableFile m_variables;
    int m_sent = 0;
    Bds5TransferResult m_result;
};

} // namespace serialport
