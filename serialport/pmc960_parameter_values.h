// How one catalog parameter of the PMC-960 is read and written: the display command for its stored (?) and
// in-use (!) value, the value inside the controller's reply ("P-16" -> "16", "F0 R0" -> "0"), and a typed
// value checked against the catalog's limits before it goes out. Shared by the IDE's parameter table
// (app/families/pmc960/pmc960_parameter_dock) and the parameter file (pmc960_parameter_file.h). Pure; any thread.
#pragma once

#include "drive_core/catalog/pmc960_catalog.h"

#include <QByteArray>
#include <QString>

#include <optional>

namespace serialport {

using Pmc960Parameter = drive_core::catalog::pmc960::ParameterInfo;

QString parameterName(const Pmc960Parameter& p);
// "TGP?" / "SL!"; empty when the controller has no display for it (D).
QByteArray displayCommand(const Pmc960Parameter& p, char kind);
// The parameter's value in a display reply's value text.
QString valueFromDisplay(const Pmc960Parameter& p, const QString& reply);
// "0 - 255", "00 - FF", "! - Z", "0:0001 - 65535:9999".
QString rangeText(const Pmc960Parameter& p);
// Parameters the host leaves alone: writing them would cut the link off (baud, echo and number format, the
// prompt's axis ID), start motion (G, J, D) or fight the SW1/SW0 around T-table writes; and D, which has no
// display to read it back.
bool isReadOnlyFromHost(const Pmc960Parameter& p);

struct ParameterWrite {
    QByteArray command;     // "TGP20\r", "SLF-4000\r"
    bool needsWriteEnable;  // T table: SW1 before, SW0 after (#D3 otherwise)
    QString error;          // why the value is refused; command is empty then
};
// Checks text against the parameter's base and limits and builds the command that sets it.
ParameterWrite parameterWrite(const Pmc960Parameter& p, const QString& text);

} // namespace serialport
