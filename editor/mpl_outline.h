// The outline of an MPL program (PMC-960): its routines, one per "@<label>" line, in program order. Pure;
// any thread.
#pragma once

#include "outline.h"

namespace editor {

// Every line "@ <label> <text>" (7.1, L1025-1036) whose label is not '.' (a comment line) and is one P,
// B, F and L accept (22H-7AH, L909). Spaces are not stored by the controller, so they are skipped before
// the label. The detail is <text> with '_' read as a space (the manual's comments are written so). A label
// that appears again is listed where it is, its detail saying that the label search, which stops at the
// first, never reaches it.
Outline mplOutline(const QString& programText);

} // namespace editor
