// Insert/Delete functions as Scintilla messages, each wrapped in one undo action.
#include "line_commands.h"

#include <Qsci/qsciscintilla.h>

namespace editor {

namespace {
// Runs edit as a single undo step.
template <typename Edit> void asOneStep(QsciScintilla& editor, Edit edit) {
    editor.beginUndoAction();
    edit();
    editor.endUndoAction();
}

QString stripBreak(QString text) {
    while (text.endsWith(QLatin1Char('\n')) || text.endsWith(QLatin1Char('\r'))) text.chop(1);
    return text;
}
} // namespace

void deleteWord(QsciScintilla& editor) {
    asOneStep(editor, [&] { editor.SendScintilla(QsciScintilla::SCI_DELWORDRIGHT); });
}

void deleteToEndOfLine(QsciScintilla& editor) {
    asOneStep(editor, [&] { editor.SendScintilla(QsciScintilla::SCI_DELLINERIGHT); });
}

QString deleteLine(QsciScintilla& editor) {
    int line = 0;
    int index = 0;
    editor.getCursorPosition(&line, &index);
    const QString text = stripBreak(editor.text(line));
    asOneStep(editor, [&] {
        editor.SendScintilla(QsciScintilla::SCI_LINEDELETE);
        editor.setCursorPosition(qMin(line, editor.lines() - 1), 0);
    });
    return text;
}

void undeleteLine(QsciScintilla& editor, const QString& line) {
    int cursorLine = 0;
    int index = 0;
    editor.getCursorPosition(&cursorLine, &index);
    asOneStep(editor, [&] {
        editor.insertAt(line + lineBreak(editor), cursorLine, 0);
        editor.setCursorPosition(cursorLine, 0);
    });
}

void insertNewLine(QsciScintilla& editor) {
    int line = 0;
    int index = 0;
    editor.getCursorPosition(&line, &index);
    asOneStep(editor, [&] {
        editor.insertAt(lineBreak(editor), line, index);
        editor.setCursorPosition(line, index);
    });
}

void deleteEntireEditor(QsciScintilla& editor) {
    asOneStep(editor, [&] {
        editor.selectAll();
        editor.removeSelectedText();
    });
}

QString lineBreak(const QsciScintilla& editor) {
    switch (editor.eolMode()) {
    case QsciScintilla::EolWindows: return QStringLiteral("\r\n");
    case QsciScintilla::EolMac: return QStringLiteral("\r");
    case QsciScintilla::EolUnix: break;
    }
    return QStringLiteral("\n");
}

} // namespace editor
