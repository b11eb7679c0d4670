// PMC-960 MPL commands: the 21 commands of 5.1 (L639-711) as their 60 leaf forms — 18 plain commands,
// OA/OB, 13 S, TF, 8 TG registers, 9 TH, 3 TL and 6 TU parameters (digest §5.6). Syntax as in 7.x, OCR fixed.
#include "pmc960_catalog.h"

#include <algorithm>
#include <array>

namespace drive_core::catalog::pmc960 {
namespace {

using C = CommandGroup;
constexpr unsigned kQ = kStored, kB = kCurrent, kP = kStream, kE = kAtError, kS = kStop;

// clang-format off
constexpr std::array kCommands{
    CommandInfo{"@", "LABEL", "@<label><text><cr>", C::Label, 0, "Marks the start of a routine; the text after the label up to <cr> is a comment. @. starts a comment line. Labels do not end a routine: execution falls through.", "L1026-1057"},
    CommandInfo{"A", "ACCELERATION", "A<rate><cr> | A<display>", C::MotionParameter, kQ | kB | kP, "Sets the acceleration in the motion buffer, used by Index, Go, Jog and Cam. A! is the current acceleration (0 at rest or top speed).", "L1059-1073"},
    CommandInfo{"B", "BRANCH", "B<label>[<hex>[:<mask>]][<sync>]<cr> | B|<cr>", C::ProgramControl, 0, "Transfers execution to <label> with no return, if the input condition on IN07'-IN00' holds. From the terminal it starts the program at <label>. B| uses the TLB label.", "L1075-1091, L723"},
    CommandInfo{"C", "CAM", "C[<sign>]<position>[:<speed>]<cr> | C[<sign>]<position>[:<speed>]^ | C^ | C*", C::MotionAction, kS, "Executes a cam segment: reach <speed> by the time absolute <position> is reached. ^ waits for the running segment to complete first. C* stops.", "L1095-1117, L1684"},
    CommandInfo{"D", "DWELL", "D[<time>][<sync>]<cr>", C::Synchronization, 0, "Waits <time> ms (0-65535) on the 4 ms clock: D1 lasts 4-8 ms, D0 less than 1 ms.", "L1119-1134"},
    CommandInfo{"E", "EXIT", "E[<hex>[:<mask>]][<sync>]<cr>", C::ProgramControl, 0, "Returns to the statement after the calling F if the input condition holds. Valid only during program execution.", "L1136-1149"},
    CommandInfo{"F", "FUNCTION CALL", "F<label>[<hex>[:<mask>]][<sync>]<cr>", C::ProgramControl, 0, "Calls the routine at <label> (GOSUB) if the input condition holds; E returns.", "L1151-1163"},
    CommandInfo{"G", "GO", "G[<position>][<sync>]<sign><cr> | G* | G<display>", C::MotionAction, kQ | kB | kP | kE | kS, "Moves to an absolute position at the motion-buffer A and V. The sign sets the sign of the position and starts the move. G* stops at once (no <cr>). G! is the actual position, G? the commanded one.", "L1165-1189"},
    CommandInfo{"H", "HOME", "H[<location>][<sync>][<direction>]<cr> | H[<sync>]<direction> (encoder) | H* | H<display>", C::MotionAction, kQ | kB | kP | kS, "Moves at the TUH home speed until the resolver reads <location> (resolver) or the encoder marker / SENSOR is seen (encoder). With an encoder the direction ends the command; H* stops at once (no <cr>).", "L1191-1250"},
    CommandInfo{"I", "INDEX", "I[<distance>]#<direction>#[<sync>]<cr> | I<display>", C::MotionAction, kQ | kB | kP | kS, "Stores a relative distance; + or - moves it at A and V. Several directions and syncs may follow on one line (I,+,-). I! is the distance still to go.", "L1252-1260"},
    CommandInfo{"J", "JOG", "J[<speed>]#<direction>#[<sync>]<cr> | J<display>", C::MotionAction, kQ | kB | kP | kS, "Jogs at <speed> (or the stored jog speed) in the direction given; * stops. While the J line is open any other character stops the jog.", "L1262-1296"},
    CommandInfo{"L", "LOOP", "L<label>[X|Y|Z]<count><cr> | L<cr>", C::ProgramControl, 0, "Jumps back to <label> <count> times using the default or the X, Y or Z counter; L<cr> resets the counter. From the terminal it runs <label> with <count> replacing the first loop count.", "L1300-1340"},
    CommandInfo{"N", "NORMALIZE", "N[<position>][<sync>]<sign> | N* | N<cr>", C::System, 0, "+/- sets the absolute position counter to +/-<position> at rest; N* resets the software (EPROM copy, power-up routine); N<cr> runs autobaud and prints the firmware identifier.", "L1342-1363"},
    CommandInfo{"OA", "OUTPUT ANALOG", "OA<value><sign><cr> | OA<display>", C::Output, kQ | kB, "Sets AOUT: <value> 0-2047 = 0-10 V, polarity from the sign.", "L1365-1381"},
    CommandInfo{"OB", "OUTPUT BINARY", "OB<hex>[:<mask>]<cr> | OB<display>", C::Output, kQ | kB | kE, "Sets OUT15'-OUT00': bit 1 = active (low). Only the masked bits change (default mask FFFF).", "L1383-1396"},
    CommandInfo{"P", "PROGRAM", "P{ | P<cr> | P<label> | P? | P!", C::ProgramControl, 0, "Enters the program buffer editor at the start, the end or a label (needs SW1), or lists the buffer (P? line by line, P! whole).", "L1398-1439, L921-930"},
    CommandInfo{"Q", "QUIT", "Q[<hex>[:<mask>]][<sync>]<cr>", C::ProgramControl, 0, "Stops program execution and returns to READY if the input condition holds.", "L662, L741"},
    CommandInfo{"R", "CONTOUR", "R<tick><count>[<tick><count>...]<cr>", C::MotionAction, 0, "Moves <count> counts linearly in each tick; the PMC prints } when it can accept the next segment. Tick 0 ends the contour.", "L1441-1460, L2155-2284"},
    CommandInfo{"U", "UNTIL", "U[<hex>[:<mask>]][<sync>]<cr>", C::Synchronization, 0, "Waits until the input condition on IN07'-IN00' is true.", "L2128-2138"},
    CommandInfo{"V", "VELOCITY", "V<speed><cr> | V<display>", C::MotionParameter, kQ | kB | kP | kE, "Sets the Index/Go speed in the motion buffer. V! is the current speed.", "L2140-2153"},

    CommandInfo{"SB", "LAST LABEL", "SB<display>", C::System, kQ | kB | kE, "Last @ label passed and the number of commands executed since.", "L1466-1474"},
    CommandInfo{"SD", "ADAPTIVE DEPTH", "SD<depth><cr> | SD<display>", C::System, kQ | kB, "Stop distance after SENSOR for adaptive depth control (3-65535 counts).", "L1476-1492"},
    CommandInfo{"SE", "LAST ERROR", "SE<display>", C::System, kQ | kB | kE, "The last error code as a hex byte.", "L1494-1503"},
    CommandInfo{"SF", "FOLLOWING ERROR", "SF<value><cr> | SF<display>", C::System, kQ | kB | kP, "Following-error trip point (1-32767, rounded up to a power of 2, 2048 at power-up). SF! is the position error.", "L1505-1517"},
    CommandInfo{"SI", "SYSTEM INPUTS", "SI[<bank>]<display>", C::System, kQ | kB | kP | kE, "General purpose inputs in hex (bank only with THM).", "L1519-1530"},
    CommandInfo{"SL", "SOFTWARE LIMITS", "SL<F|R><position>[<sign>]<cr> | SL<display>", C::System, kQ | kB, "Forward and reverse software travel limits, enabled by THS1.", "L1532-1575"},
    CommandInfo{"SM", "SYSTEM MODE", "SM<mode><cr> | SM<display>", C::System, kQ | kB | kE, "0 idle, 1 velocity, 2 position (PSJ reset), 3 position (no reset).", "L1577-1601"},
    CommandInfo{"SN", "NORMALIZATION ERROR", "SN<display>", C::System, kQ | kB, "The position error cancelled by the last N.", "L1603-1610"},
    CommandInfo{"SP", "PROFILE", "SP<hex><cr> | SP<display>", C::System, kQ | kB, "Motion profile bits: FPS, adaptive depth, external start/select, external decel, stop select, index extend, sharp jog stop.", "L1612-1631"},
    CommandInfo{"SS", "SNAPSHOT", "SS<display>", C::System, kQ | kB | kP | kE, "Motion snapshot bits: DRVON, FPS, CAM HOLD, MOTION, TOP VELOCITY, DIRECTION.", "L1633-1653"},
    CommandInfo{"ST", "TORQUE", "ST<torque><cr> | ST<display>", C::System, kQ | kB, "Torque at positive stop in 0.1 % (0-1000).", "L1655-1688"},
    CommandInfo{"SV", "FEEDRATE OVERRIDE", "SV<value><cr> | SV<display>", C::System, kQ | kB, "Percentage (1-100) of the programmed speed actually run.", "L1690-1699"},
    CommandInfo{"SW", "WRITE ENABLE", "SW<0|1><cr> | SW<display>", C::System, kQ | kB, "Enables changes to the program buffer and the parameter table; 0 at power-up.", "L1701-1711"},

    CommandInfo{"TF", "FEEDFORWARD GAINS", "TF<display>", C::Table, kQ | kB, "Feedforward gains per velocity range: 48-<g> 192-<g> 384-<g> Ext-<g>.", "L1721-1739"},
    CommandInfo{"TGP", "POSITION LOOP GAIN", "TGP[<value>]<sign|cr>", C::Table, kQ | kB, "PLGAIN, 0-255.", "L1741-1773"},
    CommandInfo{"TGV", "VELOCITY LOOP GAIN", "TGV[<value>]<sign|cr>", C::Table, kQ | kB, "VLGAIN, 0-255.", "L1741-1773"},
    CommandInfo{"TGT", "TACH GAIN", "TGT[<value>]<sign|cr>", C::Table, kQ | kB, "TGAIN, 0-255.", "L1741-1773"},
    CommandInfo{"TGF", "FEEDFORWARD GAIN", "TGF[<value>]<sign|cr>", C::Table, kQ | kB, "FFGAIN, 0-255; the other ranges are computed (TF).", "L1741-1773"},
    CommandInfo{"TGE", "POSITION COMPENSATION", "TGE[<hex>]<sign|cr>", C::Table, kQ | kB, "PLCOMP in hex; break frequency PLCOMP/67 Hz.", "L1741-1773, L629"},
    CommandInfo{"TGB", "VELOCITY COMPENSATION", "TGB[<hex>]<sign|cr>", C::Table, kQ | kB, "VLCOMP in hex; break frequency VLCOMP/20 Hz.", "L1741-1773, L603"},
    CommandInfo{"TGX", "EXTERNAL REFERENCE GAIN", "TGX[<value>]<sign|cr>", C::Table, kQ | kB, "XGAIN, 0-255.", "L1741-1773"},
    CommandInfo{"TGL", "ANALOG LOCK GAIN", "TGL[<value>]<sign|cr>", C::Table, kQ | kB, "ALGAIN, 0-255.", "L1741-1773"},
    CommandInfo{"THA", "RESOLVER SIZE", "THA<value><cr>", C::Table, kQ | kB, "Counts per revolution 4096-65535; 0 selects encoder feedback.", "L1795-1804"},
    CommandInfo{"THB", "BAUD RATE", "THB<0-8><cr>", C::Table, kQ | kB, "0 autobaud, 1 38400 ... 8 300 baud.", "L1806-1826"},
    CommandInfo{"THC", "COMMUNICATIONS FORMAT", "THC<hex><cr>", C::Table, kQ | kB, "Bits 7-6 number format, 4 engineering units, 2 single step, 1 trace, 0 no echo.", "L1828-1910"},
    CommandInfo{"THI", "AXIS ID", "THI<id><cr>", C::Table, kQ | kB, "Axis ID: prompt character and multi-axis address.", "L1912-1918"},
    CommandInfo{"THL", "HARDWARE LIMITS", "THL<0|1><cr>", C::Table, kQ | kB, "IN07' = + limit, IN06' = - limit (section lost in the seed).", "L1787, L1001-1005"},
    CommandInfo{"THM", "MUXED INPUTS", "THM<0|1><cr>", C::Table, kQ | kB, "Enables muxed input banks for SI (section lost in the seed).", "L1788, L702"},
    CommandInfo{"THP", "PROGRAM PROTECTION", "THP<0|1><cr>", C::Table, kQ | kB, "IN05' must be asserted (besides SW1) to edit the program.", "L1944-1951"},
    CommandInfo{"THR", "MOTION REFERENCE", "THR<hex><cr>", C::Table, kQ | kB, "Bits 7 master, 6 slave, 4 direction invert, 3-2 acceleration profile.", "L1966-2001"},
    CommandInfo{"THS", "SOFTWARE LIMITS ENABLE", "THS<0|1><cr>", C::Table, kQ | kB, "Enables the SL software limits.", "L2003-2014"},
    CommandInfo{"TLB", "BRANCH LABEL", "TLB<label><cr>", C::Table, kQ | kB, "Label used by B|.", "L2016-2033"},
    CommandInfo{"TLP", "POWER-UP LABEL", "TLP<label><cr>", C::Table, kQ | kB, "Routine run at power-up and after N*.", "L2016-2033"},
    CommandInfo{"TLV", "EXEC LABEL", "TLV<label><cr>", C::Table, kQ | kB, "Routine run on an EXEC' high-to-low edge.", "L2016-2033"},
    CommandInfo{"TUA", "ACCELERATION UNITS", "TUA<int[:frac]><cr>", C::Table, kQ | kB, "Hz/s per user acceleration unit.", "L2050-2063"},
    CommandInfo{"TUB", "MAXIMUM ACCELERATION", "TUB<value><cr>", C::Table, kQ | kB, "Maximum acceleration; also the emergency and limit decel rate.", "L2065-2074"},
    CommandInfo{"TUH", "HOME SPEED", "TUH<value><cr>", C::Table, kQ | kB, "Home speed in user velocity units.", "L2076-2085"},
    CommandInfo{"TUP", "POSITION UNITS", "TUP<int[:frac]><cr>", C::Table, kQ | kB, "Counts per user position unit.", "L2087-2100"},
    CommandInfo{"TUS", "VELOCITY UNITS", "TUS<int[:frac]><cr>", C::Table, kQ | kB, "Hz per user velocity unit.", "L2102-2115"},
    CommandInfo{"TUV", "MAXIMUM VELOCITY", "TUV<value><cr>", C::Table, kQ | kB, "Maximum velocity in user units; TUS x TUV < 384000.", "L2117-2126"},
};
// clang-format on
static_assert(kCommands.size() == 60, "digest §5.6: 60 command forms");

} // namespace

std::span<const CommandInfo> commands() {
    return kCommands;
}

const CommandInfo* findCommand(std::string_view upperName) {
    const auto it = std::find_if(kCommands.begin(), kCommands.end(),
                                 [upperName](const CommandInfo& c) { return c.name == upperName; });
    return it == kCommands.end() ? nullptr : &*it;
}

} // namespace drive_core::catalog::pmc960
