// The outline of a BDS5 program: its labels and task entry points in program order (numbered labels,
// POWER-UP$, AUTO$, MANUAL$, ERROR$, VARIABLE$, BACKGROUND$, A$/B$/C$ with their switch), found with the
// drive's own line lexer. Pure; any thread.
#pragma once

#include "outline.h"

namespace editor {

// Labels (Kind::Label), dedicated task labels (Task) and alarm tasks A$/B$/C$ (Handler). The detail is
// the alarm's switch and state ("I1 ON"), else the label line's comment, else the task's role.
Outline bds5Outline(const QString& programText);

} // namespace editor
