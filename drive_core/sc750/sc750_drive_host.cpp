// The simulated SC750 as the VM's host: predefined variables (computed ones and write side effects),
// motion statements, WHEN sampling/latching/actions, software timers and interrupt sources.
#include "sc750_drive.h"
#include "sc750_drive_index.h"

#include <cmath>

namespace drive_core::sc750 {

namespace cat = catalog::sc750;

const DriveIndex& driveIndex() {
    static const DriveIndex index = [] {
        auto at = [](const char* name) { return cat::variableIndex(name); };
        DriveIndex i{};
        i.enable = at("ENABLE");
        i.enabled = at("ENABLED");
        i.faultcode = at("FAULTCODE");
        i.poscmd = at("POS.COMMAND");
        i.position = at("POSITION");
        i.poserror = at("POS.ERROR");
        i.respos = at("RESPOS");
        i.velocity = at("VELOCITY");
        i.rvel = at("RVEL");
        i.velcmd = at("VEL.CMD");
        i.moving = at("MOVING");
        i.inposition = at("IN.POSITION");
        i.inposlimit = at("IN.POS.LIMIT");
        i.time = at("TIME");
        i.axisaddr = at("AXIS.ADDR");
        i.loggedon = at("LOGGEDON");
        i.accel = at("ACCEL.RATE");
        i.decel = at("DECEL.RATE");
        i.speed = at("RUN.SPEED");
        i.dir = at("DIR");
        i.indexdist = at("INDEX.DIST");
        i.target = at("TARGET.POS");
        i.pausetime = at("PAUSE.TIME");
        i.inputs = at("INPUTS");
        i.outputs = at("OUTPUTS");
        i.pwm12 = at("PWM12");
        i.inp1 = at("INP1");
        i.out1 = at("OUT1");
        i.intr0 = at("INTR.CCWINH");
        i.tmenable1 = at("TMENABLE1");
        i.tmout1 = at("TMOUT_1");
        i.whenPcmd = at("WHEN.PCMD");
        i.whenPos = at("WHEN.POS");
        i.whenEncpos = at("WHEN.ENCPOS");
        i.whenRespos = at("WHEN.RESPOS");
        i.whenRvel = at("WHEN.RVEL");
        i.whenTime = at("WHEN.TIME");
        i.whenAnalog = at("WHEN.ANALOG.IN");
        i.whenDacmon = at("WHEN.DACMON");
        i.whenIcmd = at("WHEN.ICMD");
        i.whenIfb = at("WHEN.IFB");
        i.whenVelcmd = at("WHEN.VELCMD");
        i.encpos = at("ENCPOS");
        i.encfreq = at("ENC.FREQ");
        i.analogin = at("ANALOG.IN");
        i.ratio = at("RATIO");
        i.dacmap = at("DACMAP");
        i.dmgain = at("DMGAIN");
        i.blktype = at("BLKTYPE");
        i.autostart = at("AUTOSTART");
        i.gearing = at("GEARING");
        i.acceltype = at("ACCEL.TYPE");
        i.regmode = at("REG.MODE");
        i.regfunc = at("REG.FUNC");
        i.regdist = at("REG.DIST");
        i.regflag = at("REG.FLAG");
        i.regpos = at("REG.POS");
        i.regrespos = at("REG.RESPOS");
        i.regencpos = at("REG.ENCPOS");
        i.gearlock = at("GEARLOCK");
        i.gearerror = at("GEARERROR");
        i.encin = at("ENC.IN");
        i.pulsesin = at("PULSES.IN");
        i.pulsesout = at("PULSES.OUT");
        i.accelgear = at("ACCEL.GEAR");
        i.decelgear = at("DECEL.GEAR");
        i.dacmon = at("DACMON");
        i.adf0 = at("ADF0");
        i.adoffset = at("AD.OFFSET");
        i.dmf0 = at("DMF0");
        i.encout = at("ENC.OUT");
        i.analogout = at("ANALOG.OUT");
        i.cwot = at("CW.OT.LIMIT");
        i.ccwot = at("CCW.OT.LIMIT");
        i.poserrmoving = at("POS.ERROR.MOVING");
        i.poserrstopped = at("POS.ERROR.STOPPED");
        i.kvp = at("KVP");
        i.kvi = at("KVI");
        i.kpp = at("KPP");
        i.kvff = at("KVFF");
        i.arf0 = at("ARF0");
        i.arf1 = at("ARF1");
        i.ilc = at("ILC");
        i.ilmtplus = at("ILMT.PLUS");
        i.ilmtminus = at("ILMT.MINUS");
        i.cmdgain = at("CMDGAIN");
        i.itf0 = at("ITF0");
        i.itthresh = at("IT.THRESH");
        i.model = at("MODEL");
        i.velerr = at("VEL.ERR");
        i.icmd = at("ICMD");
        i.ifb = at("IFB");
        i.reading.assign(cat::variables().size(), Reading::Stored);
        auto reads = [&i](int k, Reading r) { i.reading[std::size_t(k)] = r; };
        reads(i.poscmd, Reading::PosCmd);
        reads(i.position, Reading::Position);
        reads(i.poserror, Reading::PosError);
        reads(i.respos, Reading::ResPos);
        reads(i.velocity, Reading::Velocity);
        reads(i.rvel, Reading::Rvel);
        reads(i.velcmd, Reading::VelCmd);
        reads(i.velerr, Reading::VelErr);
        reads(i.icmd, Reading::Icmd);
        reads(i.ifb, Reading::Ifb);
        reads(i.moving, Reading::Moving);
        reads(i.inposition, Reading::InPosition);
        reads(i.analogin, Reading::AnalogIn);
        reads(i.dacmon, Reading::Dacmon);
        reads(i.enabled, Reading::Enabled);
        reads(i.faultcode, Reading::FaultCode);
        reads(i.time, Reading::Time);
        reads(i.axisaddr, Reading::AxisAddr);
        reads(i.loggedon, Reading::LoggedOn);
        reads(i.inputs, Reading::Inputs);
        for (int n = 0; n < 16; ++n) reads(i.inp1 + n, Reading::Input);
        for (int n = 0; n < 12; ++n) reads(i.out1 + n, Reading::Output);
        reads(i.encpos, Reading::EncPos);
        reads(i.gearlock, Reading::GearLock);
        reads(i.gearerror, Reading::GearError);
        reads(i.encfreq, Reading::EncFreq);
        return i;
    }();
    return index;
}

GearSettings Sc750Drive::gearSettings() const {
    if (m_gearSettingsVersion != m_valuesVersion) { // m_ratioFromPulses changes with a write too
        m_gearSettingsVersion = m_valuesVersion;
        const DriveIndex& x = ix();
        // the last of RATIO and PULSES.IN/PULSES.OUT written defines the ratio (L1622-L1624)
        const double ratio = m_ratioFromPulses ? num(x.pulsesout) / num(x.pulsesin)
                                               : num(x.ratio) * kCountsPerRev / (4 * num(x.encin));
        m_gearSettings = GearSettings{int(num(x.gearing)), 0, ratio, num(x.accelgear), num(x.decelgear)};
    }
    GearSettings g = m_gearSettings;
    g.master_cps = m_masterFrequency;
    return g;
}

MoveSettings Sc750Drive::settings() const {
    return MoveSettings{num(ix().accel), num(ix().decel), num(ix().speed), int(num(ix().dir)),
                        num(ix().acceltype) == 1};
}

double Sc750Drive::pauseTime_s() {
    return num(ix().pausetime);
}

Value Sc750Drive::readVariable(int i) {
    const DriveIndex& x = ix();
    auto integer = [](double v) { return Value(std::int32_t(std::llround(v))); };
    auto flag = [](bool on) { return Value(std::int32_t(on ? 1 : 0)); };
    // POSITION is the plant's shaft in POS.COMMAND's coordinates, to the nearest count (DECISIONS 50)
    const auto pcmd = [this] { return m_motion.positionCommand_counts(); };
    switch (x.reading[std::size_t(i)]) {
    case Reading::Stored: break;
    case Reading::PosCmd: return integer(pcmd());
    case Reading::Position: return integer(pcmd() - lag_counts());
    case Reading::PosError: return Value(std::int32_t(std::llround(pcmd()) - std::llround(pcmd() - lag_counts())));
    case Reading::ResPos: {
        const auto counts = std::llround(m_actual_counts);
        return Value(std::int32_t(((counts % 4096) + 4096) % 4096));
    }
    case Reading::Velocity: return Value(float(m_servo.averageVelocity_cps() / kCpsPerRpm));
    case Reading::Rvel: return Value(float(m_servo.velocity_cps() / kCpsPerRpm));
    case Reading::VelCmd: return Value(float(m_servo.velocityCommand_cps() / kCpsPerRpm));
    case Reading::VelErr: return Value(float(m_servo.velocityError_cps() / kCpsPerRpm));
    case Reading::Icmd: return Value(float(m_servo.currentCommand_A()));
    case Reading::Ifb: return Value(float(m_servo.current_A()));
    case Reading::Moving: return flag(m_motion.moving());
    case Reading::InPosition:
        return flag(!m_motion.moving() && std::abs(toDouble(readVariable(x.poserror))) <= num(x.inposlimit));
    case Reading::AnalogIn: return Value(float(m_analogInFiltered_V));
    case Reading::Dacmon: return Value(float(m_dacmon_V));
    case Reading::Enabled: return flag(enabled());
    case Reading::FaultCode: return Value(std::int32_t(faultCode()));
    case Reading::Time: return Value(float(double(m_ticks - m_timeBase) * kTick_s + m_timeOffset_s));
    case Reading::AxisAddr: return Value(std::int32_t(m_axis));
    case Reading::LoggedOn: return flag(m_loggedOn);
    case Reading::Inputs: {
        std::int32_t bits = 0;
        for (int n = 1; n <= 16; ++n) bits |= (input(n) ? 1 : 0) << (n - 1);
        return Value(bits);
    }
    case Reading::Input: return flag(input(i - x.inp1 + 1));
    case Reading::Output: return flag(!output(i - x.out1 + 1));
    case Reading::EncPos: return integer(m_encoderPosition);
    case Reading::GearLock: return flag(m_motion.gearLocked());
    case Reading::GearError: return integer(m_motion.gearError_counts());
    case Reading::EncFreq: return Value(float(m_masterFrequency));
    }
    return m_values[std::size_t(i)];
}

std::string Sc750Drive::writeVariable(int i, const Value& value) {
    const DriveIndex& x = ix();
    const cat::VariableInfo& info = cat::variables()[std::size_t(i)];
    const double v = toDouble(value);
    if (info.type != cat::ValueType::String && (v < info.minimum || v > info.maximum))
        return "VALUE OUT OF RANGE FOR " + std::string(info.name);
    if (i == x.poscmd) {
        m_motion.setPositionCommand(v); // redefines the present position (L1412-L1416)
        return "";
    }
    if (i == x.time) {
        m_timeBase = m_ticks;
        m_timeOffset_s = v;
        return "";
    }
    if (i == x.encpos) {
        m_encoderPosition = v;
        return "";
    }
    if (i == x.gearerror) {
        m_motion.setGearError(v);
        return "";
    }
    if (i == x.ratio) m_ratioFromPulses = false;
    if (i == x.pulsesin || i == x.pulsesout) m_ratioFromPulses = true;
    if (i >= x.out1 && i < x.out1 + 12) {
        const int bit = 1 << (i - x.out1);
        int outputs = int(num(x.outputs));
        outputs = v != 0 ? outputs | bit : outputs & ~bit;
        set(x.outputs, std::int32_t(outputs));
        return "";
    }
    if (i == x.dacmap) set(x.dmgain, 1.0f); // DMGAIN resets when DACMAP changes (L2169)
    if (i == x.blktype && v != num(x.blktype)) set(x.enable, std::int32_t(0)); // changing BLKTYPE disables (L1956)
    set(i, value);
    if (i >= x.intr0 && i < x.intr0 + int(cat::interruptSources().size())) refreshInterruptsEnabled();
    return "";
}

void Sc750Drive::refreshInterruptsEnabled() {
    const int n = int(cat::interruptSources().size());
    m_interruptsEnabled = false;
    for (int k = 0; k < n; ++k)
        if (num(ix().intr0 + k) != 0) m_interruptsEnabled = true;
}

// Sources in the catalog's (the manual's) order, which is also their priority.
int Sc750Drive::takeInterrupt() {
    const int n = int(cat::interruptSources().size());
    for (int k = 0; k < n; ++k) {
        if (num(ix().intr0 + k) == 0 || !interruptAsserted(k)) continue;
        if (k == 2) m_charReceived = false;
        if (k == 5) m_disableEvent = false;
        set(ix().intr0 + k, std::int32_t(0)); // taking an interrupt disables its source (L1766-L1780)
        refreshInterruptsEnabled();
        return k;
    }
    return -1;
}

// Registration (L1687-L1758) on rising edges of INP7/REG1 and INP8/REG2 (the encoder's Z channel is not
// on the bench). Each kind latches once after REG.FLAG is written 0 (armed); REG.FUNC = 1 then moves
// REG.DIST from the latched position, if a motion command is in progress.
void Sc750Drive::registration() {
    const DriveIndex& x = ix();
    const bool in7 = input(7), in8 = input(8);
    const bool rise7 = in7 && !m_lastInput7, rise8 = in8 && !m_lastInput8;
    m_lastInput7 = in7;
    m_lastInput8 = in8;
    const int mode = int(num(x.regmode));
    const bool resolver = mode >= 1 && rise7;
    const bool encoder = (mode == 2 && rise7) || (mode == 3 && rise8);
    const int wasFlag = int(num(x.regflag));
    int flag = wasFlag;
    if (resolver && (flag & 2) == 0) {
        set(x.regpos, readVariable(x.position));
        set(x.regrespos, readVariable(x.respos));
        flag |= 2;
        if (num(x.regfunc) == 1 && enabled() && m_motion.moving())
            m_motion.goAbs(num(x.regpos) + num(x.regdist), settings());
    }
    if (encoder && (flag & 1) == 0) {
        set(x.regencpos, readVariable(x.encpos));
        flag |= 1;
    }
    if (flag != wasFlag) set(x.regflag, std::int32_t(flag));
}

void Sc750Drive::motion(int kind) {
    if (!enabled()) return; // motion statements are ignored while disabled (L1428)
    if (num(ix().blktype) != 2) return; // and when the analog input commands the loops (DECISIONS 53)
    switch (kind) {
    case 1: m_motion.goVel(settings()); break;
    case 2: m_motion.goIncr(num(ix().indexdist), settings()); break;
    case 3: m_motion.goAbs(num(ix().target), settings()); break;
    case 4: m_motion.goAbs(0, settings()); break;
    case 5: m_motion.abort(num(ix().decel)); break;
    case 6: m_motion.update(settings()); break;
    default: break;
    }
}

void Sc750Drive::write(std::string_view text) {
    m_uart.write(text);
}

std::optional<std::string> Sc750Drive::takeLine() {
    if (!m_loggedOn) return std::nullopt; // INPUT waits for the logon (L3688)
    const auto cr = m_programInput.find('\r');
    if (cr == std::string::npos) return std::nullopt;
    std::string line = m_programInput.substr(0, cr);
    m_programInput.erase(0, cr + 1);
    if (!m_programInput.empty() && m_programInput.front() == '\n') m_programInput.erase(0, 1);
    std::erase(line, '\n');
    return line;
}

std::string Sc750Drive::takeChar() {
    if (!m_loggedOn || m_programInput.empty()) return ""; // INKEY$ is null when logged off (L3688)
    std::string c(1, m_programInput.front());
    m_programInput.erase(0, 1);
    return c;
}

double Sc750Drive::whenSample(int source) {
    if (source >= 1 && source <= 16) return input(source) ? 1 : 0;
    if (source == 17) return std::llround(m_motion.positionCommand_counts());
    if (source == 18) return std::llround(m_motion.positionCommand_counts() - lag_counts()); // POSITION
    if (source == 19) return std::llround(m_encoderPosition);
    return m_analogInFiltered_V; // 20: ANALOG.IN
}

void Sc750Drive::whenLatch() {
    const DriveIndex& x = ix();
    set(x.whenPcmd, readVariable(x.poscmd));
    set(x.whenPos, readVariable(x.position));
    set(x.whenEncpos, readVariable(x.encpos));
    set(x.whenRespos, readVariable(x.respos));
    set(x.whenRvel, readVariable(x.rvel));
    set(x.whenTime, readVariable(x.time));
    set(x.whenAnalog, readVariable(x.analogin));
    set(x.whenDacmon, readVariable(x.dacmon));
    set(x.whenVelcmd, readVariable(x.velcmd));
    set(x.whenIcmd, readVariable(x.icmd));
    set(x.whenIfb, readVariable(x.ifb));
}

void Sc750Drive::whenAction(int action, int argument, float value) {
    if (action == 1)
        writeVariable(ix().out1 + argument - 1, std::int32_t(value));
    else if (action == 2)
        set(ix().ratio, value);
    else if (action >= 3 && action <= 8)
        motion(action - 2);
    // 0 CONTINUE and 9 PAUSE: no action (digest §4.9 design)
}

void Sc750Drive::tmrset(int timer, float delay_s, int packed) {
    Timer& t = m_timers[std::size_t(timer - 1)];
    t.pulse = (packed & 1) != 0;
    t.output = packed >> 1 & 0xf;
    t.outputLevel = packed >> 5 & 1;
    t.input = packed >> 6 & 0x1f;
    t.inputLevel = packed >> 11 & 1;
    t.delay_s = delay_s;
    t.configured = t.output >= 1 && t.input >= 1;
    m_anyTimer = m_anyTimer || t.configured;
    t.lastTrigger = false;
    t.fireAt = t.endAt = -1;
}

std::optional<Value> Sc750Drive::readNamed(std::string_view name) {
    const int i = cat::variableIndex(name);
    if (i < 0) return std::nullopt;
    return readVariable(i);
}

std::string Sc750Drive::writeNamed(std::string_view name, const std::string& text) {
    const int i = cat::variableIndex(name);
    if (i < 0) return "UNKNOWN VARIABLE";
    const auto& info = cat::variables()[std::size_t(i)];
    if (info.access == cat::Access::ReadOnly) return "READ ONLY";
    const auto v = parseValue(text, info.type);
    if (!v) return "BAD VALUE";
    return writeVariable(i, *v);
}

} // namespace drive_core::sc750
