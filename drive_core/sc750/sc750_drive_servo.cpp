// The simulated SC750's servo side: what commands the loops for the BLKTYPE (L1930-L1956), the loop
// settings read from the variables each tick, and the bench's motor and load. DECISIONS 47-53.
#include "sc750_drive.h"
#include "sc750_drive_index.h"

#include "drive_core/catalog/sc750_motors.h"

#include <algorithm>

namespace drive_core::sc750 {

namespace cat = catalog::sc750;

namespace {
constexpr double kAnalogPosition_RevPerV = 0.025; // BLKTYPE 3 (L1948)
constexpr double kOverspeed_rpm = 12000;          // the resolver speed the R/D converter tracks (DECISIONS 56)
constexpr double kFollowingErrorOverflow_counts = 32767; // a 16-bit error register (DECISIONS 56)
} // namespace

const ServoSettings& Sc750Drive::servoSettings() const {
    if (m_servoSettingsVersion == m_valuesVersion) return m_servoSettings;
    m_servoSettingsVersion = m_valuesVersion;
    const DriveIndex& x = ix();
    ServoSettings& s = m_servoSettings;
    s = ServoSettings{};
    s.blocktype = int(num(x.blktype));
    s.kvp_APerRadPerS = num(x.kvp);
    s.kvi_Hz = num(x.kvi);
    s.kpp_Hz = num(x.kpp);
    s.kvff_percent = num(x.kvff);
    s.arf0_Hz = num(x.arf0);
    s.arf1_Hz = num(x.arf1);
    s.ilc = int(num(x.ilc));
    s.ilmtPlus_percent = num(x.ilmtplus);
    s.ilmtMinus_percent = num(x.ilmtminus);
    s.cmdgain = num(x.cmdgain);
    s.itf0_Hz = num(x.itf0);
    const catalog::sc750::ControllerModelInfo* model = catalog::sc750::findControllerModel(int(num(x.model)));
    s.controllerPeak_A = model ? model->peak_A : m_servo.motor().motor.peakCurrent_A;
    return s;
}

// BLKTYPE 2 closes the position loop on the profile generator's command; 3 on the analog input's position;
// 1 and 0 have no position loop, so the command follows the shaft (POS.ERROR 0), as it does while disabled.
void Sc750Drive::servoTick(bool en) {
    const ServoSettings& s = servoSettings();
    if (en && s.blocktype == 3) {
        const double offset = m_motion.positionCommand_counts() - m_motion.shaft_counts();
        m_motion.setShaftCommand(kAnalogPosition_RevPerV * kCountsPerRev * s.cmdgain * m_analogInFiltered_V - offset);
    }
    m_controllerPeak_A = s.controllerPeak_A;
    ServoCommand c;
    c.enabled = en;
    c.position_counts = m_motion.shaft_counts();
    c.velocity_cps = s.blocktype == 2 ? m_motion.velocity_rpm() * kCpsPerRpm : 0;
    c.analog_V = m_analogInFiltered_V;
    c.inhibitCw = m_inhibitCw;
    c.inhibitCcw = m_inhibitCcw;
    c.inhibitDecel_cps2 = num(ix().decel) * kCpsPerRpm;
    m_servo.tick(c, s);
    m_actual_counts = m_servo.position_counts();
    if (!en || s.blocktype < 2) m_motion.setShaftCommand(m_actual_counts);
}

void Sc750Drive::servoFaults() {
    // Fault reset: the enable taken away (L1922's "press fault reset"; the SC750's reset is the enable).
    if (!m_enableInput || num(ix().enable) != 1) m_servoFault = 0;
    if (m_servoFault != 0) return;
    const double speed_rpm = std::abs(m_servo.velocity_cps()) / kCpsPerRpm;
    const double itLimit_A = num(ix().itthresh) / 100.0 * m_controllerPeak_A;
    if (speed_rpm > kOverspeed_rpm)
        m_servoFault = cat::kFaultOverspeed;
    else if (m_servo.itFiltered_A() > itLimit_A)
        m_servoFault = cat::kFaultIt;
    else if (enabled() && std::abs(lag_counts()) > kFollowingErrorOverflow_counts)
        m_servoFault = cat::kFaultFollowingError;
}

bool Sc750Drive::selectMotor(std::string_view name) {
    Sc750Motor motor;
    if (!findSc750Motor(name, &motor)) return false;
    m_servo.setMotor(motor);
    ++m_valuesVersion; // the controller's peak current may come from the motor
    m_motion.setShaftCommand(0);
    m_actual_counts = m_lastShaft_counts = 0;
    return true;
}

void Sc750Drive::setLoadTorque_Nm(double torque_Nm) {
    physics::LoadParameters load = m_servo.plant().load();
    load.externalTorque_Nm = torque_Nm;
    m_servo.setLoad(load);
}

void Sc750Drive::setLoadInertia_kgm2(double inertia_kgm2) {
    physics::LoadParameters load = m_servo.plant().load();
    load.inertia_kgm2 = std::max(0.0, inertia_kgm2);
    if (load.inertia_kgm2 <= 0) load.couplingStiffness_NmPerRad = 0; // nothing to be compliant to
    m_servo.setLoad(load);
}

bool Sc750Drive::setLoadCoupling(double stiffness_NmPerRad, double damping_NmPerRadPerS) {
    physics::LoadParameters load = m_servo.plant().load();
    if (load.inertia_kgm2 <= 0 && stiffness_NmPerRad > 0) return false; // no load inertia to couple
    load.couplingStiffness_NmPerRad = std::max(0.0, stiffness_NmPerRad);
    load.couplingDamping_NmPerRadPerS = std::max(0.0, damping_NmPerRadPerS);
    m_servo.setLoad(load);
    return true;
}

} // namespace drive_core::sc750
