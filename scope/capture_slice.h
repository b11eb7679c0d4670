// The part of a capture inside a time range, widget-free: what Scope > Save CSV and Export Plot write when
// the user asks for the visible range only. The slice keeps its samples' times (Capture::start_s), so the
// file it is written to loads back where it was cut from.
#pragma once

#include "capture.h"

namespace scope {

// The samples whose time lies in [from_s, to_s] (a sample within a millionth of an interval of either end
// counts as inside: times are start + i * interval, not exact). An empty capture of the same channels when
// none does.
Capture sliceCapture(const Capture& capture, double from_s, double to_s);

} // namespace scope
