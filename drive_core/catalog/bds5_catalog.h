// The BDS5 catalog: every command, variable and error code of the drive, with the manual's words.
// The single source of truth for the simulator (parsing, limits, error texts) and the IDE (help,
// completion, variable browser, error log). Line references (L1234) point into the BDS5 manual seed.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string_view>

namespace drive_core::catalog::bds5 {

// Table D.1: what the drive does when the error occurs.
enum class Severity {
    HistoryOnly = 0, // logged to ERR HIST only (103, 104, 199)
    Warning = 1,     // message only
    Break = 2,       // message, break program execution, stop motion at AMAX
    Disable = 3,     // Break + disable the drive (FAULT latch)
    Firmware = 4,    // CPU LED blinks, communications stop
};

struct ErrorInfo {
    int code = 0;
    std::string_view message; // exactly as the drive prints it after the number, e.g. "ZERO DIVIDE"
    Severity severity = Severity::Break;
    std::string_view meaning;     // the manual's explanation
    std::string_view remedy;      // what the manual says to do about it ("" when silent)
    std::string_view manualLines; // e.g. "L7429"
};

// Where a command may be typed or executed (App. C "Modes").
enum ModeFlag : unsigned {
    kInteractive = 1u << 0, // --> prompt
    kMonitor = 1u << 1,     // ==> prompt and single-step
    kProgram = 1u << 2,     // in the user program
    kEditor = 1u << 3,      // resident editor e->
};

struct CommandInfo {
    std::string_view name;        // as typed: "P", "MA", "<BDS", "IF", "=" for assignment, "$" for labels
    std::string_view longName;    // "PRINT", "MOVE ABSOLUTE", ...
    std::string_view syntax;      // "MA <pos> [vel]"
    unsigned modes = 0;           // ModeFlag bits
    int minEntries = 0;           // parameters after the command word
    int maxEntries = 0;           // 14 = "up to the 15-entry limit"
    bool idling = false;          // lets lower-priority tasks run while it waits
    bool version3 = false;        // added by firmware v3.0.0
    std::string_view description; // the manual's words
    std::string_view manualLines;
};

// Table E.2 limit classes, plus switches (0/1) and explicit ranges.
enum class LimitClass { Long, LongPositive, Short, ShortPositive, Switch, Range, None };

// App. E "Programmable": when a write is accepted.
enum class WriteCondition {
    Always,
    Disabled, // drive must be disabled (ERR 51 otherwise)
    NoMotion, // no commanded motion
    Never,    // monitor variable (ERR 81)
    Factory,  // protected (ERR 111)
};

// An inclusive run of values a write may take (basic units).
struct ValueRange {
    std::int64_t low = 0;
    std::int64_t high = 0;
};

// Which user-unit pair scales the variable on every read and write (NUM/DEN classes).
enum class UnitClass { None, Position, Velocity, Acceleration, Current, ExtPosition, ExtVelocity, Time, Other };

enum class Persistence { Volatile, Remembered };

enum class VariableGroup {
    Position,
    Velocity,
    Current,
    LoopGains,
    Limits,
    Units,
    Io,
    Switches,
    Communication,
    Timers,
    Record,
    User,
    Internal
};

struct VariableInfo {
    std::string_view name; // "VMAX"; indexed families give the stem: "X", "XS", "I", "O", "TMR"
    int firstIndex = 0;    // indexed families: first and last index (X: 1..250); 0,0 otherwise
    int lastIndex = 0;
    // A family a switch extends (v3: EXTDX adds X251-X750, L9309): lastIndex+1..extendedLastIndex resolve
    // (findVariable), but exist on the drive only while the switch `extendedBy` is on (Bds5VariableStore).
    // 0 and "" for every other variable; editors that list a family show firstIndex..lastIndex.
    int extendedLastIndex = 0;
    std::string_view extendedBy{};
    std::string_view description; // the manual's words
    std::string_view units;       // as the manual prints them: "VEL", "ms", "counts", "" for none
    UnitClass unitClass = UnitClass::None;
    LimitClass limits = LimitClass::Long;
    std::int64_t minimum = INT32_MIN; // used when limits == Range; filled from the class otherwise
    std::int64_t maximum = INT32_MAX;
    // Table E.1 limits that minimum/maximum cannot say: a discrete set of valid values (ADDR "0,48-57,65-90";
    // empty: every value in the class or range is valid), and an upper limit that is another variable's
    // present value times maximumPercent / 100, both in basic units of the same unit class (ACC "0-AMAX",
    // VOSPD "below 1.2 VMAX"; "": none). The drive checks both (Bds5VariableStore::write), after the class.
    std::span<const ValueRange> validValues{};
    std::string_view maximumVariable{};
    std::int64_t maximumPercent = 100;
    WriteCondition write = WriteCondition::Always;
    std::int64_t powerUpValue = 0; // in basic units; the factory value for remembered variables
    Persistence persistence = Persistence::Remembered;
    VariableGroup group = VariableGroup::Internal;
    bool isSwitch = false;
    bool recordable = true; // RECORD may sample it
    bool version3 = false;
    std::string_view manualLines;
};

std::span<const ErrorInfo> errors();
std::span<const CommandInfo> commands();
std::span<const VariableInfo> variables();

const ErrorInfo* findError(int code);
const CommandInfo* findCommand(std::string_view upperName);

struct VariableRef {
    const VariableInfo* info = nullptr;
    int index = 0; // 0 for plain variables, 1.. for indexed families (X12 -> index 12)
};
// Resolves "VMAX", "X12", "XS3", "I16" (upper-case), and the extended indices of a family ("X600"), which
// the drive may not have at the moment (EXTDX off). nullopt if no such variable.
std::optional<VariableRef> findVariable(std::string_view upperName);
// The highest index a family can have: extendedLastIndex if the family has one, else lastIndex.
inline int highestIndex(const VariableInfo& v) {
    return v.extendedLastIndex > v.lastIndex ? v.extendedLastIndex : v.lastIndex;
}

// The inclusive limits a write is checked against (class limits or the explicit range).
std::int64_t minimumOf(const VariableInfo& v);
std::int64_t maximumOf(const VariableInfo& v);
// Whether `basic` lies within minimumOf..maximumOf and, for a variable with a discrete set, in one of its
// validValues. (maximumVariable depends on the drive's state: the variable store checks it.)
bool withinLimits(const VariableInfo& v, std::int64_t basic);

} // namespace drive_core::catalog::bds5
