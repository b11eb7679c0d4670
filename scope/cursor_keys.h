// The scope's A/B cursors moved from the keyboard, widget-free: which key does what and where the cursors
// go, so that a user without a mouse (or wanting one-sample steps) reads a period as well as with one.
//   C                 place both cursors in view (a quarter and three quarters across), A active
//   Space             switch the active cursor (A <-> B)
//   Shift+Left/Right  move the active cursor one sample (a 500th of the view for live data)
//   Ctrl+Shift+L/R    move it a tenth of the view
// A cursor moved by key never leaves the visible time range.
#pragma once

namespace scope {

enum class CursorKey { Place, SwitchActive, StepBack, StepForward, JumpBack, JumpForward };

struct CursorPair {
    double a_s = 0;
    double b_s = 0;
    int active = 0; // 0: A, 1: B
};

struct CursorView {
    double from_s = 0; // the visible time range
    double to_s = 1;
    double sample_s = 0; // the trace's sample interval; 0 for unevenly spaced (live) samples
};

constexpr double kCursorJumpOfView = 0.1;
constexpr double kCursorStepsPerViewLive = 500;

CursorPair applyCursorKey(CursorPair cursors, CursorKey key, const CursorView& view);

} // namespace scope
