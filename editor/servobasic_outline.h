// The outline of a ServoBASIC Plus program (SC750): its labels, SUBs and INTERRUPT routines in program
// order. Pure; any thread.
#pragma once

#include "outline.h"

namespace editor {

// A label is a name that starts a line and ends in a colon ("Loop_Again:", L1121-1136), not a keyword or
// predefined variable (the compiler's own rule); a SUB is "SUB name" (Task); an INTERRUPT routine is
// "INTERRUPT source" (Handler, its detail the source's condition from the catalog, L1841-1862). Names are
// shown as written (ServoBASIC ignores case). The detail is the line's comment when it has one. A line the
// compiler would refuse is read as far as it can be: the outline is for a program being written.
Outline servoBasicOutline(const QString& programText);

} // namespace editor
