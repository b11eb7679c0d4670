// The simulated SC750's shaft and analog side: the shaft following the command (held back by the
// directional inhibits), the analog input (ANALOG.IN), the analog output (DACMAP/DMGAIN/ANALOG.OUT ->
// DACMON), the encoder output (ENC.OUT) and which interrupt sources are asserted. DECISIONS 39-43.
#include "sc750_drive.h"
#include "sc750_drive_index.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace drive_core::sc750 {

namespace cat = catalog::sc750;

namespace {
// One tick of a first-order low-pass with its corner at corner_Hz.
double lowPass(double filtered, double input, double corner_Hz) {
    const double alpha = 1.0 - std::exp(-2.0 * std::numbers::pi * corner_Hz * kTick_s);
    return filtered + (input - filtered) * alpha;
}
} // namespace

// The ideal servo puts the shaft on the command every tick. An active inhibit (INH+ clockwise, INH-
// counter-clockwise) takes away torque in its direction: the shaft decelerates to rest at DECEL.RATE
// while the command runs on, so POS.ERROR grows (L1484). Once released the ideal servo closes the error.
void Sc750Drive::followCommand() {
    const double target = m_motion.shaft_counts();
    const double command_cps = m_motion.velocity_rpm() * kCpsPerRpm;
    double v = (target - m_actual_counts) / kTick_s;
    const double brake = num(ix().decel) * kCpsPerRpm * kTick_s;
    bool held = false;
    if (m_inhibitCw && v > 0) {
        const double slowing = std::max(0.0, std::min(m_actualVel_cps, std::max(command_cps, 0.0)) - brake);
        held = slowing < v;
        v = std::min(v, slowing);
    } else if (m_inhibitCcw && v < 0) {
        const double slowing = std::min(0.0, std::max(m_actualVel_cps, std::min(command_cps, 0.0)) + brake);
        held = slowing > v;
        v = std::max(v, slowing);
    }
    if (!held) {
        m_actual_counts = target; // exactly on the command: no rounding creeps into POS.ERROR
        m_actualVel_cps = command_cps;
        m_lagging = false;
        return;
    }
    m_actual_counts += v * kTick_s;
    m_actualVel_cps = v;
    m_lagging = true;
}

// The signal DACMAP selects, scaled to volts (L2147-L2175): DMGAIN multiplies every source but ANALOG.OUT;
// position signals roll over at ±5 V, the others clamp there.
double Sc750Drive::dacSignal_V() {
    const int map = int(num(ix().dacmap));
    if (map == 0) return std::clamp(num(ix().analogout), -5.0, 5.0);
    const cat::DacMapInfo& info = cat::dacMap()[std::size_t(map)];
    double value = 0;
    if (map == 10) {
        value = m_analogInFiltered_V; // FAD: the A/D after its filter
    } else if (const int index = cat::variableIndex(info.mnemonic); index >= 0) {
        value = toDouble(readVariable(index));
    } // FVEL.ERR, IT.FILT: not modelled by the ideal servo, 0
    if (info.unit == "kRPM" || info.unit == "kHz") value /= 1000.0;
    if (info.unit == "rev" || info.unit == "4096 counts") value /= kCountsPerRev;
    const double volts = value * info.voltsPerUnit * num(ix().dmgain);
    const bool position = map == 5 || map == 6 || map == 7 || map == 12;
    if (position) return volts - 10.0 * std::floor((volts + 5.0) / 10.0); // -5 ... +5, rolling over
    return std::clamp(volts, -5.0, 5.0);
}

void Sc750Drive::analogTick() {
    const double sampled = std::clamp(m_analogIn_V, -12.0, 12.0) + num(ix().adoffset);
    m_analogInFiltered_V = std::clamp(lowPass(m_analogInFiltered_V, sampled, num(ix().adf0)), -12.0, 12.0);
    m_dacmon_V = lowPass(m_dacmon_V, dacSignal_V(), num(ix().dmf0));
    const double lines = num(ix().encout);
    if (lines > 0) m_encoderOut_counts += (m_actual_counts - m_lastShaft_counts) * 4.0 * lines / kCountsPerRev;
    m_lastShaft_counts = m_actual_counts;
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
