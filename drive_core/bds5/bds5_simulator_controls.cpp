// The simulated BDS5's bench: inputs, limits, load, master input, motor and power.
#include "bds5_simulator_controls.h"

#include "bds5_drive.h"

#include "drive_core/physics/motor_parameters.h"

#include <algorithm>
#include <numbers>

namespace drive_core::bds5 {

void Bds5SimulatorControls::setInput(int number, bool on) {
    m_drive.setInput(number, on);
}

// The BDS5's hardware enable is its REMOTE input (C2): off, the drive is not ACTIVE (L2076-2125).
void Bds5SimulatorControls::setEnableInput(bool on) {
    m_drive.setDedicatedInput("REMOTE", on);
}

void Bds5SimulatorControls::setMotionInput(bool on) {
    m_drive.setDedicatedInput("MOTION", on);
}

// Setting the switch by hand ends the automatic HOME switch.
void Bds5SimulatorControls::setHomeSwitch(bool on) {
    m_drive.m_bench.homeAt_rev.reset();
    m_drive.setDedicatedInput("HOME", on);
}

void Bds5SimulatorControls::setHomeSwitchPosition_rev(double position_rev) {
    m_drive.m_bench.homeAt_rev = position_rev;
}

// The BDS5 has one LIMIT input, its two normally closed switches in series (L2237-2249).
void Bds5SimulatorControls::setLimitSwitches(bool positiveTripped, bool negativeTripped) {
    m_positiveLimit = positiveTripped;
    m_negativeLimit = negativeTripped;
    m_drive.setDedicatedInput("LIMIT", !(positiveTripped || negativeTripped));
}

void Bds5SimulatorControls::setLoadTorque_Nm(double torque_Nm) {
    physics::LoadParameters load = m_drive.m_state.servo.plant().load();
    load.externalTorque_Nm = torque_Nm;
    m_drive.m_state.servo.setLoad(load);
}

void Bds5SimulatorControls::setLoadInertia_kgm2(double inertia_kgm2) {
    physics::LoadParameters load = m_drive.m_state.servo.plant().load();
    load.inertia_kgm2 = std::max(inertia_kgm2, 0.0);
    m_drive.m_state.servo.setLoad(load);
}

// A compliant coupling makes the load a second mass on a spring (DECISIONS.md, bench): the two-mass plant
// whose resonance tuning has to find. Negative values are taken as 0 (rigid; no damping).
bool Bds5SimulatorControls::setLoadCoupling(double stiffness_NmPerRad, double damping_NmPerRadPerS) {
    physics::LoadParameters load = m_drive.m_state.servo.plant().load();
    load.couplingStiffness_NmPerRad = std::max(stiffness_NmPerRad, 0.0);
    load.couplingDamping_NmPerRadPerS = std::max(damping_NmPerRadPerS, 0.0);
    m_drive.m_state.servo.setLoad(load);
    return true;
}

void Bds5SimulatorControls::setMasterFrequency_Hz(double countsPerSecond) {
    m_drive.m_bench.master.setFrequency_Hz(countsPerSecond);
}

bool Bds5SimulatorControls::setMasterWave(const MasterWave& wave) {
    m_drive.m_bench.master.setWave(wave);
    return true;
}

// A new motor is a new machine: the drive is powered up again with it, ICONT set from its ratings.
bool Bds5SimulatorControls::selectMotor(std::string_view name) {
    const physics::ReferenceMotor* motor = physics::findReferenceMotor(name);
    if (!motor) return false;
    m_motorName = std::string(motor->name);
    m_drive.m_state.motorName = m_motorName;
    m_drive.m_state.servo.setMotor(motor->motor);
    m_drive.powerUp();
    m_drive.m_state.variables.set(
        "ICONT", std::int32_t(motor->motor.continuousCurrent_A / motor->motor.peakCurrent_A * 4095 + 0.5));
    return true;
}

void Bds5SimulatorControls::powerCycle() {
    m_drive.powerUp();
}

SimulatorStatus Bds5SimulatorControls::status() const {
    SimulatorStatus s;
    for (int i = 1; i <= Bds5Drive::kInputCount; ++i) s.inputs.push_back(m_drive.input(i));
    for (int i = 1; i <= Bds5Drive::kOutputCount; ++i) s.outputs.push_back(m_drive.output(i));
    const auto& vars = m_drive.m_state.variables;
    s.enableInput = vars.read("REMOTE").value_or(1) != 0;
    s.motionInput = vars.read("MOTION").value_or(1) != 0;
    s.homeSwitch = vars.read("HOME").value_or(0) != 0;
    s.positiveLimit = m_positiveLimit;
    s.negativeLimit = m_negativeLimit;
    s.active = vars.read("ACTIVE").value_or(0) != 0;
    s.fault = vars.read("FAULT").value_or(0) != 0;
    const physics::Plant& plant = m_drive.m_state.servo.plant();
    s.position_rev = plant.motorAngle_rad() / (2 * std::numbers::pi);
    s.velocity_rpm = plant.motorSpeed_radPerS() * 60 / (2 * std::numbers::pi);
    s.current_a = plant.current_A();
    s.loadTorque_Nm = plant.load().externalTorque_Nm;
    s.loadInertia_kgm2 = plant.load().inertia_kgm2;
    s.couplingStiffness_NmPerRad = plant.load().couplingStiffness_NmPerRad;
    s.couplingDamping_NmPerRadPerS = plant.load().couplingDamping_NmPerRadPerS;
    s.resonance_Hz = plant.resonance_Hz();
    s.masterFrequency_Hz = m_drive.m_bench.master.frequency_Hz();
    s.masterWave = m_drive.m_bench.master.wave();
    s.motorName = m_motorName;
    s.feedbackConnected = m_drive.m_bench.feedbackConnected;
    s.relayClosed = m_drive.m_powered; // hardware watchdog OK once powered up (§6.4; no firmware faults)
    s.brakeReleased = vars.read("STATUS").value_or(0) != 0; // STATUS drives a fail-safe brake (L1943-1951)
    return s;
}

void Bds5SimulatorControls::setFeedbackConnected(bool connected) {
    m_drive.m_bench.feedbackConnected = connected;
}

} // namespace drive_core::bds5
