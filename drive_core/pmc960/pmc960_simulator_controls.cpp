// The PMC-960 bench.
#include "pmc960_simulator_controls.h"

#include "pmc960_drive.h"

#include "drive_core/physics/motor_parameters.h"

#include <algorithm>
#include <chrono>
#include <numbers>

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

void Pmc960SimulatorControls::setLoadTorque_Nm(double torque_Nm) {
    Pmc960Servo& servo = m_drive.state().motion.servo();
    physics::LoadParameters load = servo.plant().load();
    load.externalTorque_Nm = torque_Nm;
    servo.setLoad(load);
}

void Pmc960SimulatorControls::setLoadInertia_kgm2(double inertia_kgm2) {
    Pmc960Servo& servo = m_drive.state().motion.servo();
    physics::LoadParameters load = servo.plant().load();
    load.inertia_kgm2 = std::max(inertia_kgm2, 0.0);
    servo.setLoad(load);
}

bool Pmc960SimulatorControls::setLoadCoupling(double stiffness_NmPerRad, double damping_NmPerRadPerS) {
    Pmc960Servo& servo = m_drive.state().motion.servo();
    physics::LoadParameters load = servo.plant().load();
    load.couplingStiffness_NmPerRad = std::max(stiffness_NmPerRad, 0.0);
    load.couplingDamping_NmPerRadPerS = std::max(damping_NmPerRadPerS, 0.0);
    servo.setLoad(load);
    return true;
}

void Pmc960SimulatorControls::setMasterFrequency_Hz(double countsPerSecond) {
    m_drive.state().motion.master().setFrequency_Hz(countsPerSecond);
}

bool Pmc960SimulatorControls::setMasterWave(const MasterWave& wave) {
    m_drive.state().motion.master().setWave(wave);
    return true;
}

bool Pmc960SimulatorControls::selectMotor(std::string_view name) {
    const physics::ReferenceMotor* motor = physics::findReferenceMotor(name);
    if (!motor) return false;
    m_motorName = std::string(motor->name);
    m_drive.state().motion.servo().setMotor(motor->motor);
    m_drive.powerUp();
    return true;
}

void Pmc960SimulatorControls::powerCycle() {
    m_drive.powerUp();
}

MonitorTrace Pmc960SimulatorControls::analogMonitor() const {
    MonitorTrace trace = m_drive.state().motion.servo().tachScope().trace(
        "tach (after TGAIN)", "velocity command (feedforward + position compensation, tach volts)");
    trace.lastSample_s = std::chrono::duration<double>(m_drive.now()).count(); // the drive's clock, to a period
    return trace;
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
    const physics::Plant& plant = state.motion.servo().plant();
    s.position_rev = plant.motorAngle_rad() / (2 * std::numbers::pi);
    s.velocity_rpm = plant.motorSpeed_radPerS() * 60 / (2 * std::numbers::pi);
    s.current_a = plant.current_A();
    s.loadTorque_Nm = plant.load().externalTorque_Nm;
    s.loadInertia_kgm2 = plant.load().inertia_kgm2;
    s.couplingStiffness_NmPerRad = plant.load().couplingStiffness_NmPerRad;
    s.couplingDamping_NmPerRadPerS = plant.load().couplingDamping_NmPerRadPerS;
    s.resonance_Hz = plant.resonance_Hz();
    s.masterFrequency_Hz = state.motion.master().frequency_Hz();
    s.masterWave = state.motion.master().wave();
    s.motorName = m_motorName;
    return s;
}

} // namespace drive_core::pmc960
