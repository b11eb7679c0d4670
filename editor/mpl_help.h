// F1 help for MPL (PMC-960) programs from the drive_core catalog: the command under the cursor (one to three
// letters: "A", "SM", "TGP"), an error code ("#B6"), and that topic's entry as rich text. Pure; any thread.
#pragma once

#include <QString>

namespace editor {

// The topic at a 0-based column of one line: the command whose letters (or arguments) the cursor is on,
// "@" on a label line, "#B6" on an error code. Empty when there is none.
QString mplTopicAt(const QString& line, int column);

// The catalog's entry as HTML (name, syntax, description, manual lines; parameter range and factory value;
// error meaning). Empty when the catalog has no such topic.
QString mplHelpHtml(const QString& topic);

} // namespace editor
