// Bds5VariablesFromDrive: Variables > From Drive. Sends DUMP (L5396-5406, L9986-9992) and keeps its
// assignment lines as a .VAR set. DUMP needs the drive disabled: with ERR 51 the result says so and nothing
// is changed (chosen: the IDE never disables a drive on its own).
#pragma once

#include "bds5_transfer.h"
#include "bds5_variable_file.h"

namespace serialport {

class Bds5VariablesFromDrive final : public Bds5Transfer {
    Q_OBJECT
public:
    explicit Bds5VariablesFromDrive(Bds5Session& session, QObject* parent = nullptr);

    // After an Ok result: the variables read (result.lines holds the same as .VAR lines).
    const Bds5VariableFile& variables() const { return m_variables; }
    void cancel() override; // Esc stops the listing

protected:
    void begin() override;
    void answered(const Bds5Response& response) override;
    void lost(const QString& reason) override;

private:
    Bds5VariableFile m_variables;
};

} // namespace serialport
