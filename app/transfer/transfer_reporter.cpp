// TransferReporter: status bar, terminal notices and new tabs for transfers.
#include "transfer_reporter.h"

#include "families/bds5/drive_connection.h"
#include "editor_area.h"
#include "editor_tabs.h"
#include "main_window.h"
#include "terminal_widget.h"
#include "transfer_dialog.h"

#include "editor/program_editor.h"

#include <QFileInfo>
#include <QStatusBar>

namespace app {

bool TransferReporter::canStart(MainWindow& window) {
    QString why;
    if (TransferDialog::active())
        why = QObject::tr("A transfer is already running: wait for it or cancel it.");
    else if (!window.connection().isConnected() || !window.connection().session())
        why = QObject::tr("Not connected to a drive: use Drive > Connect.");
    if (why.isEmpty()) return true;
    window.statusBar()->showMessage(why, kStatusMs);
    return false;
}

void TransferReporter::report(MainWindow& window, const serialport::Bds5TransferResult& result,
                              const QString& fileName) {
    window.statusBar()->showMessage(result.summary, kStatusMs);
    window.terminal()->displayNotice(result.summary);
    for (const serialport::Bds5LineError& e : result.errors) {
        const QString what = e.error.code ? serialport::describeError(e.error) : e.error.message;
        if (e.sourceLine > 0)
            window.terminal()->displayNotice(
                QObject::tr("%1 line %2: %3 (%4)").arg(fileName).arg(e.sourceLine).arg(what, e.sent));
    }
}

editor::ProgramEditor* TransferReporter::openNewDocument(MainWindow& window, const QString& baseName,
                                                         const QString& text) {
    EditorTabs& tabs = *window.editorArea()->tabs();
    const QFileInfo info(baseName);
    QString name = baseName;
    for (int n = 2;; ++n) {
        bool taken = false;
        for (const editor::ProgramEditor* e : tabs.editors())
            taken = taken || tabs.displayName(e) == name;
        if (!taken) break;
        name = QStringLiteral("%1-%2.%3").arg(info.completeBaseName()).arg(n).arg(info.suffix());
    }
    editor::ProgramEditor* editor = tabs.addEditor(name);
    editor->setText(text);
    editor->setModified(true);
    tabs.refreshTab(editor);
    return editor;
}

void TransferReporter::showLine(editor::ProgramEditor& editor, int line) {
    if (line < 1) return;
    editor.setCursorPosition(line - 1, 0);
    editor.ensureLineVisible(line - 1);
}

} // namespace app
