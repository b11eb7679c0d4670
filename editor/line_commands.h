// Motion Link's Insert/Delete editor functions (manual L1164-1170) on any QScintilla editor: delete a
// word, to the end of the line, a whole line; undelete a line; insert a new line; clear the editor. Each
// is one undo step. GUI thread only.
#pragma once

#include <QString>

class QsciScintilla;

namespace editor {

// DELETE A WORD (^T): deletes from the cursor to the start of the next word.
void deleteWord(QsciScintilla& editor);
// DELETE TO END OF LINE (^Q^Y): deletes from the cursor to the end of its line (not the line break).
void deleteToEndOfLine(QsciScintilla& editor);
// DELETE A LINE (^Y): deletes the cursor's line with its line break; returns its text (without the break)
// for undeleteLine. The cursor ends at the start of the line that moved up.
QString deleteLine(QsciScintilla& editor);
// UNDELETE A LINE (^U): inserts line as a whole line above the cursor's line and puts the cursor at its
// start.
// chosen: the manual says "starting at the cursor"; a whole line is put back above the cursor's line
// (what ^Y took away comes back whole) rather than splitting the line the cursor is in.
void undeleteLine(QsciScintilla& editor, const QString& line);
// INSERT A NEW LINE (^N): breaks the line at the cursor and leaves the cursor where it was, so at the
// start of a line it opens a blank line above.
void insertNewLine(QsciScintilla& editor);
// DELETE ENTIRE EDITOR (^K^Y): clears the text as one undo step (Undo brings it back).
void deleteEntireEditor(QsciScintilla& editor);
// The editor's line break ("\r\n" or "\n"), from its EOL mode.
QString lineBreak(const QsciScintilla& editor);

} // namespace editor
