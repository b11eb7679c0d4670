// The common schema filled from each family's catalog: one adapter per family, run once.
#include "drive_catalog.h"

#include "bds5_catalog.h"
#include "pmc960_catalog.h"
#include "sc750_catalog.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdio>
#include <vector>

namespace drive_core::catalog {

namespace {

std::string_view bds5Group(bds5::VariableGroup group) {
    using G = bds5::VariableGroup;
    switch (group) {
    case G::Position: return "Position";
    case G::Velocity: return "Velocity";
    case G::Current: return "Current";
    case G::LoopGains: return "Loop gains";
    case G::Limits: return "Limits";
    case G::Units: return "Units";
    case G::Io: return "Inputs and outputs";
    case G::Switches: return "Switches";
    case G::Communication: return "Communication";
    case G::Timers: return "Timers";
    case G::Record: return "Record";
    case G::User: return "User variables";
    case G::Internal: return "Internal";
    }
    return "Internal";
}

Writable bds5Writable(bds5::WriteCondition write) {
    using W = bds5::WriteCondition;
    switch (write) {
    case W::Always: return Writable::Always;
    case W::Disabled: return Writable::WhenDisabled;
    case W::NoMotion: return Writable::WhenStopped;
    case W::Never: return Writable::Never;
    case W::Factory: return Writable::Factory;
    }
    return Writable::Always;
}

std::vector<Parameter> bds5Parameters() {
    std::vector<Parameter> out;
    for (const bds5::VariableInfo& v : bds5::variables()) {
        Parameter p;
        p.name = v.name;
        p.firstIndex = v.firstIndex;
        p.lastIndex = v.lastIndex;
        p.extendedLastIndex = v.extendedLastIndex;
        p.extendedBy = v.extendedBy;
        p.group = bds5Group(v.group);
        p.type = v.isSwitch || v.limits == bds5::LimitClass::Switch ? ValueType::Switch : ValueType::Integer;
        p.unit = v.units;
        p.ranged = v.limits != bds5::LimitClass::None;
        p.minimum = double(bds5::minimumOf(v));
        p.maximum = double(bds5::maximumOf(v));
        p.writable = bds5Writable(v.write);
        p.nonVolatile = v.persistence == bds5::Persistence::Remembered;
        if (v.write != bds5::WriteCondition::Never) p.powerUp = double(v.powerUpValue);
        p.description = v.description;
        p.manualLines = v.manualLines;
        out.push_back(p);
    }
    return out;
}

std::vector<Parameter> sc750Parameters() {
    std::vector<Parameter> out;
    for (const sc750::VariableInfo& v : sc750::variables()) {
        Parameter p;
        p.name = v.name;
        p.group = v.access == sc750::Access::Parameter ? "Set-up parameters (PARAMS)" : "Variables";
        p.type = v.type == sc750::ValueType::String  ? ValueType::Text
                 : v.type == sc750::ValueType::Float ? ValueType::Decimal
                                                     : ValueType::Integer;
        p.unit = v.units;
        p.ranged = p.type != ValueType::Text;
        p.minimum = v.minimum;
        p.maximum = v.maximum;
        p.writable = v.access == sc750::Access::ReadOnly ? Writable::Never : Writable::Always;
        p.nonVolatile = v.access == sc750::Access::Parameter;
        if (p.type != ValueType::Text) p.powerUp = v.defaultValue;
        p.chosen = v.chosen;
        p.description = v.description;
        p.manualLines = v.manualLines;
        out.push_back(p);
    }
    return out;
}

std::vector<Parameter> pmc960Parameters() {
    std::vector<Parameter> out;
    for (const pmc960::ParameterInfo& v : pmc960::parameters()) {
        const bool fixed = v.base == pmc960::NumberBase::FixedPoint; // stored x 1000
        const double scale = fixed ? 1e-3 : 1.0;
        Parameter p;
        p.name = v.name;
        p.group = v.nonVolatile ? "Parameter table (T)" : "System registers (S)";
        p.type = fixed ? ValueType::Decimal : ValueType::Integer;
        p.ranged = true;
        p.minimum = double(v.minimum) * scale;
        p.maximum = double(v.maximum) * scale;
        p.nonVolatile = v.nonVolatile;
        p.powerUp = double(v.factory) * scale;
        p.description = v.description;
        p.manualLines = v.manualLines;
        out.push_back(p);
    }
    return out;
}

ErrorEntry bds5Error(const bds5::ErrorInfo& e) {
    ErrorEntry out;
    out.code = e.code;
    out.codeText = std::to_string(e.code);
    out.message = e.message;
    out.meaning = e.meaning;
    out.whatToDo = e.remedy;
    out.manualLines = e.manualLines;
    using S = bds5::Severity;
    switch (e.severity) {
    case S::HistoryOnly: out.severity = "Logged", out.level = ErrorLevel::Info; break;
    case S::Warning: out.severity = "Warning", out.level = ErrorLevel::Warning; break;
    case S::Break: out.severity = "Break", out.level = ErrorLevel::Error; break;
    case S::Disable: out.severity = "Disable", out.level = ErrorLevel::Fault; break;
    case S::Firmware: out.severity = "Firmware", out.level = ErrorLevel::Firmware; break;
    }
    return out;
}

// Memory and processor faults are the hardware's, not the program's or the machine's.
ErrorEntry sc750Error(const sc750::FaultInfo& f) {
    ErrorEntry out;
    out.code = f.code;
    out.codeText = std::string(f.display);
    out.message = f.sc752.empty() ? f.sc754 : f.sc752;
    out.meaning = f.sc754 != f.sc752 ? f.sc754 : std::string_view();
    out.whatToDo = sc750::faultRemedy(f.code);
    out.manualLines = f.manualLines;
    if (f.code == sc750::kFaultNone || f.code == sc750::kFaultEnabled) {
        out.severity = "Status", out.level = ErrorLevel::Info;
    } else if (f.code == 14 || f.code == sc750::kFaultProgramMemory || f.code == 243) {
        out.severity = "Fault", out.level = ErrorLevel::Firmware;
    } else if (f.code == sc750::kFaultRunTime || f.code == sc750::kFaultIncompatible) {
        out.severity = "Fault", out.level = ErrorLevel::Error;
    } else {
        out.severity = "Fault", out.level = ErrorLevel::Fault;
    }
    return out;
}

// ESC and BREAK codes are the user's (or the machine's) own stop, not a mistake in the command.
bool isAbort(std::string_view message) {
    return message.find("ESC") != std::string_view::npos || message.find("Break") != std::string_view::npos ||
           message.find("BREAK") != std::string_view::npos;
}

ErrorEntry pmc960Error(const pmc960::ErrorInfo& e) {
    ErrorEntry out;
    out.code = e.code;
    char hex[8];
    std::snprintf(hex, sizeof hex, "#%02X", unsigned(e.code));
    out.codeText = hex;
    out.message = e.message;
    out.meaning = e.meaning;
    out.whatToDo = pmc960::errorRemedy(e.code);
    out.manualLines = e.manualLines;
    // Every error ends the command and the mode it was in (L2288); the word says why.
    if (e.group == pmc960::ErrorGroup::SystemStatus) {
        out.severity = "System", out.level = ErrorLevel::Fault;
    } else if (e.code == 0xC3) {
        out.severity = "Hardware", out.level = ErrorLevel::Firmware;
    } else if (isAbort(e.message)) {
        out.severity = "Aborted", out.level = ErrorLevel::Warning;
        if (out.whatToDo.empty()) out.whatToDo = "Stopped on request: send the command again if it was not meant.";
    } else {
        out.severity = "Refused", out.level = ErrorLevel::Error;
    }
    return out;
}

template <typename Info, typename Convert> std::vector<ErrorEntry> convert(std::span<const Info> infos, Convert f) {
    std::vector<ErrorEntry> out;
    for (const Info& info : infos) out.push_back(f(info));
    return out;
}

std::string upper(std::string_view name) {
    std::string out(name);
    for (char& c : out) c = char(std::toupper(static_cast<unsigned char>(c)));
    return out;
}

} // namespace

std::span<const Parameter> parameters(DriveFamily family) {
    static const std::vector<Parameter> bds5 = bds5Parameters(), sc750 = sc750Parameters(), pmc960 = pmc960Parameters();
    switch (family) {
    case DriveFamily::Bds5: return bds5;
    case DriveFamily::Sc750: return sc750;
    case DriveFamily::Pmc960: return pmc960;
    }
    return {};
}

std::span<const ErrorEntry> errors(DriveFamily family) {
    static const std::vector<ErrorEntry> bds5 = convert(bds5::errors(), bds5Error),
                                         sc750 = convert(sc750::faults(), sc750Error),
                                         pmc960 = convert(pmc960::errors(), pmc960Error);
    switch (family) {
    case DriveFamily::Bds5: return bds5;
    case DriveFamily::Sc750: return sc750;
    case DriveFamily::Pmc960: return pmc960;
    }
    return {};
}

const Parameter* findParameter(DriveFamily family, std::string_view name) {
    const std::string wanted = upper(name);
    for (const Parameter& p : parameters(family)) {
        if (p.firstIndex == 0) {
            if (p.name == wanted) return &p;
            continue;
        }
        // An indexed family: the stem, then an index within its range ("X12"; not "X" alone).
        if (wanted.size() <= p.name.size() || std::string_view(wanted).substr(0, p.name.size()) != p.name) continue;
        int index = 0;
        const char* first = wanted.data() + p.name.size();
        const char* last = wanted.data() + wanted.size();
        const auto [end, ec] = std::from_chars(first, last, index);
        if (ec == std::errc() && end == last && index >= p.firstIndex &&
            index <= std::max(p.lastIndex, p.extendedLastIndex))
            return &p;
    }
    return nullptr;
}

const ErrorEntry* findError(DriveFamily family, int code) {
    const auto all = errors(family);
    const auto it = std::find_if(all.begin(), all.end(), [code](const ErrorEntry& e) { return e.code == code; });
    return it == all.end() ? nullptr : &*it;
}

std::string_view typeName(ValueType type) {
    switch (type) {
    case ValueType::Integer: return "integer";
    case ValueType::Decimal: return "decimal";
    case ValueType::Switch: return "switch (0 or 1)";
    case ValueType::Text: return "text";
    }
    return {};
}

std::string_view writableText(Writable writable) {
    switch (writable) {
    case Writable::Always: return "any time";
    case Writable::WhenDisabled: return "only while the drive is disabled";
    case Writable::WhenStopped: return "only without commanded motion";
    case Writable::Never: return "read only";
    case Writable::Factory: return "factory-protected";
    }
    return {};
}

} // namespace drive_core::catalog
