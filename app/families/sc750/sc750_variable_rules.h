// Sc750VariableRules: the SC750 in the variable browser — every predefined variable and set-up parameter in
// the groups of sc750_variable_groups.h; a G frame reads one ("NAME"), a P frame writes it ("NAME=VALUE"),
// checked first against the catalog's type, access and range (sc750CheckValue). G is answered while a
// program runs; P is refused then (!03 PROGRAM RUNNING), and the browser shows that answer.
#pragma once

#include "variables/variable_rules.h"

namespace app {

class Sc750VariableRules final : public VariableRules {
public:
    drive_core::DriveFamily family() const override { return drive_core::DriveFamily::Sc750; }
    QStringList groupOrder() const override;
    QString groupOf(const drive_core::catalog::Parameter& p) const override;
    QString limitsText(const QString& name, const drive_core::catalog::Parameter& p, const Context& c) const override;
    Verdict check(const QString& name, const QString& text, const Context& c) const override;
    QString readLine(const QStringList& names) const override { return names.value(0); }
    QStringList values(const QStringList& names, const serialport::LineAnswer& answer) const override;
    QString hint() const override;
    QString fileKind() const override { return QStringLiteral(".PRM"); }
    FileText fileText(const QList<QPair<QString, QString>>& values) const override;
};

} // namespace app
