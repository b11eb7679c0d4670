// Pmc960VariableRules: the PMC-960 in the variable browser — its parameter table (motion buffer, system
// registers, the non-volatile T table), each with its stored value ("TGP?") and the value in use ("TGP!");
// a change is checked against the catalog's limits and number base (serialport/pmc960_parameter_values.h)
// and written with SW1/SW0 around a T-table write. Read when asked (a connection, Refresh, after a write),
// not over and over: each read is a command on the one queue the user's own commands share.
#pragma once

#include "variables/variable_rules.h"

namespace app {

class Pmc960VariableRules final : public VariableRules {
public:
    drive_core::DriveFamily family() const override { return drive_core::DriveFamily::Pmc960; }
    QString limitsText(const QString& name, const drive_core::catalog::Parameter& p, const Context& c) const override;
    bool editable(const QString& name, const drive_core::catalog::Parameter& p) const override;
    Verdict check(const QString& name, const QString& text, const Context& c) const override;
    QString readLine(const QStringList& names) const override;
    QStringList values(const QStringList& names, const serialport::LineAnswer& answer) const override;
    QString hint() const override;
    QString valueTitle() const override { return tr("Stored (?)"); }
    QString secondTitle() const override { return tr("In use (!)"); }
    QString secondReadLine(const QString& name) const override;
    bool liveByDefault() const override { return false; }
    QString fileKind() const override { return tr("MPL lines"); }
    FileText fileText(const QList<QPair<QString, QString>>& values) const override;
};

} // namespace app
