// One schema for every family's parameters and errors: what a drive parameter is (name, group, type, unit,
// range, when writable, power-up value, description, manual reference) and what an error is (code, words,
// severity, what to do). Built once from the families' own catalogs (bds5_catalog.h, sc750_catalog.h,
// pmc960_catalog.h), which stay the source of truth; help, completion, the error log and compare tools read
// only this. Threading: the tables are built on first use (thread-safe statics) and never change.
#pragma once

#include "drive_core/drive.h"

#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace drive_core::catalog {

enum class ValueType {
    Integer,
    Decimal, // a float (SC750 FLOAT) or a fixed-point value (PMC-960, shown in its unit)
    Switch,  // 0 or 1 (BDS5 switches)
    Text,    // a string (SC750 STRING variables)
};

enum class Writable {
    Always,
    WhenDisabled, // the drive must be disabled (BDS5 ERR 51)
    WhenStopped,  // no commanded motion
    Never,        // a monitor value: read only
    Factory,      // factory-protected (BDS5 ERR 111)
};

struct Parameter {
    std::string_view name; // as the drive spells it, upper case; an indexed family gives its stem ("X")
    int firstIndex = 0;    // an indexed family's first and last index ("X" 1..250); 0, 0 otherwise
    int lastIndex = 0;
    int extendedLastIndex = 0;   // indices past lastIndex that exist while the switch `extendedBy` is on (BDS5
    std::string_view extendedBy; // v3 EXTDX: X251..X750); 0 and "" otherwise
    std::string_view group; // in words: "Loop gains", "Set-up parameter (PARAMS)", "Parameter table (T)"
    ValueType type = ValueType::Integer;
    std::string_view unit; // as the manual prints it; "" for none
    bool ranged = false;   // the manual (or a choice written down as `chosen`) gives minimum..maximum
    double minimum = 0;    // in `unit`
    double maximum = 0;
    Writable writable = Writable::Always;
    bool nonVolatile = false;      // kept without power (BDS5 remembered, SC750 PARAMS, PMC-960 T table)
    std::optional<double> powerUp; // in `unit`; the factory value of a non-volatile parameter
    bool chosen = false;           // range or power-up value is ServoDesk's choice: the manual gives none
    std::string_view description;  // the manual's words
    std::string_view manualLines;  // "L2046"
};

// What an error does to the drive, from least to most.
enum class ErrorLevel {
    Info,     // a status, or logged only
    Warning,  // a message; the program goes on (or the user asked for the stop)
    Error,    // the command or the program is refused or stopped
    Fault,    // the amplifier is disabled
    Firmware, // the controller's own hardware or memory
};

struct ErrorEntry {
    int code = 0;
    std::string codeText;      // as the drive shows it: "92" (BDS5 ERR 92), "F 4" (SC750 display), "#9C"
    std::string_view message;  // the drive's or the manual's words
    std::string_view severity; // the family's word for it: "Break", "Fault", "Refused"
    ErrorLevel level = ErrorLevel::Error;
    std::string_view meaning;  // the manual's explanation ("" when it gives none)
    std::string_view whatToDo; // the manual's remedy, or ours where it is silent ("" when there is nothing to do)
    std::string_view manualLines;
};

std::span<const Parameter> parameters(DriveFamily family);
std::span<const ErrorEntry> errors(DriveFamily family);
// "VMAX", "kvp", "X12" (an index within the family's range, extended ones included), "TGP"; nullptr when the
// family has no such name.
const Parameter* findParameter(DriveFamily family, std::string_view name);
const ErrorEntry* findError(DriveFamily family, int code);

// In words, for help pages and tables: "Integer", "read only", ...
std::string_view typeName(ValueType type);
std::string_view writableText(Writable writable);

} // namespace drive_core::catalog
