// ProgramLineJump: drive line -> editor line, through the same map downloads use.
#include "program_line_jump.h"

#include "editor/program_editor.h"
#include "serialport/bds5_program_text.h"

namespace app {

int ProgramLineJump::show(editor::ProgramEditor& editor, int driveLine) {
    // Downloads strip comments by default (Motion Link's usual choice): count lines the same way.
    const auto text = serialport::Bds5ProgramText::prepare(editor.text(), true);
    return showEditorLine(editor, text.sourceLine(driveLine));
}

int ProgramLineJump::showEditorLine(editor::ProgramEditor& editor, int line) {
    if (line <= 0 || line > editor.lines()) return 0;
    QString shown = editor.text(line - 1);
    while (shown.endsWith(QLatin1Char('\n')) || shown.endsWith(QLatin1Char('\r'))) shown.chop(1);
    editor.ensureLineVisible(line - 1);
    editor.setSelection(line - 1, int(shown.size()), line - 1, 0); // the cursor ends at the line's start
    editor.setFocus();
    return line;
}

} // namespace app
