// The bench around a simulated PMC-960 (SimulatorControls): the generic lines mapped onto the controller's —
// ENABLE = DRVRDY', MOTION = not ESTOP', HOME switch = SENSOR, limit switches = IN07'/IN06' (THL) — the
// servodrive's motor and its load on the shared plant, the master (motion reference bus) input, and a
// status snapshot in the bench's units.
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
    void setLoadTorque_Nm(double torque_Nm) override;
    void setLoadInertia_kgm2(double inertia_kgm2) override;
    bool setLoadCoupling(double stiffness_NmPerRad, double damping_NmPerRadPerS) override;
    // The master input is the motion reference bus (EXTREF): it clocks the reference in slave mode (THR bit 6).
    void setMasterFrequency_Hz(double countsPerSecond) override;
    bool setMasterWave(const MasterWave& wave) override;
    // The servodrive's motor (physics::referenceMotors(); REF-MEDIUM at first): a new machine, powered up.
    bool selectMotor(std::string_view name) override;
    void powerCycle() override;
    SimulatorStatus status() const override;
    // The tachometer signal (after TGAIN) the manual's tuning watches on an oscilloscope (§4.8, L584-L632).
    MonitorTrace analogMonitor() const override;

private:
    Pmc960Drive& m_drive;
    bool m_homeSwitch = false;
    std::string m_motorName = "REF-MEDIUM";
};

} // namespace drive_core::pmc960
