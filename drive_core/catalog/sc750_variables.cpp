// SC750 predefined variables and NV parameters (digest §5). Families (INPn, OUTn, INTR.*, TMENABLEn,
// TMOUT_n) are generated. Where the manual is silent (manual III missing) ranges/defaults are `chosen`.
#include "sc750_catalog.h"

#include <deque>
#include <string>
#include <vector>

namespace drive_core::catalog::sc750 {

namespace {

using enum ValueType;
constexpr Access RW = Access::ReadWrite;
constexpr Access RO = Access::ReadOnly;
constexpr Access NV = Access::Parameter;
constexpr double kBig = 2147483647.0;
constexpr double kPos = 134217727.0; // ±2^27 counts (L1416)

// clang-format off
const VariableInfo kFixed[] = {
    // §5.1 non-volatile set-up parameters (PARAMS START … END), defaults = boiler-plate L946–L973
    {"POLECOUNT", Integer, NV, 2, 64, 4, "poles", "motor pole count", "L946", true},
    {"ILC", Integer, NV, 0, 1000, 13, "0.1 ms", "current-loop PI zero (winding L/R), set by Controller Set Up", "L947, L2250", true},
    {"SIX.THRESH", Float, NV, 0, 1e6, 430.664063, "", "commutation threshold set by Controller Set Up", "L948", true},
    {"SIG.THRESH", Float, NV, 0, 1e6, 387.597656, "", "commutation threshold (0.9 x SIX.THRESH)", "L949", true},
    {"KVP", Float, NV, 0, 1000, 0.087086, "A/(rad/s)", "velocity-loop proportional gain", "L950, L1950", true},
    {"KVI", Float, NV, 0, 1000, 5.0, "Hz", "velocity-loop integral gain (the PI's corner)", "L951", true},
    {"ARF0", Float, NV, 1, 10000, 150.0, "Hz", "anti-resonant filter 0 (low-pass on the velocity error)", "L952, L2240", true},
    {"ARF1", Float, NV, 1, 10000, 750.0, "Hz", "anti-resonant filter 1 (low-pass on the velocity error)", "L959", true},
    {"KPP", Float, NV, 0, 1000, 15.0, "Hz", "position-loop proportional gain (bandwidth)", "L960", true},
    {"BLKTYPE", Integer, NV, 0, 3, 2, "", "servo block: 0 torque, 1 velocity, 2 program position, 3 analog position; changing it disables", "L961, L1930-L1956"},
    {"ILMT.PLUS", Integer, NV, 0, 100, 100, "%", "limit on CW torque current", "L962, L2073-L2079"},
    {"ILMT.MINUS", Integer, NV, 0, 100, 100, "%", "limit on CCW torque current", "L963, L2073-L2079"},
    {"DACMAP", Integer, NV, 0, 13, 1, "", "analog monitor source (DACMAP table); writing resets DMGAIN to 1", "L964, L2147-L2171"},
    {"DMGAIN", Float, NV, -1000, 1000, 1.0, "", "analog monitor gain; no effect when DACMAP = 0", "L965, L2169-L2171", true},
    {"CMDGAIN", Float, NV, -1000, 1000, 1.0, "", "analog command scale multiplier (BLKTYPE 0/1/3)", "L966, L1954", true},
    {"ITF0", Float, NV, 0.001, 100, 0.02, "Hz", "I.t filter", "L967", true},
    {"IT.THRESH", Integer, NV, 0, 100, 60, "%", "I.t threshold", "L968", true},
    {"KVFF", Float, NV, 0, 100, 0.0, "%", "velocity feed-forward gain, 100 = full", "L969", true},
    {"ADF0", Float, NV, 1, 10000, 1000.0, "Hz", "analog input low-pass corner", "L970, L2181", true},
    {"AD.OFFSET", Float, NV, -12, 12, 0.0, "V", "analog input offset", "L971", true},
    {"DMF0", Float, NV, 1, 10000, 1000.0, "Hz", "analog monitor low-pass corner", "L972, L2145", true},
    {"COMMOFF", Float, NV, -360, 360, 0.0, "deg", "commutation offset", "L973", true},
    {"AUTOSTART", Integer, NV, 0, 1, 0, "", "1 = run the downloaded program at power-on", "L2814-L2829", true},
    // §5.2 motion profile (power-up defaults chosen: L3515 program relies on sensible ones)
    {"ACCEL.RATE", Float, RW, 1, 1000000, 10000, "RPM/s", "acceleration (average for S-curve)", "L1325-L1335", true},
    {"DECEL.RATE", Float, RW, 1, 1000000, 10000, "RPM/s", "deceleration", "L1325-L1335", true},
    {"ACCEL.TYPE", Integer, RW, 0, 1, 0, "", "0 trapezoid, 1 S-curve", "L1337-L1358", true},
    {"RUN.SPEED", Float, RW, 0, 12000, 1000, "RPM", "GO.VEL speed, positioning traverse speed", "L1360-L1370", true},
    {"DIR", Integer, RW, 0, 1, 0, "", "GO.VEL direction: 0 CW, 1 CCW", "L1372-L1378", true},
    {"INDEX.DIST", Integer, RW, -kBig, kBig, 0, "counts", "GO.INCR distance", "L1384-L1390", true},
    {"TARGET.POS", Integer, RW, -kPos, kPos, 0, "counts", "GO.ABS target", "L1394-L1398", true},
    {"PAUSE.TIME", Float, RW, 0, 1833751, 0, "s", "PAUSE delay", "L2036", true},
    {"IN.POS.LIMIT", Integer, RW, 0, kBig, 10, "counts", "in-position tolerance for IN.POSITION", "L2965, L3374", true},
    {"POS.ERROR.MOVING", Integer, RW, 0, kBig, 4096, "counts", "POS.ERROR interrupt threshold while moving", "L1861", true},
    {"POS.ERROR.STOPPED", Integer, RW, 0, kBig, 1024, "counts", "POS.ERROR interrupt threshold at rest", "L1861", true},
    {"CW.OT.LIMIT", Integer, RW, -kPos, kPos, kPos, "counts", "CWOT interrupt while POSITION is clockwise of it (name chosen)", "L1854", true},
    {"CCW.OT.LIMIT", Integer, RW, -kPos, kPos, -kPos, "counts", "CCWOT interrupt while POSITION is counter-clockwise of it (name chosen)", "L1845", true},
    // §5.3 position, velocity, status
    {"POS.COMMAND", Integer, RW, -kPos, kPos, 0, "counts", "position command; writing redefines the present position", "L1412-L1416"},
    {"POSITION", Integer, RO, -kPos, kPos, 0, "counts", "actual position relative to electrical home", "L1418-L1420"},
    {"POS.ERROR", Integer, RO, -kBig, kBig, 0, "counts", "POS.COMMAND - POSITION", "L1422"},
    {"RESPOS", Integer, RO, 0, 4095, 0, "counts", "resolver angle within one revolution", "L1408-L1410"},
    {"VELOCITY", Float, RO, -12000, 12000, 0, "RPM", "motor speed, 128 ms average", "L1400-L1402"},
    {"RVEL", Float, RO, -12000, 12000, 0, "RPM", "raw resolver velocity", "L1982", true},
    {"MOVING", Integer, RO, 0, 1, 0, "", "1 while a commanded profile runs", "L3456, L3578", true},
    {"IN.POSITION", Integer, RO, 0, 1, 1, "", "1 when no profile runs and |POS.ERROR| <= IN.POS.LIMIT", "L3166, L3386", true},
    {"ENABLE", Integer, RW, 0, 1, 0, "", "software enable, 0 at power-up", "L1500-L1512"},
    {"ENABLED", Integer, RO, 0, 1, 0, "", "ENABLE and hardware enable and no fault", "L1518-L1520"},
    {"FAULTCODE", Integer, RO, 0, 246, 0, "", "status/fault code (display)", "L1522-L1588"},
    {"TIME", Float, RW, 0, 1833751, 0, "s", "free-running timer, 0.427 ms ticks", "L2046-L2059"},
    {"MODEL", Integer, RO, 750, 756, 752, "", "controller model number", "L2196", true},
    {"FWV", Float, RO, 0, 100, 2.8, "", "firmware version", "L2200", true},
    {"AXIS.ADDR", Integer, RO, 0, 255, 255, "", "S1 address, 255 = RS-232", "L3682, L3698"},
    {"LOGGEDON", Integer, RO, 0, 1, 1, "", "this unit is the logged-on multidrop unit", "L3686, L3716"},
    {"VEL.CMD", Float, RO, -12000, 12000, 0, "RPM", "net velocity command (the velocity loop's input)", "L2147-L2161", true},
    {"VEL.ERR", Float, RO, -24000, 24000, 0, "RPM", "velocity error", "L2147-L2161", true},
    {"ICMD", Float, RO, -100, 100, 0, "A", "torque current command", "L2147-L2161", true},
    {"IFB", Float, RO, -100, 100, 0, "A", "measured torque current", "L2147-L2161", true},
    // §5.4 gearing and encoder
    {"GEARING", Integer, RW, 0, 3, 0, "", "0 off, 1 on, 2 CW only, 3 CCW only", "L1636-L1644"},
    {"ENC.IN", Integer, RW, 1, 65535, 1024, "lines", "master encoder line count", "L1609-L1612", true},
    {"RATIO", Float, RW, -1000, 1000, 1, "", "motor revs per master rev", "L1617", true},
    {"PULSES.IN", Integer, RW, 1, kBig, 1, "pulses", "gear ratio numerator input", "L1620", true},
    {"PULSES.OUT", Integer, RW, -kBig, kBig, 1, "counts", "gear ratio output counts", "L1620", true},
    {"ACCEL.GEAR", Float, RW, 1, 1000000, 10000, "RPM/s", "gearing engage acceleration", "L1605-L1607", true},
    {"DECEL.GEAR", Float, RW, 1, 1000000, 10000, "RPM/s", "gearing disengage deceleration", "L1607, L1671", true},
    {"GEARLOCK", Integer, RO, 0, 1, 0, "", "slave synchronised to master", "L1650-L1654"},
    {"GEARERROR", Integer, RW, -kBig, kBig, 0, "counts", "lag accumulated during lock-in", "L1650-L1663"},
    {"ENC.FREQ", Float, RO, -1e7, 1e7, 0, "counts/s", "master encoder frequency", "L1626-L1630"},
    {"ENCPOS", Integer, RW, -kBig, kBig, 0, "counts", "master encoder position, 1.024 ms updates", "L1632-L1634"},
    {"ENC.OUT", Integer, RW, 0, 65535, 0, "lines", "0 encoder input, N emulate N-line encoder output", "L1675-L1685"},
    {"COUNTER", Integer, RW, 0, 32767, 0, "", "input 16 event counter, reset by input 15", "L2102-L2104"},
    // §5.5 registration
    {"REG.MODE", Integer, RW, 0, 3, 0, "", "registration trigger sources", "L1711-L1720"},
    {"REG.FUNC", Integer, RW, 0, 1, 0, "", "1 = move REG.DIST on resolver registration", "L1722-L1731"},
    {"REG.DIST", Integer, RW, -kBig, kBig, 0, "counts", "registration move distance", "L1727"},
    {"REG.FLAG", Integer, RW, 0, 3, 0, "", "1 encoder, 2 resolver registration occurred; write 0 to arm", "L1733-L1751"},
    {"REG.POS", Integer, RO, -kPos, kPos, 0, "counts", "latched position", "L1705"},
    {"REG.RESPOS", Integer, RO, 0, 4095, 0, "counts", "latched resolver angle", "L1705"},
    {"REG.ENCPOS", Integer, RO, -kBig, kBig, 0, "counts", "latched encoder position", "L1709"},
    // §5.6 WHEN latches
    {"WHEN.PCMD", Integer, RO, -kPos, kPos, 0, "counts", "POS.COMMAND latched by WHEN", "L1976-L1987"},
    {"WHEN.POS", Integer, RO, -kPos, kPos, 0, "counts", "POSITION latched by WHEN", "L1976-L1987"},
    {"WHEN.ENCPOS", Integer, RO, -kBig, kBig, 0, "counts", "ENCPOS latched by WHEN", "L1976-L1987"},
    {"WHEN.RESPOS", Integer, RO, 0, 4095, 0, "counts", "RESPOS latched by WHEN", "L1976-L1987"},
    {"WHEN.RVEL", Float, RO, -12000, 12000, 0, "RPM", "RVEL latched by WHEN", "L1976-L1987"},
    {"WHEN.TIME", Float, RO, 0, 1833751, 0, "s", "TIME latched by WHEN", "L1976-L1987"},
    {"WHEN.ANALOG.IN", Float, RO, -12, 12, 0, "V", "ANALOG.IN latched by WHEN", "L1976-L1987"},
    {"WHEN.DACMON", Float, RO, -5, 5, 0, "V", "DACMON latched by WHEN", "L1976-L1987"},
    {"WHEN.ICMD", Float, RO, -100, 100, 0, "A", "ICMD latched by WHEN", "L1976-L1987"},
    {"WHEN.IFB", Float, RO, -100, 100, 0, "A", "IFB latched by WHEN", "L1976-L1987"},
    {"WHEN.VELCMD", Float, RO, -12000, 12000, 0, "RPM", "VEL.CMD latched by WHEN", "L1976-L1987"},
    // §5.7 discrete I/O (families follow)
    {"INPUTS", Integer, RO, 0, 65535, 65535, "", "all 16 inputs, input n = bit n-1", "L2087-L2097"},
    {"OUTPUTS", Integer, RW, 0, 4095, 4095, "", "all 12 outputs, 0 = on (sinking)", "L2106-L2118"},
    {"PWM12", Integer, RW, 0, 100, 100, "%", "output 12 PWM off time at 11.8 kHz", "L2120-L2128"},
    // §5.8 analog
    {"ANALOG.OUT", Float, RW, -5, 5, 0, "V", "analog output when DACMAP = 0", "L2136, L2173"},
    {"ANALOG.IN", Float, RO, -12, 12, 0, "V", "analog input, ADF0-filtered", "L2177-L2181"},
    {"DACMON", Float, RO, -5, 5, 0, "V", "analog monitor after DMF0", "L2145"},
    // §5.10 PacLAN
    {"AXIS.INTR", Integer, RO, 0, 255, 0, "", "axis that sent the last PacLAN interrupt", "L2380"},
};
// clang-format on

struct Table {
    std::deque<std::string> names; // storage for generated names
    std::vector<VariableInfo> all;
};

const Table& table() {
    static const Table built = [] {
        Table t;
        t.all.assign(std::begin(kFixed), std::end(kFixed));
        auto add = [&t](std::string name, VariableInfo info) {
            t.names.push_back(std::move(name));
            info.name = t.names.back();
            t.all.push_back(info);
        };
        for (int n = 1; n <= 16; ++n)
            add("INP" + std::to_string(n),
                {"", Integer, RO, 0, 1, 1, "", "input level (unconnected = 1)", "L2085-L2099"});
        for (int n = 1; n <= 12; ++n)
            add("OUT" + std::to_string(n), {"", Integer, RW, 0, 1, 1, "", "output, 0 = on (sinking)", "L2110-L2112"});
        for (const InterruptSourceInfo& s : interruptSources())
            add("INTR." + std::string(s.label),
                {"", Integer, RW, 0, 1, 0, "", "interrupt enable, cleared when taken", "L1865-L1893"});
        for (int n = 1; n <= 6; ++n)
            add("TMENABLE" + std::to_string(n), {"", Integer, RW, 0, 1, 0, "", "software timer enable", "L2228-L2234"});
        for (int n = 1; n <= 6; ++n)
            add("TMOUT_" + std::to_string(n), {"", Integer, RO, 0, 1, 0, "", "software timer output state", "L2236"});
        return t;
    }();
    return built;
}

} // namespace

std::span<const VariableInfo> variables() {
    return table().all;
}

} // namespace drive_core::catalog::sc750
