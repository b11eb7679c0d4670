// The motion profile generator shared by every drive family: moves and jogs built from acceleration
// segments, straight-line or S-curve (s_curve.h), one move executing and one pending (BDS5 §7.3). Positions
// are evaluated in closed form from the segment start, so a move lands exactly on its end position.
// No Qt, no wall clock: time comes in through step(dt).
#pragma once

#include "s_curve.h"

#include <deque>
#include <optional>
#include <vector>

namespace drive_core::motion {

enum class MoveKind {
    Position, // go to target_counts at velocity_cps, starting and ending at rest
    Jog,      // change speed to velocity_cps (signed) and hold it
};

struct MoveRequest {
    MoveKind kind = MoveKind::Position;
    double target_counts = 0; // Position: the absolute end position
    double velocity_cps = 0;  // Position: traverse speed (> 0); Jog: signed speed
    double accel_cps2 = 1;    // > 0
    double decel_cps2 = 1;    // > 0, average rates: S-curves keep the segment times of straight lines
    SCurve shape = SCurve::Straight;
};

// One piece of a profile: its velocity changes by accel_cps2 * duration_s, along `shape`.
struct Segment {
    double duration_s = 0; // +infinity for a jog's endless traverse
    double accel_cps2 = 0; // the average acceleration over the segment
    int number = 1;        // the drive's segment number (BDS5 SEG, Table 5.2)
    SCurve shape = SCurve::Straight;
};

class ProfileGenerator {
public:
    // Queues a position move; it starts when the motion before it has finished. Returns the move's id, or
    // nullopt when the buffer is full (one executing + one pending).
    std::optional<int> push(const MoveRequest& move);
    // Starts a jog at once from the present speed, cancelling whatever was commanded. Returns its id.
    int jog(const MoveRequest& jog);
    // A profile given as segments, from the present position and speed, starting at once (JT, JF, CONTINUE).
    // With endPosition it is a position move and lands exactly there; without, its last segment is
    // endless (give it an infinite duration). Cancels whatever was commanded. Returns its id.
    int start(std::vector<Segment> segments, std::optional<double> endPosition);
    // A position move given as segments from rest, queued like push() (macro moves, MRD). The distance is
    // endOffset from where the motion before it ends.
    std::optional<int> push(std::vector<Segment> segments, double endOffset);
    // Decelerates to rest at decel_cps2 now and cancels every command (BDS5 S, errors).
    void stop(double decel_cps2);
    // Sets the commanded position without motion (NORM, ZPE); only meaningful at rest.
    void setPosition(double counts);

    // Held, commanded motion waits before it starts (BDS5 GATEMODE: begin on the GATE input).
    void setHeld(bool held) { m_held = held; }
    bool held() const { return m_held; }

    void step(double dt_s);

    double position() const { return m_position; }
    double velocity() const { return m_velocity; }
    double acceleration() const;
    bool moving() const { return m_active.has_value(); }
    bool jogging() const { return m_active && m_active->request.kind == MoveKind::Jog; }
    bool full() const { return m_active && !m_pending.empty(); }
    // The segment number of the executing motion, 0 at rest.
    int segment() const;
    // The end position of the last commanded move (BDS5 PFNL); the present position at rest or jogging.
    double finalPosition() const;
    // The id of the motion executing now (0 at rest) and of the last one commanded.
    int activeId() const { return m_active ? m_active->id : 0; }
    int lastId() const { return m_nextId - 1; }
    // Whether segment n of motion id has started, or that motion is over (BDS5 W n; W 0 waits for rest).
    bool reached(int id, int segment) const;

    // The segments of a position move from rest at `from` (exposed for tests and plots).
    static std::vector<Segment> plan(double from, const MoveRequest& move);

private:
    struct Motion {
        int id = 0;
        MoveRequest request;
        std::vector<Segment> segments;
        std::size_t index = 0; // executing segment
        bool planned = false;  // segments given: begin() must not plan a trapezoid
        double endOffset = 0;  // planned position moves: the end relative to the start
        double elapsed_s = 0;  // time into that segment
        double segmentStartPosition = 0;
        double segmentStartVelocity = 0;
    };

    void begin(Motion motion);
    void startNext();

    std::optional<Motion> m_active;
    std::deque<Motion> m_pending;
    double m_position = 0;
    double m_velocity = 0;
    int m_nextId = 1;
    bool m_held = false;
};

} // namespace drive_core::motion
