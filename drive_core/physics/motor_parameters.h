// Motor, load and drive data for the simulated plant, with units in the names. The reference
// combinations are ServoDesk's own round-number choices in the range of the BDS5's motors (not vendor
// data), named so tests and users can pick them.
#pragma once

#include <span>
#include <string_view>

namespace drive_core::physics {

struct MotorParameters {
    double torqueConstant_NmPerA = 0.5;
    double rotorInertia_kgm2 = 1.5e-4;
    double viscousFriction_NmPerRadPerS = 2e-5;
    double coulombFriction_Nm = 0.02;
    double continuousCurrent_A = 6;
    double peakCurrent_A = 18;
    double maxSpeed_rpm = 6000;
    double currentLoopBandwidth_Hz = 1000; // the analog current loop on the compensation module
};

struct LoadParameters {
    double inertia_kgm2 = 1.5e-4;          // load seen at the motor shaft
    double couplingStiffness_NmPerRad = 0; // 0: rigid coupling (one mass)
    double couplingDamping_NmPerRadPerS = 0;
    double viscousFriction_NmPerRadPerS = 0;
    double externalTorque_Nm = 0; // a constant load torque (gravity, process force)
};

struct ReferenceMotor {
    std::string_view name;
    std::string_view description;
    MotorParameters motor;
};

std::span<const ReferenceMotor> referenceMotors();
const ReferenceMotor* findReferenceMotor(std::string_view name);

} // namespace drive_core::physics
