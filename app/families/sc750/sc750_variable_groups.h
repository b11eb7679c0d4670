// The SC750 variable browser's widget-free rules: which group a predefined variable is shown in (the
// digest's §5 sections: set-up parameters, motion profile, position/velocity/current, status, gearing and
// encoder, registration, WHEN latches, I/O, interrupt enables, timers) and whether a typed value may be
// sent (the catalog's type, access and range; ranges the manual does not give are the catalog's choice).
#pragma once

#include "drive_core/catalog/sc750_catalog.h"

#include <QString>
#include <QStringList>

#include <optional>

namespace app {

// The groups in display order.
QStringList sc750VariableGroups();
QString sc750VariableGroup(const drive_core::catalog::sc750::VariableInfo& variable);
// "0 – 1000", "-134217727 – 134217727", "" for strings.
QString sc750RangeText(const drive_core::catalog::sc750::VariableInfo& variable);
// Why text cannot be written to the variable ("KVI must lie within 0 – 1000"), or nullopt when it can.
std::optional<QString> sc750CheckValue(const drive_core::catalog::sc750::VariableInfo& variable, const QString& text);

} // namespace app
