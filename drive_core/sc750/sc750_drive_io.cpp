// The simulated SC750's analog side: the analog input (ANALOG.IN), the analog output (DACMAP/DMGAIN/
// ANALOG.OUT -> DACMON), the encoder output (ENC.OUT) and which interrupt sources are asserted. DECISIONS 39-43.
#include "sc750_drive.h"
#include "sc750_drive_index.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>

namespace drive_core::sc750 {

namespace cat = catalog::sc750;

const Sc750Drive::AnalogSettings& Sc750Drive::analogSettings() {
    AnalogSettings& a = m_analogSettings;
    if (a.version == m_valuesVersion) return a;
    a.version = m_valuesVersion;
    const DriveIndex& x = ix();
    a.adoffset_V = num(x.adoffset);
    a.adf0_Hz = num(x.adf0);
    a.dmf0_Hz = num(x.dmf0);
    a.encoderLines = num(x.encout);
    a.dacmap = int(num(x.dacmap));
    a.analogOut_V = std::clamp(num(x.analogout), -5.0, 5.0);
    if (a.dacmap > 0 && a.dacmap < int(cat::dacMap().size())) {
        const cat::DacMapInfo& info = cat::dacMap()[std::size_t(a.dacmap)];
        double perUnit = info.voltsPerUnit * num(x.dmgain);
        if (info.unit == "kRPM" || info.unit == "kHz") perUnit /= 1000.0;
        if (info.unit == "rev" || info.unit == "4096 counts") perUnit /= kCountsPerRev;
        a.voltsPerValue = perUnit;
    }
    a.rollsOver = a.dacmap == 5 || a.dacmap == 6 || a.dacmap == 7 || a.dacmap == 12;
    return a;
}

// The signal DACMAP selects, scaled to volts (L2147-L2175): DMGAIN multiplies every source but ANALOG.OUT;
// position signals roll over at ±5 V, the others clamp there.
double Sc750Drive::dacSignal_V(const AnalogSettings& a) {
    const int map = a.dacmap;
    if (map == 0) return a.analogOut_V;
    // The servo's signals straight from the loops (no look-up by name: this runs every tick); positions in
    // whole counts, as the variables read.
    const double pcmd = m_motion.positionCommand_counts();
    double value = 0;
    switch (map) {
    case 1: value = m_servo.velocity_cps() / kCpsPerRpm; break; // the loop's resolver speed (DECISIONS 54)
    case 2: value = m_servo.velocityCommand_cps() / kCpsPerRpm; break;
    case 3: value = m_servo.velocityError_cps() / kCpsPerRpm; break;
    case 4: value = m_servo.filteredVelocityError_cps() / kCpsPerRpm; break;
    case 5: value = double(std::llround(pcmd - lag_counts())); break;
    case 6: value = double(std::llround(pcmd) - std::llround(pcmd - lag_counts())); break;
    case 7: value = double(std::llround(pcmd)); break;
    case 8: value = m_servo.currentCommand_A(); break;
    case 9: value = m_servo.current_A(); break;
    case 10: value = m_analogInFiltered_V; break; // FAD: the A/D after its filter
    case 11: value = m_masterFrequency; break;
    case 12: value = double(std::llround(m_encoderPosition)); break;
    case 13: value = m_servo.itFiltered_A(); break;
    default: break;
    }
    const double volts = value * a.voltsPerValue;
    if (a.rollsOver) return volts - 10.0 * std::floor((volts + 5.0) / 10.0); // -5 ... +5, rolling over
    return std::clamp(volts, -5.0, 5.0);
}

double Sc750Drive::LowPass::operator()(double filtered, double input, double corner) {
    if (corner != corner_Hz) {
        corner_Hz = corner;
        alpha = 1.0 - std::exp(-2.0 * std::numbers::pi * corner * kTick_s);
    }
    return filtered + (input - filtered) * alpha;
}

void Sc750Drive::analogTick() {
    const AnalogSettings& a = analogSettings();
    const double sampled = std::clamp(m_analogIn_V, -12.0, 12.0) + a.adoffset_V;
    m_analogInFiltered_V = std::clamp(m_adf0(m_analogInFiltered_V, sampled, a.adf0_Hz), -12.0, 12.0);
    m_dacmon_V = m_dmf0(m_dacmon_V, dacSignal_V(a), a.dmf0_Hz);
    // The second probe: the net velocity command at DACMAP 2's scale, 1 V/kRPM (DECISIONS 55).
    m_dacmonScope.push(m_dacmon_V, m_servo.velocityCommand_cps() / kCpsPerRpm / 1000.0,
                       std::chrono::duration<double>(m_now).count());
    const double lines = a.encoderLines;
    if (lines > 0) m_encoderOut_counts += (m_actual_counts - m_lastShaft_counts) * 4.0 * lines / kCountsPerRev;
    m_lastShaft_counts = m_actual_counts;
}

MonitorTrace Sc750Drive::analogMonitor() const {
    const int map = std::clamp(int(std::lround(num(ix().dacmap))), 0, int(cat::dacMap().size()) - 1);
    const cat::DacMapInfo& info = cat::dacMap()[std::size_t(map)];
    const double gain = map == 0 ? 1.0 : num(ix().dmgain);
    char scale[64];
    std::snprintf(scale, sizeof scale, "%g V/%s", info.voltsPerUnit * gain, std::string(info.unit).c_str());
    return m_dacmonScope.trace("DACMON: " + std::string(info.mnemonic) + ", " + scale, "VEL.CMD, 1 V/kRPM");
}

// Source k of the catalog's table (0 CCWINH, 1 CCWOT, 2 CHAR, 3 CWINH, 4 CWOT, 5 DISABLE, 6 FAULT,
// 7-22 I1HI-I16HI, 23-38 I1LO-I16LO, 39 PACLAN, 40 POS.ERROR). PACLAN is never asserted: no other axis
// exists to send a LANINTERRUPT to this one (DECISIONS 43).
bool Sc750Drive::interruptAsserted(int k) {
    const DriveIndex& x = ix();
    if (k == 0) return m_inhibitCcw;
    if (k == 1) return toDouble(readVariable(x.position)) < num(x.ccwot);
    if (k == 2) return m_charReceived;
    if (k == 3) return m_inhibitCw;
    if (k == 4) return toDouble(readVariable(x.position)) > num(x.cwot);
    if (k == 5) return m_disableEvent;
    if (k == 6) return faultCode() != cat::kFaultNone && faultCode() != cat::kFaultEnabled;
    if (k >= 7 && k < 23) return input(k - 6);
    if (k >= 23 && k < 39) return !input(k - 22);
    if (k == 40) {
        const double limit = m_motion.moving() ? num(x.poserrmoving) : num(x.poserrstopped);
        return std::abs(toDouble(readVariable(x.poserror))) > limit;
    }
    return false;
}

} // namespace drive_core::sc750
