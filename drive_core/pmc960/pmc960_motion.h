// PMC-960 motion: the shared profile generator makes the commanded position (the digital reference into the
// PSJ); a first-order position loop makes the actual position lag it by the following error (PSJ content).
// The seed gives no plant equations (digest §9.10): the loop's velocity constant is chosen from PLGAIN and
// the feedforward gain cancels part of the lag. SF trips to IDLE when |PSJ| exceeds the trip point (L223).
#pragma once

#include "drive_core/motion/profile_generator.h"

#include <optional>

namespace drive_core::pmc960 {

class Pmc960Motion {
public:
    struct Loop {
        int positionGain = 16;    // TGP (PLGAIN)
        int feedForwardGain = 16; // TGF (FFGAIN)
    };

    void reset();
    void setLoop(Loop loop) { m_loop = loop; }

    // Modes 0-3 (SM, L1577-1601, L212-223). SM0 stops the reference and disables the drive, the PSJ keeping
    // its count. SM1 (velocity): the PSJ is cleared and not summed; the motor runs at TGF/128 of the
    // commanded speed with no position loop, so it drifts from the absolute position and never trips.
    // SM2 clears the PSJ; at rest and without an overflow the absolute position takes up the error (the
    // reference moves to the motor). SM3 keeps the PSJ: the motor jumps to where its count is cancelled.
    void setMode(int mode);
    int mode() const { return m_mode; }
    bool enabled() const { return m_mode != 0; }

    // Motion, in counts, counts/s, counts/s². Relative index, absolute go, signed jog speed.
    void index(double distance_counts, double velocity_cps, double accel_cps2);
    // Queued behind the motion in progress (one may wait, L2216); false when the buffer is full.
    bool go(double target_counts, double velocity_cps, double accel_cps2);
    void jog(double velocity_cps, double accel_cps2);
    void stop(double decel_cps2);
    void sharpStop();
    // N: the absolute position becomes position; returns the position error it cancelled (SN).
    double normalize(double position_counts);

    // SENSOR (JM4, L516), per the SP bits latched when a motion starts (L1612-1631). holdForSensor: the
    // motion just commanded from rest waits for SENSOR (bits 5+4). onSensor: what SENSOR does to the motion
    // just commanded once it runs at top speed (Stop: at any speed).
    enum class SensorAction { None, Decelerate, Depth, Stop };
    void holdForSensor() { m_generator.setHeld(true); }
    void onSensor(SensorAction action, double decel_cps2, double depth_counts = 0);
    // SENSOR asserted (its edge): releases a held start, else does the motion's SensorAction.
    void sensor();
    bool waitingForSensor() const { return m_generator.held(); }
    // The following error the loop settles to at a constant speed (adaptive depth, #B1).
    double steadyError_counts(double velocity_cps) const;

    // Cam (7.4, pmc960_cam.cpp): a segment changes the speed uniformly over the distance to position_counts,
    // reaching speed_cps (> 0 forward or reverse as the position lies) there, then holds it; speed 0 stops
    // there. One segment waits behind one still in its ramp.
    enum class CamResult { Started, Queued, Full, OtherMotion, Reverse, TooClose, AccelTooHigh, RampTooLong };
    CamResult cam(double position_counts, double speed_cps, double maxAccel_cps2);
    bool camRunning() const { return m_cam; }
    // SS CAM HOLD: the latest segment has not reached its position.
    bool camHold() const { return m_camPending.has_value() || (m_cam && m_generator.segment() == 1); }
    static constexpr double kMaxCamRamp_s = 65.535; // a 16-bit count of milliseconds (chosen, #83)

    // Feed to positive stop (SP bit 7, ST, L1655-1688). armPositiveStop: the motion just commanded may end
    // on a stop: when its PSJ passes the trip point the reference stops and the PMC holds the ST torque
    // instead of tripping (atPositiveStop, SS bit 6). A stop command ends it: the reference moves to the
    // motor, the PSJ is cleared and the loop closes. setPositiveStop: a hard stop on the bench the motor
    // cannot pass (nullopt: none).
    void armPositiveStop(bool armed) { m_fpsArmed = armed; }
    bool atPositiveStop() const { return m_fps; }
    void setPositiveStop(std::optional<double> position_counts);

    // Advances dt; returns true when the following error exceeds the SF trip point in a position mode
    // (the caller raises #E1 and sets SM0).
    bool step(double dt_s);
    void setTripPoint(double counts) { m_trip_counts = counts; }

    bool moving() const { return m_generator.moving(); }
    bool jogging() const { return m_generator.jogging(); }
    bool full() const { return m_generator.full(); }
    // ';' is satisfied at constant speed or at rest.
    bool atConstantSpeed() const { return !moving() || m_generator.acceleration() == 0; }
    bool atTopSpeed() const { return moving() && !waitingForSensor() && m_generator.acceleration() == 0; }
    double commanded_counts() const { return m_generator.position(); }
    double target_counts() const { return m_generator.finalPosition(); }
    // The motor's position (feedback); in position modes it trails the reference by the PSJ's count.
    double actual_counts() const { return m_actual_counts; }
    double velocity_cps() const { return m_generator.velocity(); }
    double acceleration_cps2() const { return m_generator.acceleration(); }
    double followingError_counts() const { return m_error_counts; }
    double remaining_counts() const;
    bool forward() const { return m_forward; }

private:
    motion::ProfileGenerator m_generator;
    Loop m_loop;
    int m_mode = 0;
    double m_error_counts = 0;  // the PSJ
    double m_actual_counts = 0; // the motor
    bool m_fpsArmed = false;
    bool m_fps = false;
    std::optional<double> m_stop_counts; // the bench's hard stop
    bool m_stopAhead = true;             // it lies forward of the motor
    bool m_overflow = false;    // the PSJ passed the trip point; cleared by SM1 and SM2
    double m_trip_counts = 2048;
    bool m_forward = true;
    struct CamSegment {
        double position_counts = 0;
        double speed_cps = 0;
        double maxAccel_cps2 = 1;
    };
    CamResult startCam(const CamSegment& segment, bool check);
    bool m_cam = false; // a cam runs: ramping, or holding its speed
    std::optional<CamSegment> m_camPending;
    double m_camEnd_counts = 0; // where the running segment's ramp ends
    SensorAction m_sensorAction = SensorAction::None;
    double m_sensorDecel_cps2 = 1;
    double m_depth_counts = 0;
};

} // namespace drive_core::pmc960
