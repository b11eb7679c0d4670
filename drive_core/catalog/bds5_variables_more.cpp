// BDS5 variables, part 2: the v3.0.0 additions (L9302-9312), the two variables named only in the text (RTMR,
// CHECKSUM) and the internal/factory variables of App. E Table E.3 (L7697-7721).
#include "bds5_variables_more.h"

#include <array>

namespace drive_core::catalog::bds5 {
namespace {

using enum LimitClass;
using enum WriteCondition;
using enum Persistence;
using U = UnitClass;
using G = VariableGroup;

// One entry per variable, packed by hand: clang-format would put every field on its own line.
// clang-format off
constexpr std::array kMore{
    // ---- v3.0.0 (BDS5300.DOC, BDS5COM2 L10105-10116) ----
    VariableInfo{.name = "MONITOR",
                 .description = "Automatically enter the monitor mode whenever a program starts, so the "
                                "serial port is always listening. Set to 0 on power-up.",
                 .limits = Switch, .powerUpValue = 0, .persistence = Volatile, .group = G::Communication,
                 .isSwitch = true, .version3 = true, .manualLines = "L9302, L10108, L10116"},
    VariableInfo{.name = "ECHO",
                 .description = "Echo of the serial port characters; 0 suppresses it. Remembered on "
                                "power-up (set ECHO=1 after upgrading to v3).",
                 .limits = Switch, .powerUpValue = 1, .group = G::Communication, .isSwitch = true,
                 .version3 = true, .manualLines = "L9303, L9289-9293, L10109"},
    VariableInfo{.name = "MSG",
                 .description = "Power-up message and monitor mode message; 0 suppresses them. Remembered "
                                "on power-up (set MSG=1 after upgrading to v3).",
                 .limits = Switch, .powerUpValue = 1, .group = G::Communication, .isSwitch = true,
                 .version3 = true, .manualLines = "L9304, L9289-9293, L10110"},
    VariableInfo{.name = "EXTDX",
                 .description = "Enable the extended user registers X251-X750; PC-SCOPE (RECORD, PLAY) and "
                                "real time trace (TRECORD, TPLAY) cannot be used while it is on (ERR 63), and "
                                "turning it on or off discards what they had recorded. Remembered on "
                                "power-up (set EXTDX=0 after upgrading).",
                 .limits = Switch, .powerUpValue = 0, .group = G::User, .isSwitch = true, .version3 = true,
                 .manualLines = "L9309, L9295-9297, L9321-9325"},
    // The name is lost in the OCR of L9311; CAM is the switch that NORM <pos> CAM turns on (L9314, L9462).
    VariableInfo{.name = "CAM",
                 .description = "Internal switch: on while the 128-point camming mode with linear "
                                "interpolation is enabled (set by NORM <pos> CAM; turned off by reset, "
                                "disable, a disabling error or NORM without CAM). Cannot be written.",
                 .limits = Switch, .write = Never, .powerUpValue = 0, .persistence = Volatile,
                 .group = G::Position, .isSwitch = true, .version3 = true,
                 .manualLines = "L9311, L9358-9569"},
    VariableInfo{.name = "PCAM",
                 .description = "Position command from the cam table in user registers X100-X227 (PE = PCAM "
                                "- PFB while camming).",
                 .units = "POS", .unitClass = U::Position, .limits = None, .write = Never,
                 .persistence = Volatile, .group = G::Position, .version3 = true,
                 .manualLines = "L9312, L9458-9468"},

    // ---- Named only in the text ----
    // chosen: RTMR behaves like a timer (ms, Long>0, writable); the manual gives only its power-up value.
    VariableInfo{.name = "RTMR", .description = "Profile regulation timer. Set to 0 on power-up.",
                 .units = "ms", .unitClass = U::Time, .limits = LongPositive, .powerUpValue = 0,
                 .persistence = Volatile, .group = G::Timers, .manualLines = "L1546"},
    VariableInfo{.name = "CHECKSUM",
                 .description = "Checksum of the program memory (with a varying offset), to record after a "
                                ">BDS load and compare after later loads.",
                 .limits = None, .write = Never, .persistence = Volatile, .group = G::Communication,
                 .manualLines = "L9953, L9970-9984"},

    // ---- Table E.3: internal variables, set at the factory; the MOTOR command changes them ----
    // chosen: the rows without a programming condition (A1-A16, ADVSLIP, ADVSPD, ADVLD, MANG) are Factory,
    // and every internal value below is a plausible brushless-motor setting (the manual gives none).
    VariableInfo{.name = "A", .firstIndex = 1, .lastIndex = 16, .description = "Internal.", .limits = None,
                 .write = Factory, .manualLines = "L7700"},
    VariableInfo{.name = "ADVSLIP", .description = "Internal.", .limits = None, .write = Factory,
                 .manualLines = "L7701"},
    VariableInfo{.name = "ADVSPD", .description = "Internal.", .limits = None, .write = Factory,
                 .manualLines = "L7702"},
    VariableInfo{.name = "ADVLD", .description = "Internal.", .limits = None, .write = Factory,
                 .manualLines = "L7703"},
    VariableInfo{.name = "ANGLD", .description = "Internal.", .limits = None, .write = Factory,
                 .manualLines = "L7704"},
    VariableInfo{.name = "BSLIP", .description = "Induction base slip.", .units = "mHz",
                 .unitClass = U::Other, .limits = None, .write = Factory, .manualLines = "L7705"},
    VariableInfo{.name = "FOLDD", .description = "Foldback delay (ERR 200 if out of bounds).",
                 .units = "sec/100", .unitClass = U::Other, .limits = None, .write = Factory,
                 .powerUpValue = 200, .manualLines = "L7706, L7509"},
    VariableInfo{.name = "FOLDR", .description = "Foldback reset (ERR 200 if out of bounds).",
                 .units = "sec/100", .unitClass = U::Other, .limits = None, .write = Factory,
                 .powerUpValue = 1000, .manualLines = "L7707, L7509"},
    VariableInfo{.name = "FOLDT", .description = "Foldback constant (ERR 200 if out of bounds).",
                 .units = "sec/100", .unitClass = U::Other, .limits = None, .write = Factory,
                 .powerUpValue = 1000, .manualLines = "L7708, L7509"},
    VariableInfo{.name = "IBASE", .description = "Induction base amps.", .units = "I",
                 .unitClass = U::Current, .limits = None, .write = Factory, .manualLines = "L7709"},
    VariableInfo{.name = "IMAG", .description = "Induction magnetizing current.", .units = "I",
                 .unitClass = U::Current, .limits = None, .write = Factory, .manualLines = "L7710"},
    VariableInfo{.name = "IND", .description = "Select induction motor.", .limits = None, .write = Factory,
                 .manualLines = "L7711"},
    VariableInfo{.name = "IZERO", .description = "Zeroing current (used by ZERO mode).", .units = "I",
                 .unitClass = U::Current, .limits = None, .write = Factory, .powerUpValue = 1024,
                 .manualLines = "L7712"},
    VariableInfo{.name = "MADV", .description = "Enable manual advance.", .limits = None, .write = Factory,
                 .manualLines = "L7713"},
    VariableInfo{.name = "MANG", .description = "Internal.", .limits = None, .write = Factory,
                 .manualLines = "L7714"},
    VariableInfo{.name = "MSLIP", .description = "Manual slip.", .limits = None, .write = Factory,
                 .manualLines = "L7715"},
    VariableInfo{.name = "POLES", .description = "Motor poles, times 128.", .units = "Poles*128",
                 .unitClass = U::Other, .limits = None, .write = Factory, .powerUpValue = 768,
                 .manualLines = "L7716"},
    VariableInfo{.name = "SGOOSE", .description = "Induction angle.", .limits = None, .write = Factory,
                 .manualLines = "L7717"},
    VariableInfo{.name = "SLIP", .description = "Induction slip.", .limits = None, .write = Never,
                 .persistence = Volatile, .manualLines = "L7718"},
    VariableInfo{.name = "SLOPE", .description = "Induction slip slope.", .units = "1/10%",
                 .unitClass = U::Other, .limits = None, .write = Factory, .manualLines = "L7719"},
    VariableInfo{.name = "VADVTBL", .description = "Angle table maximum speed.", .units = "VEL",
                 .unitClass = U::Velocity, .limits = None, .write = Factory, .powerUpValue = 33554250,
                 .manualLines = "L7720"},
    VariableInfo{.name = "VBASE", .description = "Induction base speed.", .units = "VEL",
                 .unitClass = U::Velocity, .limits = None, .write = Factory, .manualLines = "L7721"},
};
// clang-format on

} // namespace

std::span<const VariableInfo> moreVariables() {
    return kMore;
}

} // namespace drive_core::catalog::bds5
