// What the Outline dock lists for a program, in any drive language: its labels and entry points in
// program order. Each language finds them its own way (editor/<language>_outline.h); the dock, Go to
// label and the run dialogs read only this. Pure data; any thread.
#pragma once

#include <QRegularExpression>
#include <QString>
#include <QStringList>

#include <vector>

namespace editor {

struct OutlineEntry {
    // Label: a jump target (BDS5 "10$", ServoBASIC "Loop_Again:", an MPL routine "@H").
    // Task: an entry point of its own (BDS5 POWER-UP$ … BACKGROUND$, a ServoBASIC SUB).
    // Handler: what runs when a condition arises (BDS5 A$/B$/C$ alarms, a ServoBASIC INTERRUPT routine).
    enum class Kind { Label, Task, Handler };
    int line = 0; // 0-based editor line
    Kind kind = Kind::Label;
    QString name;   // as the program's own commands name it: "10$", "POWER-UP$", "H", "SEEKHOME"
    QString detail; // the line's comment, else what the entry is for
};

using Outline = std::vector<OutlineEntry>;
using OutlineOf = Outline (*)(const QString& programText);

// The program's lines as the editor numbers them: a file from a drive or DOS ends its lines in CR LF (or CR),
// and a label's line must not keep the CR ("10$\r" is no label).
inline QStringList programLines(const QString& programText) {
    static const QRegularExpression kLineEnd(QStringLiteral("\r\n|\n|\r"));
    return programText.split(kLineEnd);
}

} // namespace editor
