// The PMC-960 bench.
#include "pmc960_simulator_controls.h"

#include "pmc960_drive.h"

namespace drive_core::pmc960 {

void Pmc960SimulatorControls::setInput(int number, bool on) {
    m_drive.setInput(number, on);
}

void Pmc960SimulatorControls::setEnableInput(bool on) {
    m_drive.setLine(Pmc960Line::DriveReady, on);
}

void Pmc960SimulatorControls::setMotionInput(bool on) {
    m_drive.setLine(Pmc960Line::Estop, !on);
}

void Pmc960SimulatorControls::setHomeSwitch(bool on) {
    m_homeSwitch = on;
    m_drive.setLine(Pmc960Line::Sensor, on);
}

void Pmc960SimulatorControls::setLimitSwitches(bool positiveTripped, bool negativeTripped) {
    m_drive.setInput(8, positiveTripped); // IN07' = + limit (THL)
    m_drive.setInput(7, negativeTripped); // IN06' = - limit
}

void Pmc960SimulatorControls::powerCycle() {
    m_drive.powerUp();
}

SimulatorStatus Pmc960SimulatorControls::status() const {
    const Pmc960State& state = m_drive.state();
    SimulatorStatus s;
    for (int i = 1; i <= m_drive.inputCount(); ++i) s.inputs.push_back(m_drive.input(i));
    for (int i = 1; i <= m_drive.outputCount(); ++i) s.outputs.push_back(m_drive.output(i));
    s.enableInput = state.lines.driveReady;
    s.motionInput = !state.lines.estop;
    s.homeSwitch = m_homeSwitch;
    s.positiveLimit = m_drive.input(8);
    s.negativeLimit = m_drive.input(7);
    s.active = state.motion.enabled();
    s.fault = state.lines.fault || state.lines.estop;
    const double countsPerRev = state.table.inUse("THA") > 0 ? double(state.table.inUse("THA")) : 4096.0;
    s.position_rev = state.motion.actual_counts() / countsPerRev;
    s.velocity_rpm = state.motion.velocity_cps() / countsPerRev * 60.0;
    s.loadTorque_Nm = m_loadTorque_Nm;
    s.loadInertia_kgm2 = m_loadInertia_kgm2;
    s.masterFrequency_Hz = m_master_Hz;
    s.motorName = "analog servodrive";
    return s;
}

} // namespace drive_core::pmc960
