// The outline of a BDS5 program: its labels and task entry points in program order (numbered labels,
// POWER-UP$, AUTO$, MANUAL$, ERROR$, VARIABLE$, BACKGROUND$, A$/B$/C$ with their switch), found with the
// drive's own line lexer. Pure; any thread.
#pragma once

#include <QString>

#include <vector>

namespace editor {

struct Bds5OutlineEntry {
    enum class Kind { Label, Task, Alarm };
    int line = 0; // 0-based editor line
    Kind kind = Kind::Label;
    QString name;   // "10$", "POWER-UP$", "A$"
    QString detail; // the alarm's switch and state ("I1 ON"), else the label line's comment, else the task's role
};

std::vector<Bds5OutlineEntry> bds5Outline(const QString& programText);

} // namespace editor
