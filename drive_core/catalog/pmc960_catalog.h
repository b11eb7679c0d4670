// The PMC-960 catalog: every MPL command form, parameter and error code of the controller, with the manual's
// words. The single source of truth for the simulator (ranges, defaults, error texts) and the host side
// (error decoding, help). Line references (L1234) point into seeds/004_bc51514956ef4e5f.txt.
#pragma once

#include <cstdint>
#include <span>
#include <string_view>

namespace drive_core::catalog::pmc960 {

enum class ErrorGroup { Cam, InputRange, Syntax, Motion, Programming, Miscellaneous, SystemStatus };

struct ErrorInfo {
    int code = 0;             // 0x80..0xE3, printed as #<two hex digits>
    std::string_view message; // short text for logs ("Index distance out of range")
    std::string_view meaning; // the manual's explanation
    ErrorGroup group = ErrorGroup::Syntax;
    bool reserved = false;        // listed as "Reserved" in 7.22
    bool asynchronous = false;    // E0-EF: may arrive while the controller sits at the prompt
    std::string_view manualLines; // "L2317"
};

enum class CommandGroup {
    Label,
    MotionParameter,
    MotionAction,
    Synchronization,
    ProgramControl,
    Output,
    System,
    Table
};

// Display characters a command accepts (5.3.1): bit set = accepted.
enum DisplayFlag : unsigned {
    kStored = 1u << 0,  // ?
    kCurrent = 1u << 1, // !
    kStream = 1u << 2,  // %[<time>]<cr>
    kAtError = 1u << 3, // &
    kStop = 1u << 4,    // * (stop motion)
};

struct CommandInfo {
    std::string_view name;     // as typed, upper case: "A", "SM", "TGP", "@"
    std::string_view longName; // "ACCELERATION"
    std::string_view syntax;   // 5.2 / 7.x syntax with the OCR fixed
    CommandGroup group = CommandGroup::System;
    unsigned displays = 0; // DisplayFlag bits
    std::string_view description;
    std::string_view manualLines;
};

enum class NumberBase { Decimal, Hex, Label, FixedPoint };

// One value in the parameter table (T, non-volatile) or a system register (S, volatile).
struct ParameterInfo {
    std::string_view name; // "TGP", "SF"
    std::string_view description;
    std::int64_t minimum = 0;
    std::int64_t maximum = 0;
    std::int64_t factory = 0; // T: factory value; S: power-up value. FixedPoint: value x 1000
    std::int64_t generic = 0; // in use after a generic (ESTOP') power-up (5.4.1)
    NumberBase base = NumberBase::Decimal;
    int binaryBits = 16;     // width of the value in binary communications format
    bool nonVolatile = true; // T table: survives power cycles; ? stored vs ! in use
    std::string_view manualLines;
};

std::span<const ErrorInfo> errors();
std::span<const CommandInfo> commands();
std::span<const ParameterInfo> parameters();

const ErrorInfo* findError(int code);
// What to do about an error (error_remedies.cpp); "" where there is nothing specific to say.
std::string_view errorRemedy(int code);
const CommandInfo* findCommand(std::string_view upperName);
const ParameterInfo* findParameter(std::string_view upperName);

} // namespace drive_core::catalog::pmc960
