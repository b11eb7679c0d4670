// BDS5 macro moves (MCA, MCI, MCD, MCGO; L2496-2579, L6862-6908): sections chained into one move of up to
// 30 acceleration segments (each section with the SCRV in force when it was defined), precalculated, beginning and
// ending at rest. Sections are kept as incremental distances (the manual: "all Macro moves are converted to Incremental
// before being executed"), each rounded to whole counts.
#pragma once

#include "drive_core/motion/profile_generator.h"

#include <optional>
#include <vector>

namespace drive_core::bds5 {

constexpr int kMaxMacroSegments = 30; // ERR 47 beyond (L7275)

class Bds5Macro {
public:
    void reset();
    // A section of `distance` counts (signed). Speeds in counts/s, positive: with both, traverse then end;
    // with one, it is the end speed and the traverse is the faster of start and end; with none, the section
    // continues at its start speed (L2508). 0 or the error: 40 direction change, 41 no speed, 42 too short,
    // 47 too many segments.
    int addSection(double distance, std::optional<double> first, std::optional<double> second, double acc_cps2,
                   double dec_cps2, motion::SCurve shape = motion::SCurve::Straight);
    // A dwell, only at the start or after a section ending at rest (ERR 44).
    int addDwell(double seconds);
    // MCGO: 0, or 43 when the last section does not end at rest or nothing was defined. Closes the
    // definition: the next section starts a new macro (L2522).
    int close();
    // Where the next MCA section starts from, relative to the first section's start.
    double definedDistance() const { return m_distance; }
    bool open() const { return !m_closed; }
    const std::vector<motion::Segment>& segments() const { return m_segments; }

private:
    void add(double duration_s, double accel_cps2, motion::SCurve shape = motion::SCurve::Straight);

    std::vector<motion::Segment> m_segments;
    double m_endSpeed = 0; // signed speed at the end of the last section
    double m_distance = 0; // counts, the sum of the sections
    bool m_closed = false;
};

} // namespace drive_core::bds5
