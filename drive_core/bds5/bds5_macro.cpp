// BDS5 macro-move sections.
#include "bds5_macro.h"

#include <algorithm>
#include <cmath>

namespace drive_core::bds5 {

void Bds5Macro::reset() {
    *this = Bds5Macro{};
}

void Bds5Macro::add(double duration_s, double accel_cps2, motion::SCurve shape) {
    if (duration_s <= 0) return;
    m_segments.push_back({duration_s, accel_cps2, int(m_segments.size()) + 1, shape});
}

int Bds5Macro::addSection(double distance, std::optional<double> first, std::optional<double> second, double acc,
                          double dec, motion::SCurve shape) {
    if (m_closed) reset(); // a new definition after MCGO starts over (L2522)
    distance = std::round(distance);
    const double direction = distance < 0 ? -1.0 : 1.0;
    const double start = std::abs(m_endSpeed);
    if (start > 0 && (m_endSpeed < 0) != (direction < 0)) return 40; // CHANGED DIRECTION
    double traverse = start;
    double end = start;
    if (first && second) {
        traverse = *first;
        end = *second;
    } else if (first) {
        end = *first;
        traverse = std::max(start, end);
    }
    if (traverse <= 0 || traverse < 0 || end < 0) return 41; // MOVE NEEDS MOTION
    const double rate1 = traverse > start ? acc : dec;
    const double rate2 = end > traverse ? acc : dec;
    const double ramp1 = std::abs(traverse * traverse - start * start) / (2 * rate1);
    const double ramp2 = std::abs(end * end - traverse * traverse) / (2 * rate2);
    const double cruise = std::abs(distance) - ramp1 - ramp2;
    if (cruise < -1e-9) return 42; // MOVE w/o TIME: the section cannot reach its speeds in its distance
    const auto before = m_segments;
    add(std::abs(traverse - start) / rate1, direction * (traverse > start ? rate1 : -rate1), shape);
    add(std::max(cruise, 0.0) / traverse, 0);
    add(std::abs(end - traverse) / rate2, direction * (end > traverse ? rate2 : -rate2), shape);
    if (int(m_segments.size()) > kMaxMacroSegments) {
        m_segments = before;
        return 47; // MCI/MCA TOO COMPLEX
    }
    m_endSpeed = direction * end;
    m_distance += distance;
    return 0;
}

int Bds5Macro::addDwell(double seconds) {
    if (m_closed) reset();
    if (m_endSpeed != 0) return 44; // MCD w/MACRO MOVING
    if (int(m_segments.size()) >= kMaxMacroSegments) return 47;
    add(seconds, 0);
    return 0;
}

int Bds5Macro::close() {
    if (m_segments.empty() || m_endSpeed != 0) return 43; // MACRO NOT READY
    m_closed = true;
    return 0;
}

} // namespace drive_core::bds5
