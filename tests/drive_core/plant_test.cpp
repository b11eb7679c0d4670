// The motor/load plant: Newton's law with exact answers, the current loop's time constant, a shaft coasting
// down against viscous and Coulomb friction, Coulomb friction holding against a small torque, and a
// compliant coupling ringing at its resonance.
#include "drive_core/physics/plant.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace drive_core::physics;

namespace {
MotorParameters frictionless() {
    MotorParameters m;
    m.viscousFriction_NmPerRadPerS = 0;
    m.coulombFriction_Nm = 0;
    m.currentLoopBandwidth_Hz = 1e6; // an instant current loop, for the mechanics alone
    return m;
}
} // namespace

TEST(Plant, ConstantTorqueAcceleratesAsNewtonSays) {
    LoadParameters load;
    Plant plant(frictionless(), load);
    const double j = plant.motor().rotorInertia_kgm2 + load.inertia_kgm2;
    for (int i = 0; i < 100; ++i) plant.step(0.001, 2.0); // 1 Nm for 0.1 s
    const double torque = plant.motor().torqueConstant_NmPerA * 2.0;
    EXPECT_NEAR(plant.motorSpeed_radPerS(), torque / j * 0.1, 1e-3 * torque / j * 0.1);
    EXPECT_NEAR(plant.motorAngle_rad(), torque / j * 0.01 / 2, 2e-3 * torque / j * 0.01 / 2);
}

TEST(Plant, CurrentLoopIsFirstOrderAtItsBandwidth) {
    Plant plant(MotorParameters{}, LoadParameters{});
    const double tau = 1 / (2 * std::numbers::pi * plant.motor().currentLoopBandwidth_Hz);
    plant.step(tau, 10.0);
    EXPECT_NEAR(plant.current_A(), 10.0 * (1 - std::exp(-1.0)), 0.01);
    plant.step(0.01, 100.0);
    EXPECT_DOUBLE_EQ(plant.current_A(), plant.motor().peakCurrent_A) << "the command is clamped to the peak";
}

// J w' = -b w - F while turning: w(t) = (w0 + F/b) e^(-bt/J) - F/b, until it stops.
TEST(Plant, ASpinningShaftCoastsDownAsItsFrictionSays) {
    for (const double b : {2e-5, 5e-3}) { // viscous friction (N m s/rad): a slow and a fast decay
        MotorParameters m = frictionless();
        m.viscousFriction_NmPerRadPerS = b;
        m.coulombFriction_Nm = 0.02;
        const LoadParameters load;
        Plant plant(m, load);
        const double j = m.rotorInertia_kgm2 + load.inertia_kgm2;
        for (int i = 0; i < 10; ++i) plant.step(0.001, 100 * j / 0.01 / m.torqueConstant_NmPerA); // ~100 rad/s
        plant.step(0.001, 0.0); // the current gone
        const double w0 = plant.motorSpeed_radPerS(), angle0 = plant.motorAngle_rad();
        ASSERT_GT(w0, 80);
        const double t = 0.1, beta = b / j, stall = m.coulombFriction_Nm / b;
        for (int i = 0; i < 100; ++i) plant.step(0.001, 0.0);
        const double e = std::exp(-beta * t);
        const double turned = (w0 + stall) * (1 - e) / beta - stall * t;
        EXPECT_NEAR(plant.motorSpeed_radPerS(), (w0 + stall) * e - stall, 1e-9 * w0) << "b " << b;
        EXPECT_NEAR(plant.motorAngle_rad() - angle0, turned, 1e-9 * turned) << "b " << b;
    }
}

TEST(Plant, CoulombFrictionHoldsAgainstASmallTorque) {
    MotorParameters m = frictionless();
    m.coulombFriction_Nm = 0.1;
    Plant plant(m, LoadParameters{});
    for (int i = 0; i < 1000; ++i) plant.step(0.001, 0.1); // 0.05 Nm < 0.1 Nm
    EXPECT_LT(std::abs(plant.motorSpeed_radPerS()), 0.01);
}

TEST(Plant, CompliantCouplingRingsAtItsResonance) {
    LoadParameters load;
    load.inertia_kgm2 = 3e-4;
    load.couplingStiffness_NmPerRad = 500;
    Plant plant(frictionless(), load);
    const double expected = plant.resonance_Hz();
    ASSERT_GT(expected, 100);
    plant.step(0.002, 5.0); // a torque pulse
    int crossings = 0;
    double last = plant.motorAngle_rad() - plant.loadAngle_rad();
    const double duration = 0.5;
    for (int i = 0; i < int(duration / 1e-4); ++i) {
        plant.step(1e-4, 0.0);
        const double twist = plant.motorAngle_rad() - plant.loadAngle_rad();
        if ((twist > 0) != (last > 0)) ++crossings;
        last = twist;
    }
    EXPECT_NEAR(crossings / 2.0 / duration, expected, expected * 0.02);
}

TEST(Plant, ReferenceMotorsAreNamed) {
    ASSERT_GE(referenceMotors().size(), 3u);
    ASSERT_NE(findReferenceMotor("REF-MEDIUM"), nullptr);
    EXPECT_EQ(findReferenceMotor("NOPE"), nullptr);
    for (const ReferenceMotor& r : referenceMotors()) {
        EXPECT_GT(r.motor.peakCurrent_A, r.motor.continuousCurrent_A) << r.name;
        EXPECT_GT(r.motor.torqueConstant_NmPerA, 0) << r.name;
    }
}
