// TransferReporter: what the Program and Variables menus share — checking a transfer may start, showing
// its result (status bar and terminal, the drive's words), and opening text from the drive in a new tab.
// GUI thread only.
#pragma once

#include "serialport/bds5_transfer.h"

#include <QString>

namespace editor {
class ProgramEditor;
}

namespace app {

class MainWindow;

class TransferReporter {
public:
    // True when connected, at a session, and no other transfer runs; otherwise says why in the status bar.
    static bool canStart(MainWindow& window);
    // The summary in the status bar and the terminal, and each error with its line in the terminal.
    static void report(MainWindow& window, const serialport::Bds5TransferResult& result,
                       const QString& fileName);
    // A new tab named like baseName ("drive-program.bds", "drive-program-2.bds", ...) holding text; modified,
    // so closing it asks to save.
    static editor::ProgramEditor* openNewDocument(MainWindow& window, const QString& baseName,
                                                  const QString& text);
    // Shows a 1-based line of editor and puts the cursor on it.
    static void showLine(editor::ProgramEditor& editor, int line);

    static constexpr int kStatusMs = 15000;
};

} // namespace app
