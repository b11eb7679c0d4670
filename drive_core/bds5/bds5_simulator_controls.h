// The bench around a simulated BDS5 (SimulatorControls): I1-I16, the REMOTE (enable), MOTION, HOME and
// LIMIT lines, the load on the shaft, the master encoder frequency and its wave, the resolver wires (ERR 17), the
// reference motor and power.
// Not thread-safe: call it from the thread that steps the drive.
#pragma once

#include "drive_core/simulator_controls.h"

namespace drive_core::bds5 {

class Bds5Drive;

class Bds5SimulatorControls final : public SimulatorControls {
public:
    explicit Bds5SimulatorControls(Bds5Drive& drive) : m_drive(drive) {}

    void setInput(int number, bool on) override;
    void setEnableInput(bool on) override;
    void setMotionInput(bool on) override;
    void setHomeSwitch(bool on) override;
    void setHomeSwitchPosition_rev(double position_rev) override;
    void setLimitSwitches(bool positiveTripped, bool negativeTripped) override;
    void setLoadTorque_Nm(double torque_Nm) override;
    void setLoadInertia_kgm2(double inertia_kgm2) override;
    bool setLoadCoupling(double stiffness_NmPerRad, double damping_NmPerRadPerS) override;
    void setMasterFrequency_Hz(double countsPerSecond) override;
    bool setMasterWave(const MasterWave& wave) override;
    bool selectMotor(std::string_view name) override;
    void powerCycle() override;
    SimulatorStatus status() const override;
    void setFeedbackConnected(bool connected) override;

private:
    Bds5Drive& m_drive;
    std::string m_motorName = "REF-MEDIUM";
    bool m_positiveLimit = false;
    bool m_negativeLimit = false;
};

} // namespace drive_core::bds5
