// BDS5 variables, part 1: the standard variables of App. E Table E.1 (L7553-7684) with the initial and
// power-up values of sections 3.3.8-3.3.9 (L1490-1570). The v3.0.0, text-only and internal variables are in
// bds5_variables_more.cpp; variables() joins both tables.
#include "bds5_catalog.h"
#include "bds5_variables_more.h"

#include <array>
#include <vector>

namespace drive_core::catalog::bds5 {
namespace {

using enum LimitClass;
using enum WriteCondition;
using enum Persistence;
using U = UnitClass;
using G = VariableGroup;

// Values are stored in basic units (digest §5.8). With the standard units:
// ACC = RPM/s x ANUM/ADEN (4474/1000), velocity = RPM x VNUM/VDEN (44739/10), current = % x INUM/IDEN
// (4095/100), position = counts.
constexpr std::int64_t kRpm100kPerS = 447400; // 100000 RPM/s x 4474 / 1000
constexpr std::int64_t kVmax = 33554250;      // 7500 RPM x 44739 / 10
constexpr std::int64_t kFullCurrent = 4095;   // 100 % x 4095 / 100

// ADDR's valid values: 0 single-drop, 48-57 ('0'-'9') and 65-90 ('A'-'Z') multidrop (L7558, L5424-5426).
constexpr ValueRange kAddressValues[] = {{0, 0}, {48, 57}, {65, 90}};

// One entry per variable, packed by hand: clang-format would put every field on its own line.
// clang-format off
constexpr std::array kStandard{
    // chosen: full scale (100 % in standard units)
    VariableInfo{.name = "AMPS",
                 .description = "Drive amps: the current rating of the drive, set at the factory (ERR 203 "
                                "AMPS BAD if invalid).",
                 .units = "I", .unitClass = U::Current, .limits = None, .write = Factory,
                 .powerUpValue = kFullCurrent, .group = G::Current, .manualLines = "L7554, L7515"},
    // chosen: 0 so the simulator signs on at once
    VariableInfo{.name = "ABAUD",
                 .description = "Autobaud on: at power-up, with ADDR 0, the drive measures the baud rate "
                                "from carriage returns and stores it in BAUD (CPU LED flashes while "
                                "waiting). Set to 1 at the factory; turn it off when using multitasking.",
                 .limits = Switch, .powerUpValue = 0, .group = G::Communication, .isSwitch = true,
                 .manualLines = "L7555, L1518, L5292-5318"},
    VariableInfo{.name = "ACC",
                 .description = "Acceleration rate of MA, MI, MRD, J, JT, JF and macro sections (the "
                                "average rate with S-curves); 0 to AMAX. Initially 100000 RPM/s.",
                 .units = "ACC", .unitClass = U::Acceleration, .limits = LongPositive,
                 .maximumVariable = "AMAX", .powerUpValue = kRpm100kPerS, .group = G::Velocity,
                 .manualLines = "L7556, L1519, L2186"},
    VariableInfo{.name = "ACTIVE",
                 .description = "Monitor drive: on when the drive is active (READY and REMOTE on) and the "
                                "motor is under control.",
                 .limits = Switch, .write = Never, .persistence = Volatile, .group = G::Switches,
                 .isSwitch = true, .manualLines = "L7557, L1937-1941"},
    VariableInfo{.name = "ADDR",
                 .description = "Multidrop address: 0 for single-drop, 48-57 ('0'-'9') or 65-90 ('A'-'Z') "
                                "for multidrop, which a non-zero value selects at once. MOTION off at "
                                "power-up forces ADDR to 0.",
                 .limits = Range, .minimum = 0, .maximum = 90, .validValues = kAddressValues, .powerUpValue = 0,
                 .group = G::Communication,
                 .manualLines = "L7558, L1520, L5416-5469"},
    VariableInfo{.name = "ADEN", .description = "Acceleration units denominator. Initially 1000 for RPM/s.",
                 .powerUpValue = 1000, .group = G::Units, .manualLines = "L7559, L1521"},
    VariableInfo{.name = "AMAX",
                 .description = "Acc/dec maximum: limits ACC and DEC; S and every error that stops motion "
                                "decelerate at AMAX. Changeable only when disabled. Initially 100000 RPM/s.",
                 .units = "ACC", .unitClass = U::Acceleration, .limits = LongPositive, .write = Disabled,
                 .powerUpValue = kRpm100kPerS, .group = G::Limits, .manualLines = "L7560, L1522, L2180"},
    VariableInfo{.name = "ANUM", .description = "Acceleration units numerator. Initially 4474 for RPM/s.",
                 .powerUpValue = 4474, .group = G::Units, .manualLines = "L7561, L1523"},
    // chosen: 9600 (manual: set by autobaud)
    VariableInfo{.name = "BAUD",
                 .description = "Baud rate for serial communications, normally set by autobaud. An "
                                "unsupported value forces autobaud at power-up (ERR 103).",
                 .limits = Range, .minimum = 300, .maximum = 19200, .powerUpValue = 9600,
                 .group = G::Communication, .manualLines = "L7562, L1524, L5292-5318"},
    VariableInfo{.name = "CAP",
                 .description = "Enable capture: when HOME changes to the state given by CAPDIR, PFB is "
                                "stored in PCAP and CAP turns off.",
                 .limits = Switch, .powerUpValue = 0, .persistence = Volatile, .group = G::Position,
                 .isSwitch = true, .manualLines = "L7563, L1525, L2615-2627"},
    VariableInfo{.name = "CAPDIR",
                 .description = "Polarity of capture: 1 captures when HOME goes from 0 to 1, 0 when it goes "
                                "from 1 to 0. Writing CAPDIR turns CAP off.",
                 .limits = Switch, .powerUpValue = 1, .persistence = Volatile, .group = G::Position,
                 .isSwitch = true, .manualLines = "L7564, L1526, L2625-2627"},
    VariableInfo{.name = "CLAMP",
                 .description = "Enable clamp mode: when PE exceeds PECLAMP during a move the profile stops "
                                "and the motor holds against the stop with current limited by ILIM.",
                 .limits = Switch, .powerUpValue = 0, .persistence = Volatile, .group = G::Switches,
                 .isSwitch = true, .manualLines = "L7569, L1527, L2659-2732"},
    VariableInfo{.name = "CYCLE", .description = "Start cycle: the CYCLE input; a rising edge starts AUTO$.",
                 .limits = Switch, .write = Never, .persistence = Volatile, .group = G::Io, .isSwitch = true,
                 .manualLines = "L7570, L4960-4978"},
    VariableInfo{.name = "DEC",
                 .description = "Deceleration rate of moves, jogs and macro sections; 0 to AMAX. Initially "
                                "100000 RPM/s.",
                 .units = "ACC", .unitClass = U::Acceleration, .limits = LongPositive,
                 .maximumVariable = "AMAX", .powerUpValue = kRpm100kPerS, .group = G::Velocity,
                 .manualLines = "L7571, L1528, L2188"},
    VariableInfo{.name = "DEP",
                 .description = "Shorten error messages to 40 characters for the DEP-01 data entry panel.",
                 .limits = Switch, .powerUpValue = 0, .persistence = Volatile, .group = G::Communication,
                 .isSwitch = true, .manualLines = "L7572, L6102-6108"},
    VariableInfo{.name = "DIR",
                 .description = "On if CW is positive: sets the sign of position, velocity and torque (0: "
                                "counter-clockwise is positive). Set DIR before PMAX and PMIN.",
                 .limits = Switch, .powerUpValue = 1, .persistence = Volatile, .group = G::Switches,
                 .isSwitch = true, .manualLines = "L7573, L1529, L2259"},
    VariableInfo{.name = "EXTLOOP",
                 .description = "On for encoder feedback: close the position loop on the external encoder "
                                "(PE = PCMD - PEXT). Changeable only when disabled.",
                 .limits = Switch, .write = Disabled, .powerUpValue = 0, .persistence = Volatile,
                 .group = G::Switches, .isSwitch = true, .manualLines = "L7574, L3115-3133"},
    VariableInfo{.name = "FAULT",
                 .description = "On for BDS5 fault: the fault latch, set by any fault or by the program; "
                                "FAULT OFF, EN or power-down reset it.",
                 .limits = Switch, .powerUpValue = 0, .persistence = Volatile, .group = G::Switches,
                 .isSwitch = true, .manualLines = "L7575, L1530, L1925-1931"},
    VariableInfo{.name = "FOLD",
                 .description = "Monitor foldback mode: on when the current is limited by IFOLD.",
                 .limits = Switch, .write = Never, .persistence = Volatile, .group = G::Current,
                 .isSwitch = true, .manualLines = "L7576, L2155"},
    VariableInfo{.name = "GATE",
                 .description = "Monitor GATE input (C7 pin 17); starts gated motion in GATEMODE.",
                 .limits = Switch, .write = Never, .persistence = Volatile, .group = G::Io, .isSwitch = true,
                 .manualLines = "L7577, L5957"},
    VariableInfo{.name = "GATEMODE",
                 .description = "Enable gate mode: precalculate the next motion and start it on a rising "
                                "edge of GATE; turns off when motion starts.",
                 .limits = Switch, .powerUpValue = 0, .persistence = Volatile, .group = G::Switches,
                 .isSwitch = true, .manualLines = "L7578, L1532, L5949-5971"},
    VariableInfo{.name = "GEAR",
                 .description = "Enable gear mode: the electronic gearbox follows the external input times "
                                "GEARI/GEARO; turning it on sets VOFF to 0.",
                 .limits = Switch, .powerUpValue = 0, .persistence = Volatile, .group = G::Switches,
                 .isSwitch = true, .manualLines = "L7579, L1533, L2923-3042"},
    VariableInfo{.name = "GEARI",
                 .description = "Input gear teeth of the electronic gearbox; the sign reverses the "
                                "direction. Initially 1.",
                 .limits = Short, .powerUpValue = 1, .group = G::Units, .manualLines = "L7580, L1534, L2945"},
    // chosen: 1..32767, because GEARO 0 would divide by zero (Table E.2 writes the bounds as strict).
    VariableInfo{.name = "GEARO", .description = "Output gear teeth of the electronic gearbox. Initially 3.",
                 .limits = Range, .minimum = 1, .maximum = 32767, .powerUpValue = 3, .group = G::Units,
                 .manualLines = "L7581, L1535, L2945"},
    VariableInfo{.name = "HOME", .description = "Monitor HOME input: the position capture trigger.",
                 .limits = Switch, .write = Never, .persistence = Volatile, .group = G::Io, .isSwitch = true,
                 .manualLines = "L7582, L2754"},
    VariableInfo{.name = "ICMD",
                 .description = "Commanded current, generated internally from motion commands.", .units = "I",
                 .unitClass = U::Current, .limits = None, .write = Never, .persistence = Volatile,
                 .group = G::Current, .manualLines = "L7583, L2056"},
    // chosen: 50 % of peak
    VariableInfo{.name = "ICONT", .description = "Continuous current rating, set at the factory.",
                 .units = "I", .unitClass = U::Current, .limits = None, .write = Factory,
                 .powerUpValue = 2048, .group = G::Current, .manualLines = "L7584, L2141"},
    VariableInfo{.name = "IDEN", .description = "Current units denominator. Initially 100 for percent.",
                 .powerUpValue = 100, .group = G::Units, .manualLines = "L7585, L1536"},
    VariableInfo{.name = "IFOLD",
                 .description = "Monitor foldback: the foldback current limit; high when the drive is "
                                "disabled.",
                 .units = "I", .unitClass = U::Current, .limits = None, .write = Never,
                 .powerUpValue = kFullCurrent, .persistence = Volatile, .group = G::Current,
                 .manualLines = "L7586, L2143-2168"},
    // Table E.1 gives 1-IMAX (IMAX = 4095 basic); §3.3.3 says 0-100.
    VariableInfo{.name = "ILIM",
                 .description = "Set current limit: limits the peak of ICMD, 1 to IMAX; can be changed at "
                                "any time. Initial value from the TL sheet, normally IMAX.",
                 .units = "I", .unitClass = U::Current, .limits = Range, .minimum = 1,
                 .maximum = kFullCurrent, .maximumVariable = "IMAX", .powerUpValue = kFullCurrent,
                 .group = G::Current,
                 .manualLines = "L7587, L1537, L2060-2066"},
    VariableInfo{.name = "IMAX",
                 .description = "Maximum current the BDS5 can output, set at the factory for the drive "
                                "rating and the motor.",
                 .units = "I", .unitClass = U::Current, .limits = None, .write = Factory,
                 .powerUpValue = kFullCurrent, .group = G::Limits, .manualLines = "L7588, L2062"},
    VariableInfo{.name = "IMON",
                 .description = "Monitor current: magnitude of the measured motor current (always positive).",
                 .units = "I", .unitClass = U::Current, .limits = None, .write = Never,
                 .persistence = Volatile, .group = G::Current, .manualLines = "L7589, L2058"},
    VariableInfo{.name = "I", .firstIndex = 1, .lastIndex = 16,
                 .description = "Monitor 16 input lines: the general-purpose inputs I1-I16.",
                 .limits = Switch, .write = Never, .persistence = Volatile, .group = G::Io, .isSwitch = true,
                 .manualLines = "L7590, L1800-1825"},
    VariableInfo{.name = "IN",
                 .description = "Input word: I1-I16 as one number, I1 is the least significant bit.",
                 .limits = None, .write = Never, .persistence = Volatile, .group = G::Io,
                 .manualLines = "L7591, L1825"},
    VariableInfo{.name = "INUM", .description = "Current units numerator. Initially 4095 for percent.",
                 .powerUpValue = 4095, .group = G::Units, .manualLines = "L7592, L1538"},
    VariableInfo{.name = "KC",
                 .description = "Low speed adjust: low-speed graininess compensation, almost always 200.",
                 .limits = Range, .minimum = 0, .maximum = 255, .powerUpValue = 200, .group = G::LoopGains,
                 .manualLines = "L7593, L1539"},
    VariableInfo{.name = "KF",
                 .description = "Feed-forward gain: velocity feed-forward, 16384 is unity. Set to 0 for "
                                "preliminary operation.",
                 .limits = ShortPositive, .powerUpValue = 0, .group = G::LoopGains,
                 .manualLines = "L7594, L1540, L3178-3182"},
    // chosen: below KPmax 2000 of a 20 Hz loop (Table 6.4)
    VariableInfo{.name = "KP",
                 .description = "Position loop gain. Initial value from the TL sheet; TUNE sets it.",
                 .limits = ShortPositive, .powerUpValue = 1500, .group = G::LoopGains,
                 .manualLines = "L7595, L1541, L3170"},
    // chosen: a typical value (manual: from the TL sheet)
    VariableInfo{.name = "KPROP",
                 .description = "Proportional velocity loop gain (PROP on) and torque gain. Initial value "
                                "from the TL sheet; TUNE sets it.",
                 .limits = ShortPositive, .powerUpValue = 2000, .group = G::LoopGains,
                 .manualLines = "L7596, L1532, L3198, L3210"},
    // chosen: a typical value (manual: from the TL sheet)
    VariableInfo{.name = "KV",
                 .description = "Integrating velocity loop gain (tuning gain #1). Initial value from the TL "
                                "sheet; TUNE sets it.",
                 .limits = ShortPositive, .powerUpValue = 2000, .group = G::LoopGains,
                 .manualLines = "L7597, L1533, L3206"},
    // chosen: 20 Hz (Table 6.3)
    VariableInfo{.name = "KVI",
                 .description = "Integrating velocity loop gain (tuning gain #2); sets the velocity loop "
                                "bandwidth (Table 6.3). Initial value from the TL sheet.",
                 .limits = ShortPositive, .powerUpValue = 5000, .group = G::LoopGains,
                 .manualLines = "L7598, L1534, L3204, L6330-6341"},
    // chosen: switches closed, no overtravel
    VariableInfo{.name = "LIMIT",
                 .description = "Monitor LIMIT input: the normally closed hardware travel limit switches; 0 "
                                "means overtravel (ERR 24 while enabled).",
                 .limits = Switch, .write = Never, .powerUpValue = 1, .persistence = Volatile, .group = G::Io,
                 .isSwitch = true, .manualLines = "L7601, L7224-7228"},
    // chosen: off (TL sheet)
    VariableInfo{.name = "LPF",
                 .description = "Enable low pass filter (two cascaded one-pole filters at LPFHZ), often "
                                "needed against noise or torsional resonance. Remembered; initial value "
                                "from the TL sheet.",
                 .limits = Switch, .powerUpValue = 0, .group = G::LoopGains, .isSwitch = true,
                 .manualLines = "L7602, L1535, L6473-6489"},
    // chosen: a typical value (manual: from the TL sheet)
    VariableInfo{.name = "LPFHZ",
                 .description = "Low pass filter break frequency. Initial value from the TL sheet; reduce "
                                "it if the system is too noisy.",
                 .units = "Hz", .unitClass = U::Other, .limits = Range, .minimum = 0, .maximum = 500,
                 .powerUpValue = 200, .group = G::LoopGains, .manualLines = "L7603, L1536, L6473-6489"},
    VariableInfo{.name = "LSTERR", .description = "Last error: the number of the most recent error.",
                 .limits = None, .write = Never, .persistence = Volatile, .group = G::Record,
                 .manualLines = "L7604"},
    VariableInfo{.name = "LSTLBL", .description = "Last label executed.", .persistence = Volatile,
                 .group = G::Record, .manualLines = "L7605"},
    VariableInfo{.name = "MANUAL",
                 .description = "Monitor MANUAL input: with MANUAL$ present the MANUAL program runs while "
                                "it is on; it can fire alarms.",
                 .limits = Switch, .write = Never, .persistence = Volatile, .group = G::Io, .isSwitch = true,
                 .manualLines = "L7606, L4980-4997"},
    // chosen: on, so the simulator signs on at once
    VariableInfo{.name = "MOTION",
                 .description = "Monitor MOTION input: must be on to command motion (ERR 19); off at "
                                "power-up forces autobaud and ADDR 0.",
                 .limits = Switch, .write = Never, .powerUpValue = 1, .persistence = Volatile, .group = G::Io,
                 .isSwitch = true, .manualLines = "L7607, L2196-2210, L5306"},
    VariableInfo{.name = "MULTI",
                 .description = "Enable multi-tasking of alarm C, VARIABLE$ and BACKGROUND$ (alarms A and B "
                                "always run).",
                 .limits = Switch, .powerUpValue = 1, .persistence = Volatile, .group = G::Switches,
                 .isSwitch = true, .manualLines = "L7608, L1537, L4569-4577"},
    // chosen: constants are not recordable
    VariableInfo{.name = "N", .description = "Special constant = 0 (same as OFF).", .limits = None,
                 .write = Never, .persistence = Volatile, .group = G::User, .recordable = false,
                 .manualLines = "L7609, L1647"},
    VariableInfo{.name = "O", .firstIndex = 1, .lastIndex = 8,
                 .description = "Set/monitor output lines: the general-purpose outputs O1-O8.",
                 .limits = Switch, .powerUpValue = 0, .persistence = Volatile, .group = G::Io,
                 .isSwitch = true, .manualLines = "L7610, L1538, L1800-1825"},
    VariableInfo{.name = "OFF", .description = "Special constant = 0.", .limits = None, .write = Never,
                 .persistence = Volatile, .group = G::User, .recordable = false,
                 .manualLines = "L7611, L1647"},
    // chosen: no fault at power-up
    VariableInfo{.name = "OK2EN", .description = "OK to enable BDS5: no fault prevents enabling.",
                 .limits = Switch, .write = Never, .powerUpValue = 1, .persistence = Volatile,
                 .group = G::Switches, .isSwitch = true, .manualLines = "L7612"},
    VariableInfo{.name = "ON", .description = "Special constant = 1.", .limits = None, .write = Never,
                 .powerUpValue = 1, .persistence = Volatile, .group = G::User, .recordable = false,
                 .manualLines = "L7613, L1647"},
    VariableInfo{.name = "OUT",
                 .description = "Set/monitor output word: O1-O8 as one number, O1 is the least significant "
                                "bit. Set to 0 shortly after power-up.",
                 .limits = Range, .minimum = 0, .maximum = 255, .powerUpValue = 0, .persistence = Volatile,
                 .group = G::Io, .manualLines = "L7614, L1504, L1825"},
    VariableInfo{.name = "PCAP", .description = "Capture position: PFB stored when the capture occurred.",
                 .units = "POS", .unitClass = U::Position, .limits = None, .write = Never,
                 .persistence = Volatile, .group = G::Position, .manualLines = "L7615, L2623"},
    VariableInfo{.name = "PCMD",
                 .description = "Position command, generated from motion commands; equals PFB when "
                                "disabled. While camming it is the gearbox output (rotary, 32768 counts).",
                 .units = "POS", .unitClass = U::Position, .limits = None, .write = Never,
                 .persistence = Volatile, .group = G::Position, .manualLines = "L7616, L1985, L9462"},
    VariableInfo{.name = "PDEN",
                 .description = "Position units denominator. Initially 1. Not changeable with ROTARY on.",
                 .powerUpValue = 1, .group = G::Units, .manualLines = "L7617, L1539, L5248-5286"},
    VariableInfo{.name = "PE",
                 .description = "Position error PCMD - PFB (PCMD - PEXT with EXTLOOP, PCAM - PFB when "
                                "camming); 0 when disabled. Cannot be recorded.",
                 .units = "POS", .unitClass = U::Position, .limits = None, .write = Never,
                 .persistence = Volatile, .group = G::Position, .recordable = false,
                 .manualLines = "L7618, L1991, L7013"},
    VariableInfo{.name = "PECLAMP",
                 .description = "Clamp position error: the PE at which clamp mode stops the profile. "
                                "Initially 100.",
                 .units = "POS", .unitClass = U::Position, .limits = ShortPositive, .powerUpValue = 100,
                 .group = G::Limits, .manualLines = "L7619, L1543, L2659-2732"},
    VariableInfo{.name = "PEMAX",
                 .description = "Maximum position error: ERR 25 PE OVERFLOW when PE exceeds it. Initially "
                                "32767 (its upper limit).",
                 .units = "POS", .unitClass = U::Position, .limits = ShortPositive, .powerUpValue = 32767,
                 .group = G::Limits, .manualLines = "L7620, L1544, L1993"},
    // Table E.1 prints POS, but PEXT is scaled by the external units PXNUM/PXDEN.
    // chosen: 0 (manual: undefined)
    VariableInfo{.name = "PEXT",
                 .description = "External position: the accumulated counts of the external (master) input; "
                                "writing it normalizes. Initially undefined.",
                 .units = "POS", .unitClass = U::ExtPosition, .powerUpValue = 0, .persistence = Volatile,
                 .group = G::Position, .manualLines = "L7621, L1545, L2929"},
    VariableInfo{.name = "PFB",
                 .description = "Position feedback, updated every millisecond; 0 at power-up. Writing it is "
                                "the same as NORM.",
                 .units = "POS", .unitClass = U::Position, .write = NoMotion, .powerUpValue = 0,
                 .persistence = Volatile, .group = G::Position, .manualLines = "L7622, L1987, L2457-2463"},
    VariableInfo{.name = "PFNL",
                 .description = "Final position of the present (or last) move; of the whole macro for macro "
                                "moves.",
                 .units = "POS", .unitClass = U::Position, .limits = None, .write = Never,
                 .persistence = Volatile, .group = G::Position, .manualLines = "L7623, L2426-2435"},
    VariableInfo{.name = "PL",
                 .description = "Enable position loop; off runs the BDS5 as a velocity loop. Turning PL on "
                                "turns TQ off.",
                 .limits = Switch, .powerUpValue = 1, .persistence = Volatile, .group = G::LoopGains,
                 .isSwitch = true, .manualLines = "L7624, L1546, L2068-2070, L3184"},
    VariableInfo{.name = "PLIM", .description = "Enable soft limits PMAX and PMIN (ERR 23).",
                 .limits = Switch, .powerUpValue = 1, .persistence = Volatile, .group = G::Limits,
                 .isSwitch = true, .manualLines = "L7625, L1547, L2257"},
    VariableInfo{.name = "PMAX",
                 .description = "Soft upper limit: with PLIM on no positive motion beyond it. Initially 100.",
                 .units = "POS", .unitClass = U::Position, .powerUpValue = 100, .group = G::Limits,
                 .manualLines = "L7626, L1548, L2237-2259"},
    VariableInfo{.name = "PMIN",
                 .description = "Soft lower limit: with PLIM on no negative motion beyond it. Initially "
                                "-100.",
                 .units = "POS", .unitClass = U::Position, .powerUpValue = -100, .group = G::Limits,
                 .manualLines = "L7627, L1549, L2237-2259"},
    // COM2 (L10077) says PROMPT is remembered; Table 3.2 (ON at power-up) is followed.
    VariableInfo{.name = "PROMPT",
                 .description = "Enable prompts: when 0 no prompt (such as -->) is printed, so programs can "
                                "print customized screens.",
                 .limits = Switch, .powerUpValue = 1, .persistence = Volatile, .group = G::Communication,
                 .isSwitch = true, .manualLines = "L7628, L1550, L5320-5326"},
    // chosen: one revolution
    VariableInfo{.name = "PROTARY",
                 .description = "Rotary distance: PFB, PCMD and PFNL roll over at it in rotary mode. Not "
                                "changeable with ROTARY on.",
                 .units = "POS", .unitClass = U::Position, .powerUpValue = 4096, .group = G::Position,
                 .manualLines = "L7629, L5248-5286"},
    VariableInfo{.name = "PNUM",
                 .description = "Position units numerator. Initially 1. Not changeable with ROTARY on.",
                 .powerUpValue = 1, .group = G::Units, .manualLines = "L7630, L1551, L5248-5286"},
    VariableInfo{.name = "PRD",
                 .description = "Position from R/D: the raw resolver-to-digital reading, 0-4095 (12-bit), "
                                "16383 or 65535; not in position units and not latched.",
                 .units = "counts", .limits = None, .write = Never, .persistence = Volatile,
                 .group = G::Position, .manualLines = "L7633, L1997-2014"},
    VariableInfo{.name = "PROP",
                 .description = "Enable proportional velocity loop (gain KPROP) instead of the integrating "
                                "loop.",
                 .limits = Switch, .powerUpValue = 0, .persistence = Volatile, .group = G::LoopGains,
                 .isSwitch = true, .manualLines = "L7634, L1552, L2072-2074"},
    // chosen: 0
    VariableInfo{.name = "PTRIP1", .description = "Position trip point #1: TRIP1 is on while PFB >= PTRIP1.",
                 .units = "POS", .unitClass = U::Position, .powerUpValue = 0, .group = G::Position,
                 .manualLines = "L7635, L2261-2275"},
    // chosen: 0
    VariableInfo{.name = "PTRIP2", .description = "Position trip point #2: TRIP2 is on while PFB >= PTRIP2.",
                 .units = "POS", .unitClass = U::Position, .powerUpValue = 0, .group = G::Position,
                 .manualLines = "L7636, L2261-2275"},
    VariableInfo{.name = "PXDEN", .description = "External position units denominator. Initially 1.",
                 .powerUpValue = 1, .group = G::Units, .manualLines = "L7637, L1553"},
    VariableInfo{.name = "PXNUM", .description = "External position units numerator. Initially 1.",
                 .powerUpValue = 1, .group = G::Units, .manualLines = "L7638, L1543"},
    VariableInfo{.name = "RAMP",
                 .description = "Ramp control with gear: with PL off, limit the slew of the gearbox "
                                "velocity command to ACC and DEC.",
                 .limits = Switch, .powerUpValue = 0, .persistence = Volatile, .group = G::Switches,
                 .isSwitch = true, .manualLines = "L7639, L3033-3042"},
    VariableInfo{.name = "READY",
                 .description = "Enable drive: the ready latch, set by EN, reset by DIS, K or a fault.",
                 .limits = Switch, .write = Never, .persistence = Volatile, .group = G::Switches,
                 .isSwitch = true, .manualLines = "L7640, L1933-1935"},
    VariableInfo{.name = "REG",
                 .description = "Enable profile regulation: profiles advance in proportion to the external "
                                "frequency (full speed at REGKHZ). Not with GEAR.",
                 .limits = Switch, .powerUpValue = 0, .persistence = Volatile, .group = G::Switches,
                 .isSwitch = true, .manualLines = "L7641, L1544, L3044-3061"},
    VariableInfo{.name = "REGKHZ",
                 .description = "Max regulation frequency: the external frequency at which a regulated "
                                "profile runs as specified, resolved to 1 kHz. Initially 1000.",
                 .units = "kHz", .unitClass = U::Other, .limits = Range, .minimum = 1, .maximum = 2000,
                 .powerUpValue = 1000, .group = G::Units, .manualLines = "L7642, L1545, L3059-3061"},
    // chosen: on, so EN makes the drive active
    VariableInfo{.name = "REMOTE",
                 .description = "Monitor REMOTE input (enable input on C2); prints -1 when a fault hides "
                                "it. Not allowed for alarms, H or RECORD.",
                 .limits = Switch, .write = Never, .powerUpValue = 1, .persistence = Volatile, .group = G::Io,
                 .isSwitch = true, .recordable = false, .manualLines = "L7643, L1941, L7414"},
    VariableInfo{.name = "ROTARY",
                 .description = "Enable rotary mode: PFB, PCMD and PFNL roll over at PROTARY; needs 0 <= "
                                "PFB <= PROTARY (ERR 61).",
                 .limits = Switch, .powerUpValue = 0, .persistence = Volatile, .group = G::Switches,
                 .isSwitch = true, .manualLines = "L7644, L5248-5286"},
    VariableInfo{.name = "SAT",
                 .description = "Monitor saturation: on when ICMD is limited by ILIM or IFOLD.",
                 .limits = Switch, .write = Never, .persistence = Volatile, .group = G::Current,
                 .isSwitch = true, .manualLines = "L7645, L2155"},
    // chosen: 1-5 as Table 3.7 names five shapes (Table E.1 says 1-3).
    VariableInfo{.name = "SCRV",
                 .description = "S-curve type: 1 straight-line, 2 modified polynomial, 3 polynomial, 4 "
                                "modified sinusoid, 5 sinusoid. Initially 2.",
                 .limits = Range, .minimum = 1, .maximum = 5, .powerUpValue = 2, .group = G::Velocity,
                 .manualLines = "L7646, L1547, L2300-2312"},
    VariableInfo{.name = "SEG",
                 .description = "Motion segment: the segment of the present profile, 0 when no profile is "
                                "commanded.",
                 .limits = None, .write = Never, .persistence = Volatile, .group = G::Position,
                 .manualLines = "L7647, L5841-5852"},
    VariableInfo{.name = "SERIAL",
                 .description = "Monitor serial port: on when the port is not busy transmitting.",
                 .limits = Switch, .write = Never, .powerUpValue = 1, .persistence = Volatile,
                 .group = G::Communication, .isSwitch = true, .manualLines = "L7648, L4437-4444"},
    VariableInfo{.name = "SS",
                 .description = "Enable single step: each program line waits for Enter at the single-step "
                                "prompt.",
                 .limits = Switch, .powerUpValue = 0, .persistence = Volatile, .group = G::Switches,
                 .isSwitch = true, .manualLines = "L7649, L1548, L1310-1320"},
    VariableInfo{.name = "STATMODE",
                 .description = "Select STATUS type: 1 makes STATUS follow READY, 0 ACTIVE.",
                 .limits = Switch, .powerUpValue = 0, .persistence = Volatile, .group = G::Switches,
                 .isSwitch = true, .manualLines = "L7650, L1549, L1943-1951"},
    VariableInfo{.name = "STATUS",
                 .description = "Monitor STATUS output (C8 pin 35), e.g. for brake control.",
                 .limits = Switch, .write = Never, .persistence = Volatile, .group = G::Io, .isSwitch = true,
                 .manualLines = "L7651, L1943-1951"},
    VariableInfo{.name = "TMR", .firstIndex = 1, .lastIndex = 4,
                 .description = "Standard timers TMR1-TMR4: count down every millisecond and stop at 0. Set "
                                "to 0 on power-up. Cannot be recorded.",
                 .units = "ms", .unitClass = U::Time, .limits = LongPositive, .powerUpValue = 0,
                 .persistence = Volatile, .group = G::Timers, .recordable = false,
                 .manualLines = "L7652-7655, L1550, L5783-5815"},
    VariableInfo{.name = "TRC",
                 .description = "Enable trace: each program line is printed before it executes.",
                 .limits = Switch, .powerUpValue = 0, .persistence = Volatile, .group = G::Switches,
                 .isSwitch = true, .manualLines = "L7656, L1554, L1316-1320"},
    VariableInfo{.name = "TRIP", .description = "Enable trip points (costs about 4% of execution time).",
                 .limits = Switch, .powerUpValue = 1, .persistence = Volatile, .group = G::Position,
                 .isSwitch = true, .manualLines = "L7657, L1555, L2269-2275"},
    VariableInfo{.name = "TRIP1", .description = "Trip #1 indicator: on while PFB >= PTRIP1.",
                 .limits = Switch, .write = Never, .persistence = Volatile, .group = G::Position,
                 .isSwitch = true, .manualLines = "L7658, L2265"},
    VariableInfo{.name = "TRIP2", .description = "Trip #2 indicator: on while PFB >= PTRIP2.",
                 .limits = Switch, .write = Never, .persistence = Volatile, .group = G::Position,
                 .isSwitch = true, .manualLines = "L7659, L2265"},
    VariableInfo{.name = "TQ",
                 .description = "Enable torque loop, which disables the velocity loop; turning TQ on turns "
                                "PL off.",
                 .limits = Switch, .powerUpValue = 0, .persistence = Volatile, .group = G::LoopGains,
                 .isSwitch = true, .manualLines = "L7660, L1556, L3208-3214"},
    VariableInfo{.name = "VAVG",
                 .description = "Averaged VFB over the previous 16 milliseconds. Cannot be recorded.",
                 .units = "VEL", .unitClass = U::Velocity, .limits = None, .write = Never,
                 .persistence = Volatile, .group = G::Velocity, .recordable = false,
                 .manualLines = "L7661, L2042"},
    VariableInfo{.name = "VCMD",
                 .description = "Velocity command, generated from motion commands; 0 when disabled.",
                 .units = "VEL", .unitClass = U::Velocity, .limits = None, .write = Never,
                 .persistence = Volatile, .group = G::Velocity, .manualLines = "L7662, L2036"},
    // 1 RPM x 44739 / 10 = 4473.9, rounded. "<VMAX" read as at most VMAX, as Table E.2's "<" bounds are
    // (PEMAX's initial value is its limit 32767), and MA/MI accept a speed of VMAX (L7254).
    VariableInfo{.name = "VDEFAULT", .description = "MI/MA default velocity, below VMAX. Initially 1 RPM.",
                 .units = "VEL", .unitClass = U::Velocity, .limits = LongPositive, .maximumVariable = "VMAX",
                 .powerUpValue = 4474,
                 .group = G::Velocity, .manualLines = "L7665, L1560"},
    VariableInfo{.name = "VDEN", .description = "Velocity units denominator. Initially 10 for RPM.",
                 .powerUpValue = 10, .group = G::Units, .manualLines = "L7666, L1559"},
    VariableInfo{.name = "VE", .description = "Velocity error: VCMD - VFB.", .units = "VEL",
                 .unitClass = U::Velocity, .limits = None, .write = Never, .persistence = Volatile,
                 .group = G::Velocity, .manualLines = "L7667, L2040"},
    // Table E.1 prints VEL, but VEXT and VXAVG are scaled by the external units VXNUM/VXDEN.
    VariableInfo{.name = "VEXT", .description = "External velocity: frequency of the external input.",
                 .units = "VEL", .unitClass = U::ExtVelocity, .limits = None, .write = Never,
                 .persistence = Volatile, .group = G::Velocity, .manualLines = "L7668, L2929"},
    VariableInfo{.name = "VFB",
                 .description = "Velocity feedback, averaged over 1 millisecond; active even when disabled.",
                 .units = "VEL", .unitClass = U::Velocity, .limits = None, .write = Never,
                 .persistence = Volatile, .group = G::Velocity, .manualLines = "L7669, L2038"},
    // chosen: the 12-bit maximum, 7500 RPM
    VariableInfo{.name = "VMAX",
                 .description = "Maximum speed, set at the factory for the motor and the R/D resolution: at "
                                "most 7500 RPM with 12-bit, 3000 RPM 14-bit, 750 RPM 16-bit.",
                 .units = "VEL", .unitClass = U::Velocity, .limits = None, .write = Factory,
                 .powerUpValue = kVmax, .group = G::Limits, .manualLines = "L7670, L2046"},
    VariableInfo{.name = "VNUM", .description = "Velocity units numerator. Initially 44739 for RPM.",
                 .powerUpValue = 44739, .group = G::Units, .manualLines = "L7671, L1561"},
    VariableInfo{.name = "VOFF",
                 .description = "Gearbox velocity offset, added to the velocity command with GEAR on; reset "
                                "to 0 whenever GEAR is turned on.",
                 .units = "VEL", .unitClass = U::Velocity, .powerUpValue = 0, .group = G::Velocity,
                 .manualLines = "L7672, L1562, L3025-3031"},
    // chosen: 230 VAC drive
    VariableInfo{.name = "VOLTS", .description = "Drive voltage rating, set at the factory.",
                 .units = "Volts", .unitClass = U::Other, .limits = None, .write = Factory,
                 .powerUpValue = 230, .group = G::Limits, .manualLines = "L7673"},
    // 1.2 x VMAX = 9000 RPM x 44739 / 10 = 40265100. Table E.1 says Long; the text caps it at 1.2 VMAX
    // ("any level below 1.2 VMAX", L2048), which the initial value reaches, so the cap is inclusive.
    VariableInfo{.name = "VOSPD",
                 .description = "Overspeed setpoint: ERR 13 when VFB exceeds it; at most 1.2 VMAX. "
                                "Changeable only when disabled. Initially VMAX x 1.2.",
                 .units = "VEL", .unitClass = U::Velocity, .maximumVariable = "VMAX", .maximumPercent = 120,
                 .write = Disabled, .powerUpValue = 40265100,
                 .group = G::Limits, .manualLines = "L7674, L1563, L2048-2050"},
    VariableInfo{.name = "VXAVG", .description = "Averaged VEXT over 16 milliseconds. Cannot be recorded.",
                 .units = "VEL", .unitClass = U::ExtVelocity, .limits = None, .write = Never,
                 .persistence = Volatile, .group = G::Velocity, .recordable = false,
                 .manualLines = "L7675, L2931"},
    VariableInfo{.name = "VXDEN", .description = "External velocity units denominator. Initially VDEN.",
                 .powerUpValue = 10, .group = G::Units, .manualLines = "L7676, L1564"},
    VariableInfo{.name = "VXNUM", .description = "External velocity units numerator. Initially VNUM.",
                 .powerUpValue = 44739, .group = G::Units, .manualLines = "L7677, L1565"},
    VariableInfo{.name = "WATCH",
                 .description = "Enable serial watchdog: ERR 105 if no carriage return is received for "
                                "WTIME milliseconds.",
                 .limits = Switch, .powerUpValue = 0, .persistence = Volatile, .group = G::Communication,
                 .isSwitch = true, .manualLines = "L7678, L1566, L5328-5342"},
    VariableInfo{.name = "WTIME", .description = "Serial watchdog timeout. Initially 1000.", .units = "ms",
                 .unitClass = U::Time, .limits = ShortPositive, .powerUpValue = 1000,
                 .group = G::Communication, .manualLines = "L7679, L1567"},
    // v3: EXTDX on adds the extended user registers X251-X750; off, they are unknown (ERR 80, X(Xn) ERR 85).
    VariableInfo{.name = "X", .firstIndex = 1, .lastIndex = 250, .extendedLastIndex = 750, .extendedBy = "EXTDX",
                 .description = "User variables X1-X250, initially 0. X(Xn) refers indirectly to the "
                                "variable Xn points at (ERR 85 if none). Firmware v3: while EXTDX is on, the "
                                "extended user registers X251-X750 exist too (ERR 80 while it is off).",
                 .group = G::User, .manualLines = "L7680, L7682, L1572-1630, L9295-9297, L9309"},
    VariableInfo{.name = "XS", .firstIndex = 1, .lastIndex = 50,
                 .description = "User switches XS1-XS50, initially 0. XS1-XS10 may be used with H; none can "
                                "be recorded.",
                 .limits = Switch, .group = G::User, .isSwitch = true, .recordable = false,
                 .manualLines = "L7681, L1632-1645"},
    VariableInfo{.name = "Y", .description = "Special constant = 1 (same as ON).", .limits = None,
                 .write = Never, .powerUpValue = 1, .persistence = Volatile, .group = G::User,
                 .recordable = false, .manualLines = "L7683, L1647"},
    VariableInfo{.name = "ZERO",
                 .description = "Enable zeroing mode: the BDS5 drives the motor to the resolver zero "
                                "position (used only during installation).",
                 .limits = Switch, .powerUpValue = 0, .persistence = Volatile, .group = G::Switches,
                 .isSwitch = true, .manualLines = "L7684, L1570"},
};
// clang-format on

} // namespace

std::span<const VariableInfo> variables() {
    // Table E.1 first, then the rest; built once, contiguous so VariableRef::info can index into it.
    static const std::vector<VariableInfo> kAll = [] {
        std::vector<VariableInfo> all(kStandard.begin(), kStandard.end());
        const std::span<const VariableInfo> more = moreVariables();
        all.insert(all.end(), more.begin(), more.end());
        return all;
    }();
    return kAll;
}

} // namespace drive_core::catalog::bds5
