// The bench around a simulated PMC-960 (SimulatorControls): the generic lines mapped onto the controller's —
// ENABLE = DRVRDY', MOTION = not ESTOP', HOME switch = SENSOR, limit switches = IN07'/IN06' (THL) — and a
// status snapshot in the bench's units (THA counts per revolution; 4,096 for an encoder).
#pragma once

#include "drive_core/simulator_controls.h"

namespace drive_core::pmc960 {

class Pmc960Drive;

class Pmc960SimulatorControls final : public SimulatorControls {
public:
    explicit Pmc960SimulatorControls(Pmc960Drive& drive) : m_drive(drive) {}

    void setInput(int number, bool on) override;
    void setEnableInput(bool on) override;
    void setMotionInput(bool on) override;
    void setHomeSwitch(bool on) override;
    void setHomeSwitchPosition_rev(double) override {}
    void setLimitSwitches(bool positiveTripped, bool negativeTripped) override;
    void setLoadTorque_Nm(double torque_Nm) override { m_loadTorque_Nm = torque_Nm; }
    void setLoadInertia_kgm2(double inertia_kgm2) override { m_loadInertia_kgm2 = inertia_kgm2; }
    void setMasterFrequency_Hz(double countsPerSecond) override { m_master_Hz = countsPerSecond; }
    // The PMC-960 drives any servodrive through an analog command: no motor model to choose.
    bool selectMotor(std::string_view) override { return false; }
    void powerCycle() override;
    SimulatorStatus status() const override;

private:
    Pmc960Drive& m_drive;
    bool m_homeSwitch = false;
    double m_loadTorque_Nm = 0;
    double m_loadInertia_kgm2 = 0;
    double m_master_Hz = 0;
};

} // namespace drive_core::pmc960
