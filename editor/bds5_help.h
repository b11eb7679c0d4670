// F1 help for BDS5 programs from the drive_core catalog: which topic the word under the cursor names
// (a command, a variable, `ERR 25`), and that topic's entry as rich text. Pure functions; any thread.
#pragma once

#include <QString>

namespace editor {

// The help topic at a 0-based column of one line: "MA", "VMAX", "X12", "ERR 25" (a number after ERR, or ERR
// before a number), "$" for a label. Empty when the cursor is on no word, in a comment or in a string.
QString bds5TopicAt(const QString& line, int column);

// The catalog's entry for a topic as HTML (syntax, units, limits, description, manual lines); a bare
// number is an error code. Empty when the catalog has no such command, variable or error.
QString bds5HelpHtml(const QString& topic);

} // namespace editor
