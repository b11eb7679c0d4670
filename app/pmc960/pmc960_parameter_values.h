// How the parameter table reads and writes one catalog parameter on the PMC-960: the display command for
// its stored (?) and in-use (!) value, the value inside the controller's reply ("P-16" -> "16", "F0 R0" ->
// "0"), and a typed value checked against the catalog's limits before it goes out. Pure; any thread.
#pragma once

#include "drive_core/catalog/pmc960_catalog.h"

#include <QByteArray>
#include <QString>

#include <optional>

namespace app {

using Pmc960Parameter = drive_core::catalog::pmc960::ParameterInfo;

QString parameterName(const Pmc960Parameter& p);
// "TGP?" / "SL!"; empty when the controller has no display for it (D).
QByteArray displayCommand(const Pmc960Parameter& p, char kind);
// The parameter's value in a display reply's value text.
QString valueFromDisplay(const Pmc960Parameter& p, const QString& reply);
// "0 - 255", "00 - FF", "! - Z", "0:0001 - 65535:9999".
QString rangeText(const Pmc960Parameter& p);

struct ParameterWrite {
    QByteArray command;     // "TGP20\r", "SLF-4000\r"
    bool needsWriteEnable;  // T table: SW1 before, SW0 after (#D3 otherwise)
    QString error;          // why the value is refused; command is empty then
};
// Checks text against the parameter's base and limits and builds the command that sets it.
ParameterWrite parameterWrite(const Pmc960Parameter& p, const QString& text);

} // namespace app
