// F1 help and completion for ServoBASIC Plus (.bas) programs from the drive_core SC750 catalog: the word
// under the cursor ("GO.VEL", "run.speed", "MID$"), its statement, function or variable entry as rich text
// (L880-L916: cursor on a keyword, F1), and the names that complete a prefix. Pure functions; any thread.
#pragma once

#include <QString>
#include <QStringList>

namespace editor {

// Letters, digits, '.', '_' and '$' make up ServoBASIC words (GO.VEL, MID$).
bool isServoBasicWordChar(QChar c);

// The word at a 0-based column of one line or just before it. Empty when
// the cursor is on no word.
QString servoBasicTopicAt(const QString& line, int column);

// The catalog names (statements, functions, predefined variables and parameters) that start with prefix and
// are longer than it, any case, sorted.
QStringList servoBasicCompletions(const QString& prefix);

// The catalog entry for a word as HTML (syntax, type, range, default, manual lines); any case. Empty when
// the catalog has no such statement, function or predefined variable.
QString servoBasicHelpHtml(const QString& word);

} // namespace editor
