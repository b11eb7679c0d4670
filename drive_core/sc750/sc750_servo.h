// The SC750's servo loops on the shared plant (DECISIONS 47-52), every drive tick (0.427 ms): the position
// loop KPP with velocity feed-forward KVFF, the velocity error through the anti-resonant low-passes ARF0 and
// ARF1 (FVEL.ERR), the velocity PI KVP/KVI, the directional current limits ILMT.PLUS/ILMT.MINUS and the
// inhibits, then the ILC current loop and the motor. BLKTYPE picks what commands the loops.
#pragma once

#include "sc750_current_loop.h"

#include "drive_core/physics/plant.h"

#include <array>
#include <cstddef>
#include <string>
#include <string_view>

namespace drive_core::sc750 {

// A motor on the bench: the plant's data plus what the SC750's own current loop needs.
struct Sc750Motor {
    std::string name;
    physics::MotorParameters motor;
    double windingTau_s = 1.3e-3; // L / R
};

// The bench motor by name: the Controller Set Up table's parts (R32G ..., catalog::sc750::motors()) or the
// shared reference motors (REF-SMALL ...). False if unknown.
bool findSc750Motor(std::string_view name, Sc750Motor* out);
// R32G, the boiler-plate motor whose Auto set-up the catalog's defaults are.
Sc750Motor defaultSc750Motor();

// The loop parameters, in the catalog's units, read from the variables every tick.
struct ServoSettings {
    int blocktype = 2;            // BLKTYPE
    double kvp_APerRadPerS = 0;   // KVP
    double kvi_Hz = 0;            // KVI: the PI's corner
    double kpp_Hz = 0;            // KPP: the position loop's bandwidth
    double kvff_percent = 0;      // KVFF
    double arf0_Hz = 1e4, arf1_Hz = 1e4;
    int ilc = 13;                 // the current loop's zero, 0.1 ms
    double ilmtPlus_percent = 100, ilmtMinus_percent = 100;
    double cmdgain = 1;           // CMDGAIN
    double controllerPeak_A = 7.5; // the model's peak current: 100 % of ILMT
    double itf0_Hz = 0.02;         // ITF0: the I.t filter's corner
};

// What commands the loops this tick.
struct ServoCommand {
    bool enabled = false;
    double position_counts = 0;  // BLKTYPE 2 and 3: the position command, shaft coordinates (counts since power-up)
    double velocity_cps = 0;     // BLKTYPE 2: the profile's speed, for KVFF
    double analog_V = 0;         // BLKTYPE 0 and 1: ANALOG.IN
    bool inhibitCw = false, inhibitCcw = false;
    double inhibitDecel_cps2 = 0; // DECEL.RATE: how an inhibit brings the shaft to rest
};

class Sc750Servo {
public:
    Sc750Servo();

    void setMotor(const Sc750Motor& motor); // keeps the load, puts the shaft at rest at 0
    const Sc750Motor& motor() const { return m_motor; }
    void setLoad(const physics::LoadParameters& load) { m_plant.setLoad(load); }
    const physics::Plant& plant() const { return m_plant; }
    // Power-up: the shaft stays where it is and counts from 0 again; the loops start from rest.
    void powerUp();

    void tick(const ServoCommand& command, const ServoSettings& settings);

    // The shaft (counts since power-up, not rounded) and its speeds.
    double position_counts() const { return (m_plant.motorAngle_rad() - m_origin_rad) * kCountsPerRad; }
    double velocity_cps() const { return m_velocity_radPerS * kCountsPerRad; }  // over the last tick (RVEL)
    double averageVelocity_cps() const;                                          // over 128 ms (VELOCITY)
    double velocityCommand_cps() const { return m_vcmd_radPerS * kCountsPerRad; } // VEL.CMD
    double velocityError_cps() const { return m_verr_radPerS * kCountsPerRad; }   // VEL.ERR
    double filteredVelocityError_cps() const { return m_arf[1] * kCountsPerRad; } // FVEL.ERR
    double currentCommand_A() const { return m_icmd_A; }                          // ICMD
    double current_A() const { return m_plant.current_A(); }                      // IFB
    double itFiltered_A() const { return m_it_A; }                                // IT.FILT
    // True while an inhibit keeps the shaft from following the command.
    bool inhibited() const { return m_cwRamp_radPerS >= 0 || m_ccwRamp_radPerS >= 0; }

    static constexpr double kPeriod_s = 0.000427; // the drive tick (DECISIONS 21)
    static constexpr double kCountsPerRad = 4096 / (2 * 3.14159265358979323846);

private:
    double filterAlpha(double hz, std::size_t which);

    Sc750Motor m_motor;
    physics::Plant m_plant;
    Sc750CurrentLoop m_currentLoop;
    double m_origin_rad = 0;
    double m_lastAngle_rad = 0;
    double m_velocity_radPerS = 0;
    std::array<double, 301> m_angleHistory{}; // 300 ticks = 128 ms between oldest and newest, VELOCITY (L1400)
    std::size_t m_historyAt = 0;
    double m_vcmd_radPerS = 0, m_verr_radPerS = 0;
    std::array<double, 2> m_arf{};                  // ARF0, ARF1 outputs (rad/s)
    std::array<double, 3> m_alphaHz{-1, -1, -1};    // ARF0, ARF1, ITF0 corners the alphas are for
    std::array<double, 3> m_alpha{};
    double m_integral_radPerS = 0; // the PI's integral, 2 pi KVI x integral of FVEL.ERR
    double m_icmd_A = 0;
    double m_it_A = 0;
    double m_cwRamp_radPerS = -1, m_ccwRamp_radPerS = -1; // an inhibit's speed limit while braking; -1 = off
};

} // namespace drive_core::sc750
