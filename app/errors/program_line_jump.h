// ProgramLineJump: shows the editor line a drive program line came from ("ERR 83 LINE 12" means the 12th
// line the drive holds, counted without the comment lines a download leaves out, L1157).
#pragma once

namespace editor {
class ProgramEditor;
}

namespace app {

class ProgramLineJump {
public:
    // Moves the cursor to the source of drive line driveLine (1-based) and selects that line. Returns the
    // 1-based editor line, or 0 if the program in the editor has no such line.
    static int show(editor::ProgramEditor& editor, int driveLine);
    // The same for editor line `line` (1-based) itself, for drives whose lines are the source's (SC750).
    static int showEditorLine(editor::ProgramEditor& editor, int line);
};

} // namespace app
