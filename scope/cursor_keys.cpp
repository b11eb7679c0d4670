// Keyboard moves of the A/B cursors.
#include "cursor_keys.h"

#include <algorithm>

namespace scope {

CursorPair applyCursorKey(CursorPair cursors, CursorKey key, const CursorView& view) {
    const double span = view.to_s - view.from_s;
    const double step = view.sample_s > 0 ? view.sample_s : span / kCursorStepsPerViewLive;
    double move = 0;
    switch (key) {
    case CursorKey::Place: return {view.from_s + span / 4, view.from_s + span * 3 / 4, 0};
    case CursorKey::SwitchActive: cursors.active = 1 - cursors.active; return cursors;
    case CursorKey::StepBack: move = -step; break;
    case CursorKey::StepForward: move = step; break;
    case CursorKey::JumpBack: move = -span * kCursorJumpOfView; break;
    case CursorKey::JumpForward: move = span * kCursorJumpOfView; break;
    }
    double& t = cursors.active == 0 ? cursors.a_s : cursors.b_s;
    t = std::clamp(t + move, std::min(view.from_s, view.to_s), std::max(view.from_s, view.to_s));
    return cursors;
}

} // namespace scope
