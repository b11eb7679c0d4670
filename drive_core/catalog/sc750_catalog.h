// The SC750 catalog: every ServoBASIC Plus statement, function, predefined variable, interrupt source,
// DACMAP selection and fault code, as data with the manual's line references (Lnnnn = seed 003).
// Ranges and defaults the manual does not give are our choices and are marked `chosen`.
#pragma once

#include <span>
#include <string_view>

namespace drive_core::catalog::sc750 {

enum class ValueType { Integer, Float, String };

enum class Access {
    ReadWrite,
    ReadOnly,
    Parameter, // non-volatile set-up parameter: PARAMS section, R/W at run time, restored at power-up
};

struct VariableInfo {
    std::string_view name; // upper case, as the compiler matches it: "RUN.SPEED", "INP3", "INTR.I3HI"
    ValueType type = ValueType::Integer;
    Access access = Access::ReadWrite;
    double minimum = 0;
    double maximum = 0;
    double defaultValue = 0;
    std::string_view units;
    std::string_view description;
    std::string_view manualLines;
    bool chosen = false; // range or default is our design choice (manual III is not in the seeds)
};

enum class StatementKind { Basic, Motion, Timing, Io, Structure, PacLan };

struct StatementInfo {
    std::string_view name; // "GO.VEL", "IF", "END INTERRUPT"
    std::string_view syntax;
    StatementKind kind = StatementKind::Basic;
    std::string_view description;
    std::string_view manualLines;
};

struct FunctionInfo {
    std::string_view name; // "MID$"
    int minArgs = 0;
    int maxArgs = 0;
    ValueType result = ValueType::Float;
    std::string_view syntax;
    std::string_view description;
    std::string_view manualLines;
};

struct InterruptSourceInfo {
    std::string_view label; // "I3HI", "POS.ERROR"
    std::string_view condition;
    std::string_view manualLines;
};

struct DacMapInfo {
    int value = 0;
    std::string_view mnemonic;
    std::string_view signal;
    double voltsPerUnit = 0; // default scale, volts per unit below
    std::string_view unit;   // "kRPM", "rev", "A", "V", "kHz", "4096 counts"
    std::string_view manualLines;
};

struct FaultInfo {
    int code = 0;             // FAULTCODE value
    std::string_view display; // front panel: "0".."E", "F 1".."F 6"
    std::string_view sc752;   // meaning on SC752/SC753
    std::string_view sc754;   // meaning on SC754/SC755/SC756
    std::string_view manualLines;
};

std::span<const VariableInfo> variables();
std::span<const StatementInfo> statements();
std::span<const FunctionInfo> functions();
std::span<const InterruptSourceInfo> interruptSources(); // 41, in the manual's table order = priority
std::span<const DacMapInfo> dacMap();
std::span<const FaultInfo> faults();

// Case-insensitive look-ups; nullptr when unknown. variableIndex gives the position in variables(), -1.
const VariableInfo* findVariable(std::string_view name);
int variableIndex(std::string_view name);
const FunctionInfo* findFunction(std::string_view name);
const StatementInfo* findStatement(std::string_view name);
int interruptIndex(std::string_view label);
const FaultInfo* findFault(int code);
// What to do about a fault (error_remedies.cpp); "" for a code not in the table.
std::string_view faultRemedy(int code);

// Fault codes the simulator raises itself.
inline constexpr int kFaultNone = 0;
inline constexpr int kFaultOverspeed = 1; // software resolver overspeed (L1531)
inline constexpr int kFaultIt = 4;        // servocontroller I.t (L1534)
inline constexpr int kFaultEnabled = 8;
inline constexpr int kFaultFollowingError = 241;
inline constexpr int kFaultProgramMemory = 242;
inline constexpr int kFaultRunTime = 244;
inline constexpr int kFaultIncompatible = 246;
// The display of an unconfigured controller (L1555): "U C" alternating, like the F codes; it has no FAULTCODE.
inline constexpr std::string_view kUnconfiguredDisplay = "U C";

} // namespace drive_core::catalog::sc750
