// Bds5VariableRules: the BDS5 in the variable browser — "P A B C" reads up to eight at a time (well inside
// the 15-entry line), "NAME value" writes, the edit checked by VariableValidator (App. E limits in the user
// units NUM/DEN give, the programming condition, the drive's ERR named), switches shown OFF/ON.
#pragma once

#include "variables/variable_rules.h"

namespace app {

class Bds5VariableRules final : public VariableRules {
public:
    drive_core::DriveFamily family() const override { return drive_core::DriveFamily::Bds5; }
    QStringList groupOrder() const override;
    QString limitsText(const QString& name, const drive_core::catalog::Parameter& p, const Context& c) const override;
    QString displayValue(const drive_core::catalog::Parameter& p, const QString& printed) const override;
    Verdict check(const QString& name, const QString& text, const Context& c) const override;
    bool scalesLimits(const QString& name) const override;
    QStringList alsoRead(const Context& c) const override;
    int batch() const override { return 8; }
    int pollIntervalMs() const override { return 150; }
    QString readLine(const QStringList& names) const override;
    QStringList values(const QStringList& names, const serialport::LineAnswer& answer) const override;
    QStringList unreadable(const QStringList& names, const serialport::LineAnswer& answer) const override;
    QString hint() const override;
    QString fileKind() const override { return QStringLiteral(".VAR"); }
    FileText fileText(const QList<QPair<QString, QString>>& values) const override;
};

} // namespace app
