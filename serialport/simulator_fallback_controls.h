// The bench for a simulated drive whose family does not offer SimulatorControls yet: inputs and outputs
// through the Drive pins, the BDS5's dedicated inputs where it has them, the rest only remembered.
// Internal to SimulatorWorker (worker thread); Drive::controls() replaces it once the family implements it.
#pragma once

#include "drive_core/drive.h"

namespace serialport {

class SimulatorFallbackControls final : public drive_core::SimulatorControls {
public:
    explicit SimulatorFallbackControls(drive_core::Drive& drive) : m_drive(drive) {}

    void setInput(int number, bool on) override { m_drive.setInput(number, on); }
    void setEnableInput(bool on) override { m_status.enableInput = on; }
    void setMotionInput(bool on) override;
    void setHomeSwitch(bool on) override;
    void setHomeSwitchPosition_rev(double) override {}
    void setLimitSwitches(bool positiveTripped, bool negativeTripped) override;
    void setLoadTorque_Nm(double torque_Nm) override { m_status.loadTorque_Nm = torque_Nm; }
    void setLoadInertia_kgm2(double inertia_kgm2) override { m_status.loadInertia_kgm2 = inertia_kgm2; }
    void setMasterFrequency_Hz(double countsPerSecond) override { m_status.masterFrequency_Hz = countsPerSecond; }
    bool selectMotor(std::string_view name) override;
    void powerCycle() override { m_drive.powerUp(); }
    drive_core::SimulatorStatus status() const override;

private:
    void setDedicated(const char* name, bool on);

    drive_core::Drive& m_drive;
    drive_core::SimulatorStatus m_status;
};

} // namespace serialport
