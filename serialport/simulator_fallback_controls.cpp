// SimulatorFallbackControls: the Drive pins, plus the BDS5's dedicated inputs by name.
#include "simulator_fallback_controls.h"

#include "drive_core/bds5/bds5_drive.h"
#include "drive_core/physics/motor_parameters.h"

namespace serialport {

void SimulatorFallbackControls::setDedicated(const char* name, bool on) {
    if (auto* bds5 = dynamic_cast<drive_core::bds5::Bds5Drive*>(&m_drive)) bds5->setDedicatedInput(name, on);
}

void SimulatorFallbackControls::setMotionInput(bool on) {
    m_status.motionInput = on;
    setDedicated("MOTION", on);
}

void SimulatorFallbackControls::setHomeSwitch(bool on) {
    m_status.homeSwitch = on;
    setDedicated("HOME", on);
}

void SimulatorFallbackControls::setLimitSwitches(bool positiveTripped, bool negativeTripped) {
    m_status.positiveLimit = positiveTripped;
    m_status.negativeLimit = negativeTripped;
    setDedicated("LIMIT", !(positiveTripped || negativeTripped)); // the BDS5's limits are normally closed
}

bool SimulatorFallbackControls::selectMotor(std::string_view name) {
    if (!drive_core::physics::findReferenceMotor(name)) return false;
    m_status.motorName = std::string(name);
    return true;
}

drive_core::SimulatorStatus SimulatorFallbackControls::status() const {
    drive_core::SimulatorStatus s = m_status;
    s.inputs.clear();
    s.outputs.clear();
    for (int i = 1; i <= m_drive.inputCount(); ++i) s.inputs.push_back(m_drive.input(i));
    for (int o = 1; o <= m_drive.outputCount(); ++o) s.outputs.push_back(m_drive.output(o));
    return s;
}

} // namespace serialport
