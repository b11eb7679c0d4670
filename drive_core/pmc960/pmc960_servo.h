// The PMC-960's analog servo electronics (2.2.2, 4.8; L204-210, L571-636) on the shared physics::Plant: the
// PSJ's 12-bit D/A, the position compensation amplifier (PLGAIN, PLCOMP), the analog lock (ALGAIN), the
// velocity summing junction (feedforward through FFGAIN, tach through TGAIN), the velocity compensation
// amplifier (VLGAIN, VLCOMP) and ICMD into the servodrive. Every choice the manual leaves open is numbered in
// DECISIONS.md ("Servo physics", S1-S12). Steps in fixed periods; never reads a clock, never allocates.
#pragma once

#include "drive_core/monitor_recorder.h"
#include "drive_core/physics/plant.h"

#include <cstdint>

namespace drive_core::pmc960 {

class Pmc960Servo {
public:
    // The table's gain registers in use (TG, L1741-1773) and what scales them.
    struct Gains {
        int positionGain = 16;        // TGP PLGAIN
        int velocityGain = 16;        // TGV VLGAIN
        int tachGain = 160;           // TGT TGAIN
        int feedForwardGain = 16;     // FFGAIN as TF scaled it for the velocity range in use
        int positionComp = 0;         // TGE PLCOMP: break frequency PLCOMP/67 Hz, 0 = proportional only
        int velocityComp = 0;         // TGB VLCOMP: break frequency VLCOMP/20 Hz, 0 = proportional only
        int lockGain = 0;             // TGL ALGAIN
        double countsPerRev = 4096;   // THA (4,096 for an encoder)
        double rangeTop_cps = 192000; // the velocity range's top speed: the feedforward D/A's full scale
    };

    // What the PMC's mode makes of the loops for one period.
    enum class Loop {
        Off,      // SM0: DRVENB' off; the servodrive, disabled, brakes the motor dynamically (S9)
        Velocity, // SM1: feedforward only into the velocity loop
        Position, // SM2/SM3: the PSJ through PLGAIN/PLCOMP, plus the feedforward
        Torque,   // at a positive stop: compensators off, a fixed current (ST)
    };

    static constexpr std::int64_t kPeriod_us = 500; // the analog loops are emulated at 2 kHz (S1)
    static constexpr double kPeriod_s = double(kPeriod_us) * 1e-6;

    Pmc960Servo();

    void setGains(const Gains& gains); // precomputes the loop coefficients (no lookups per period)
    const Gains& gains() const { return m_gains; }
    // A new motor: the shaft restarts at rest where the count was.
    void setMotor(const physics::MotorParameters& motor);
    void setLoad(const physics::LoadParameters& load) { m_plant.setLoad(load); }
    const physics::Plant& plant() const { return m_plant; }

    // The feedback count (R/D word or encoder count, plus the offset N set), rounded to the nearest count
    // (S6), and the shaft speed in counts/s (the tach).
    std::int64_t count() const;
    double velocity_cps() const;
    // The shaft's position in counts, not rounded (where a hard stop catches it).
    double position_counts() const;
    // N: the count reads `counts` from now on; the shaft does not move.
    void setCount(std::int64_t counts);
    // A hard stop: the shaft stands at `counts` (an inelastic stop), the current loop restarting.
    void stallAt(double counts);

    // One period: the loops read the shaft as it is, then the plant runs kPeriod_s with the current held.
    // psj_counts is the PSJ's content, referenceVelocity_cps the reference generator's rate (feeding
    // forward), torqueFraction the current at a positive stop (fraction of peak, signed).
    void tick(Loop loop, double psj_counts, double referenceVelocity_cps, double torqueFraction);
    // The compensators' integrators restart from 0 (loops opened, PSJ cleared).
    void resetIntegrators();

    // The closed position loop's velocity constant (1/s) and the feedforward's share of the speed, as the
    // gains and the motor make them (the steady following error is v (1 - ff) / kv).
    double positionLoopGain_perS() const;
    double feedForwardShare() const;
    // ICMD in volts (10 V = the servodrive's peak current).
    double currentCommand_V() const { return m_icmd_V; }
    // The tachometer signal after TGAIN (UA5A's output, the test point of §4.8's tuning), a sample a period,
    // as the bench's oscilloscope recorded it; its clock counts the servo's periods.
    const MonitorRecorder& tachScope() const { return m_tachScope; }

private:
    double countsPerRad() const;

    physics::Plant m_plant;
    Gains m_gains;
    std::int64_t m_offset_counts = 0; // count - round(shaft counts)
    // Coefficients from the gains (volts, seconds).
    double m_gp = 0, m_gv = 0;        // amplifier gains V/V
    double m_we = 0, m_wb = 0;        // compensator break frequencies, rad/s
    double m_tach_VperRadS = 0;       // tach volts per rad/s after TGAIN
    double m_ff_VperCps = 0;          // feedforward volts per count/s of reference
    double m_lock = 0;                // inter-LSB gain relative to one count per count
    double m_positionIntegral_Vs = 0; // PLCOMP's integral of POSERR
    double m_velocityIntegral_Vs = 0; // VLCOMP's integral of the summing junction
    double m_icmd_V = 0;
    double m_tachAlpha = 0; // the tach filter's step response over a period
    double m_tach_V = 0;    // the filtered tach voltage
    MonitorRecorder m_tachScope{kPeriod_s};
    std::int64_t m_periods = 0;
};

} // namespace drive_core::pmc960
