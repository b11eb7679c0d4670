// Tabs, recent files, per-tab unsaved prompts, the two keymaps typed into a real main window, blocks,
// merge and autosave, files changed on disk by other programs — as a user sees them in the window, the tab
// bar, the menus, the info bars and the status bar.
#include "app/editing/autosaver.h"
#include "app/editing/disk_change_bar.h"
#include "app/editing/disk_watcher.h"
#include "app/editing/document_controller.h"
#include "app/editing/editor_actions.h"
#include "app/editing/editor_area.h"
#include "app/editing/editor_tabs.h"
#include "app/main_window.h"
#include "app/editing/recent_files.h"

#include "editor/editor_size_dialog.h"
#include "editor/find_bar.h"
#include "editor/keymap.h"
#include "editor/program_editor.h"

#include <QApplication>
#include <QClipboard>
#include <QFile>
#include <QLabel>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QSaveFile>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTest>

using app::MainWindow;

namespace {
constexpr int kTimeoutMs = 30000; // a file watch's event, on a loaded machine

QString writeFile(const QTemporaryDir& dir, const QString& name, const QByteArray& bytes) {
    const QString path = dir.filePath(name);
    QFile file(path);
    if (file.open(QIODevice::WriteOnly)) file.write(bytes);
    return path;
}

// As many editors save: a new file written beside the old one, then renamed over it.
bool saveAtomically(const QString& path, const QByteArray& bytes) {
    QSaveFile file(path);
    return file.open(QIODevice::WriteOnly) && file.write(bytes) == bytes.size() && file.commit();
}

QByteArray readAll(const QString& path) {
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

QString statusLabel(const MainWindow& window, const char* name) {
    const auto* label = window.statusBar()->findChild<QLabel*>(QLatin1String(name));
    return label ? label->text() : QString();
}

int cursorLine(const QsciScintilla& editor) {
    int line = 0;
    int index = 0;
    editor.getCursorPosition(&line, &index);
    return line;
}
} // namespace

class EditorTabsTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true); // never touch the user's settings
        QCoreApplication::setOrganizationName(QStringLiteral("ServoDesk"));
        QCoreApplication::setApplicationName(QStringLiteral("ServoDeskTabsTest"));
        qputenv("SERVODESK_RECOVERY_DIR", m_recovery.path().toUtf8());
        qRegisterMetaType<editor::ProgramEditor*>();
    }
    void init() { QSettings().clear(); }

    void filesOpenInTabsWithTheirTypeAndRecentList() {
        QTemporaryDir dir;
        const QString program = writeFile(dir, QStringLiteral("MOTION.BDS"), "10$\r\nJ 100\r\nB\r\n");
        const QString vars = writeFile(dir, QStringLiteral("SETUP.VAR"), "X1=4096\r\n");
        MainWindow window;
        app::EditorArea* area = window.editorArea();
        app::EditorTabs* tabs = area->tabs();
        QSignalSpy changed(&window, &MainWindow::currentEditorChanged);
        QCOMPARE(tabs->count(), 1); // the sample program

        QVERIFY(area->documents()->openFile(program));
        QVERIFY(area->documents()->openFile(vars));
        QCOMPARE(tabs->count(), 3);
        QCOMPARE(tabs->tabText(2), QStringLiteral("SETUP.VAR"));
        QVERIFY(!tabs->tabIcon(2).isNull());
        QCOMPARE(window.editor()->filePath(), vars);
        QVERIFY(window.windowTitle().startsWith(QStringLiteral("SETUP.VAR")));
        QVERIFY(changed.size() >= 2);
        QCOMPARE(changed.last().at(0).value<editor::ProgramEditor*>(), window.editor());

        QVERIFY(area->documents()->openFile(program)); // already open: its tab comes forward
        QCOMPARE(tabs->count(), 3);
        QCOMPARE(window.editor()->filePath(), program);
        QCOMPARE(area->recentFiles()->files(), QStringList({program, vars}));
        QMenu menu;
        area->recentFiles()->fillMenu(&menu);
        QCOMPARE(menu.actions().at(0)->text(), QStringLiteral("&1  MOTION.BDS"));
        QCOMPARE(menu.actions().at(1)->text(), QStringLiteral("&2  SETUP.VAR"));

        // Each tab has its own text, modified state and undo.
        window.editor()->append(QStringLiteral("P \"X\"\r\n"));
        QCOMPARE(tabs->tabText(1), QStringLiteral("MOTION.BDS*"));
        QCOMPARE(tabs->tabText(2), QStringLiteral("SETUP.VAR"));
        tabs->setCurrentIndex(2);
        QCOMPARE(window.editor()->text(), QStringLiteral("X1=4096\r\n"));
        QVERIFY(!window.editor()->isUndoAvailable());
    }

    void closingAModifiedTabAsksWithoutBlocking() {
        QTemporaryDir dir;
        const QString program = writeFile(dir, QStringLiteral("A.BDS"), "B\n");
        MainWindow window;
        window.show();
        app::EditorTabs* tabs = window.editorArea()->tabs();
        QVERIFY(window.editorArea()->documents()->openFile(program));
        window.editor()->append(QStringLiteral("J 1\n"));
        window.editorArea()->documents()->closeCurrentTab();
        auto* box = window.findChild<QMessageBox*>(QStringLiteral("unsavedChangesBox"));
        QVERIFY(box);
        QTRY_VERIFY(box->isVisible());
        QVERIFY(box->text().contains(QStringLiteral("A.BDS")));
        QCOMPARE(tabs->count(), 2); // still open while the question is asked
        QTest::mouseClick(box->button(QMessageBox::Discard), Qt::LeftButton);
        QCOMPARE(tabs->count(), 1);
        QCOMPARE(readAll(program), QByteArray("B\n")); // discarded, not written
        // Closing the last tab leaves an empty program, so there is always an editor.
        window.editorArea()->documents()->closeCurrentTab();
        QCOMPARE(tabs->count(), 1);
        QVERIFY(window.editor());
        QCOMPARE(tabs->tabText(0), QStringLiteral("untitled.bds"));
    }

    void ctrlYDeletesALineOnlyInTheClassicKeymap() {
        MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowActive(&window));
        editor::ProgramEditor* ed = window.editor();
        ed->setText(QStringLiteral("A\nB\nC\n"));
        ed->setFocus();
        ed->setCursorPosition(1, 0);
        QCOMPARE(statusLabel(window, "keymapLabel"), QStringLiteral("Modern keys"));

        QTest::keyClick(ed, Qt::Key_Y, Qt::ControlModifier); // modern: redo, nothing to redo
        QCOMPARE(ed->text(), QStringLiteral("A\nB\nC\n"));
        QTest::keyClick(ed, Qt::Key_F, Qt::ControlModifier);
        QVERIFY(window.editorArea()->findBar()->isVisible());
        window.editorArea()->findBar()->hide();
        ed->setFocus();

        QAction* classic = window.findChild<QAction*>(QStringLiteral("classicKeysAction"));
        QVERIFY(classic);
        classic->trigger(); // Edit > Classic Motion Link Keys
        QCOMPARE(QSettings().value(editor::Keymap::kSettingsKey).toString(), editor::Keymap::kClassic);
        QCOMPARE(window.editorArea()->keymapName(), editor::Keymap::kClassic);
        QCOMPARE(statusLabel(window, "keymapLabel"), QStringLiteral("Classic keys"));
        auto* deleteLine = window.editorArea()->actions()->action(editor::EditorCommand::DeleteLine);
        QCOMPARE(deleteLine->shortcut(), QKeySequence(Qt::CTRL | Qt::Key_Y)); // what the Edit menu shows

        QTest::keyClick(ed, Qt::Key_Y, Qt::ControlModifier); // ^Y: DELETE A LINE
        QCOMPARE(ed->text(), QStringLiteral("A\nC\n"));
        QTest::keyClick(ed, Qt::Key_U, Qt::ControlModifier); // ^U: UNDELETE A LINE
        QCOMPARE(ed->text(), QStringLiteral("A\nB\nC\n"));

        // ^K^B at A, ^X ^X down, ^K^K: the block is A and B; ^K^C copies it; ^K^P pastes it.
        ed->setCursorPosition(0, 0);
        QTest::keyClick(ed, Qt::Key_K, Qt::ControlModifier);
        QVERIFY(statusLabel(window, "keymapLabel").contains(QStringLiteral("^K")));
        QTest::keyClick(ed, Qt::Key_B, Qt::ControlModifier);
        QTest::keyClick(ed, Qt::Key_X, Qt::ControlModifier);
        QTest::keyClick(ed, Qt::Key_X, Qt::ControlModifier);
        QTest::keyClick(ed, Qt::Key_K, Qt::ControlModifier);
        QTest::keyClick(ed, Qt::Key_K, Qt::ControlModifier);
        QCOMPARE(ed->selectedText(), QStringLiteral("A\nB\n"));
        QTest::keyClick(ed, Qt::Key_K, Qt::ControlModifier);
        QTest::keyClick(ed, Qt::Key_C, Qt::ControlModifier);
        QCOMPARE(QApplication::clipboard()->text(), QStringLiteral("A\nB\n"));
        ed->SendScintilla(QsciScintilla::SCI_DOCUMENTEND);
        QTest::keyClick(ed, Qt::Key_K, Qt::ControlModifier);
        QTest::keyClick(ed, Qt::Key_P, Qt::ControlModifier);
        QCOMPARE(ed->text(), QStringLiteral("A\nB\nC\nA\nB\n"));

        // ^Q^F finds, ^L repeats the last find.
        QTest::keyClick(ed, Qt::Key_Q, Qt::ControlModifier);
        QTest::keyClick(ed, Qt::Key_F, Qt::ControlModifier);
        editor::FindBar* find = window.editorArea()->findBar();
        QVERIFY(find->isVisible());
        find->setSearchText(QStringLiteral("B"));
        ed->setFocus();
        ed->setCursorPosition(0, 0);
        QTest::keyClick(ed, Qt::Key_L, Qt::ControlModifier);
        QCOMPARE(cursorLine(*ed), 1);
        QTest::keyClick(ed, Qt::Key_L, Qt::ControlModifier);
        QCOMPARE(cursorLine(*ed), 4);
        QCOMPARE(find->statusText(), QStringLiteral("Match 2 of 2"));

        window.editorArea()->applyKeymap(editor::Keymap::kModern); // and back: ^Y no longer deletes
        QTest::keyClick(ed, Qt::Key_Y, Qt::ControlModifier);
        QCOMPARE(ed->text(), QStringLiteral("A\nB\nC\nA\nB\n"));
    }

    void f10OpensTheMenuBarInTheClassicKeymap() {
        MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowActive(&window));
        editor::ProgramEditor* ed = window.editor();
        ed->setFocus();
        QTest::keyClick(ed, Qt::Key_F10); // modern: F10 is not the editor's
        QVERIFY(!window.menuBar()->activeAction());
        window.editorArea()->applyKeymap(editor::Keymap::kClassic);
        QTest::keyClick(ed, Qt::Key_F10);
        QVERIFY(window.menuBar()->activeAction());
        QCOMPARE(window.menuBar()->activeAction()->text(), QStringLiteral("&File"));
        // The classic table is one Help click away.
        QWidget* help = window.editorArea()->showClassicKeys();
        auto* text = help->findChild<QPlainTextEdit*>();
        QVERIFY(text && text->toPlainText().contains(QStringLiteral("MARK START OF BLOCK       ^K^B")));
    }

    void saveBlockAndMergeFileThroughTheEditMenu() {
        QTemporaryDir dir;
        MainWindow window;
        editor::ProgramEditor* ed = window.editor();
        ed->setText(QStringLiteral("10$\nJ 100\nW 2\nB\n"));
        ed->setSelection(1, 0, 3, 0);
        app::EditorActions* actions = window.editorArea()->actions();
        const QString block = dir.filePath(QStringLiteral("JOG.BDS"));
        QVERIFY(actions->saveBlockTo(block));
        QCOMPARE(readAll(block), QByteArray("J 100\nW 2\n"));
        ed->setCursorPosition(3, 0);
        QVERIFY(actions->mergeFileFrom(block));
        QCOMPARE(ed->text(), QStringLiteral("10$\nJ 100\nW 2\nJ 100\nW 2\nB\n"));
        QVERIFY(statusLabel(window, "editorSizeLabel").contains(QStringLiteral("of 6")));
        QVERIFY(window.statusBar()->currentMessage().contains(QStringLiteral("Merged JOG.BDS")));
        const QString pdf = dir.filePath(QStringLiteral("JOG.pdf"));
        QVERIFY(actions->printToPdf(pdf));
        QVERIFY(readAll(pdf).startsWith("%PDF-"));
    }

    void sizeOfEditorShowsLinesAndBytesLeft() {
        MainWindow window;
        window.editor()->setText(QStringLiteral("10$\nJ 100\nB\n"));
        auto* dialog = window.editorArea()->actions()->showSize();
        QVERIFY(dialog->isVisible());
        QCOMPARE(dialog->size().lines, 3);
        QCOMPARE(dialog->size().bytes, 12);
        QVERIFY2(dialog->figuresText().contains(QStringLiteral("3 of 2,000 lines used, 1,997 left")),
                 qPrintable(dialog->figuresText()));
        QVERIFY(dialog->figuresText().contains(QStringLiteral("12 of 24,000 bytes used, 23,988 left")));
        window.editor()->append(QStringLiteral("P 1\n")); // follows the edits while open
        QCOMPARE(dialog->size().lines, 4);
        QCOMPARE(statusLabel(window, "editorSizeLabel"), QStringLiteral("Line 1 of 4 \u00b7 16 of 24,000 bytes"));
    }

    void autosaveWritesChangesAndASaveRemovesThem() {
        QTemporaryDir dir;
        const QString program = writeFile(dir, QStringLiteral("A.BDS"), "B\n");
        MainWindow window;
        QVERIFY(window.editorArea()->documents()->openFile(program));
        QSignalSpy written(window.editorArea()->autosaver(), &app::Autosaver::buffersWritten);
        window.editor()->append(QStringLiteral("J 1\n"));
        QVERIFY(written.wait(app::Autosaver::kDelayMs + 3000));
        const QString session = window.editorArea()->recoveryStore().sessionDirectory();
        QCOMPARE(QDir(session).entryList({QStringLiteral("*.json")}).size(), 1);
        window.editorArea()->documents()->save();
        QCOMPARE(QDir(session).entryList({QStringLiteral("*.json")}).size(), 0);
    }

    // Issue 19 (9): a file changed on disk by another program still showed the old text.
    void anUnmodifiedTabReloadsWhenItsFileChangesOnDisk() {
        QTemporaryDir dir;
        const QString path = writeFile(dir, QStringLiteral("MOTION.BDS"), "10$\nJ 100\nB\n");
        MainWindow window;
        window.show();
        app::EditorArea* area = window.editorArea();
        QVERIFY(area->documents()->openFile(path));
        editor::ProgramEditor* ed = window.editor();

        writeFile(dir, QStringLiteral("MOTION.BDS"), "10$\nJ 200\nB\n"); // written in place
        QTRY_COMPARE_WITH_TIMEOUT(ed->text(), QStringLiteral("10$\nJ 200\nB\n"), kTimeoutMs);
        QVERIFY(!ed->isModified());
        QCOMPARE(window.statusBar()->currentMessage(), QStringLiteral("Reloaded MOTION.BDS: changed on disk"));
        QVERIFY(!area->diskChangeBar()->isVisible()); // nothing to ask: the tab had no edits

        // Saved by an editor that renames a new file over the old one, twice: the new file is watched too.
        QVERIFY(saveAtomically(path, "10$\nJ 300\nB\n"));
        QTRY_COMPARE_WITH_TIMEOUT(ed->text(), QStringLiteral("10$\nJ 300\nB\n"), kTimeoutMs);
        QVERIFY(saveAtomically(path, "10$\nJ 400\nB\n"));
        QTRY_COMPARE_WITH_TIMEOUT(ed->text(), QStringLiteral("10$\nJ 400\nB\n"), kTimeoutMs);
        writeFile(dir, QStringLiteral("MOTION.BDS"), "10$\nJ 500\nB\n"); // in place: only the file's watch sees it
        QTRY_COMPARE_WITH_TIMEOUT(ed->text(), QStringLiteral("10$\nJ 500\nB\n"), kTimeoutMs);

        // Deleted, then written again.
        QVERIFY(QFile::remove(path));
        writeFile(dir, QStringLiteral("MOTION.BDS"), "10$\nJ 600\nB\n");
        QTRY_COMPARE_WITH_TIMEOUT(ed->text(), QStringLiteral("10$\nJ 600\nB\n"), kTimeoutMs);
        QVERIFY(!ed->isModified());
        QCOMPARE(area->tabs()->count(), 2); // the sample program and MOTION.BDS, reloaded in its own tab
    }

    void ourOwnSaveSaysNothingAndEditsAreAskedAbout() {
        QTemporaryDir dir;
        const QString path = writeFile(dir, QStringLiteral("A.BDS"), "B\n");
        MainWindow window;
        window.show();
        app::EditorArea* area = window.editorArea();
        app::DiskChangeBar* bar = area->diskChangeBar();
        QVERIFY(area->documents()->openFile(path));
        editor::ProgramEditor* ed = window.editor();
        QSignalSpy examined(area->diskWatcher(), &app::DiskWatcher::examined);

        ed->append(QStringLiteral("J 1\n"));
        area->documents()->save(); // written by ServoDesk: looked at, found to be ours, nothing asked
        QTRY_VERIFY_WITH_TIMEOUT(!examined.isEmpty(), kTimeoutMs);
        for (const QList<QVariant>& look : std::as_const(examined))
            QCOMPARE(look.at(1).value<app::DiskWatcher::Outcome>(), app::DiskWatcher::Outcome::Unchanged);
        QVERIFY(!bar->isVisible());
        QCOMPARE(ed->text(), QStringLiteral("B\nJ 1\n"));

        // Another program writes the file while the tab has unsaved edits: asked, the edits stay.
        ed->append(QStringLiteral("J 2\n"));
        writeFile(dir, QStringLiteral("A.BDS"), "P \"OTHER\"\n");
        QTRY_VERIFY_WITH_TIMEOUT(bar->isVisible(), kTimeoutMs);
        QVERIFY2(bar->message().contains(QStringLiteral("A.BDS")) &&
                     bar->message().contains(QStringLiteral("unsaved edits")),
                 qPrintable(bar->message()));
        QCOMPARE(ed->text(), QStringLiteral("B\nJ 1\nJ 2\n"));
        QVERIFY(ed->isModified());
        QTest::mouseClick(bar->keepButton(), Qt::LeftButton); // Keep My Edits
        QVERIFY(!bar->isVisible());
        QCOMPARE(ed->text(), QStringLiteral("B\nJ 1\nJ 2\n"));
        QVERIFY(ed->isModified());
        QCOMPARE(readAll(path), QByteArray("P \"OTHER\"\n")); // nothing written

        // Changed again: asked again; Reload shows the disk's text.
        QVERIFY(saveAtomically(path, "P \"THIRD\"\n"));
        QTRY_VERIFY_WITH_TIMEOUT(bar->isVisible(), kTimeoutMs);
        QCOMPARE(ed->text(), QStringLiteral("B\nJ 1\nJ 2\n"));
        QTest::mouseClick(bar->reloadButton(), Qt::LeftButton);
        QCOMPARE(ed->text(), QStringLiteral("P \"THIRD\"\n"));
        QVERIFY(!ed->isModified());
        QVERIFY(!bar->isVisible());
        // Reload is one undo step: the edits it replaced come back, and the tab is modified again.
        ed->undo();
        QCOMPARE(ed->text(), QStringLiteral("B\nJ 1\nJ 2\n"));
        QVERIFY(ed->isModified());
        ed->redo();
        QCOMPARE(ed->text(), QStringLiteral("P \"THIRD\"\n"));
        QVERIFY(!ed->isModified());

        // Asked, the user saves instead: the tab's text is on disk and the question goes.
        ed->append(QStringLiteral("J 9\n"));
        QVERIFY(saveAtomically(path, "P \"FOURTH\"\n"));
        QTRY_VERIFY_WITH_TIMEOUT(bar->isVisible(), kTimeoutMs);
        area->documents()->save();
        QVERIFY(!bar->isVisible());
        QCOMPARE(readAll(path), QByteArray("P \"THIRD\"\nJ 9\n"));
    }

    void openingAnOpenFileAgainShowsTheDiskOrAsks() {
        QTemporaryDir dir;
        const QString path = writeFile(dir, QStringLiteral("A.BDS"), "B\n");
        MainWindow window;
        window.show();
        app::EditorArea* area = window.editorArea();
        app::DiskChangeBar* bar = area->diskChangeBar();
        QVERIFY(area->documents()->openFile(path));
        editor::ProgramEditor* ed = window.editor();

        // Unmodified: File > Open shows the disk's text at once, in the same tab.
        writeFile(dir, QStringLiteral("A.BDS"), "J 7\n");
        area->tabs()->setCurrentIndex(0);
        QVERIFY(area->documents()->openFile(path));
        QCOMPARE(window.editor(), ed);
        QCOMPARE(ed->text(), QStringLiteral("J 7\n"));
        QCOMPARE(area->tabs()->count(), 2);

        // With edits: asked, nothing lost until the user chooses.
        ed->append(QStringLiteral("J 8\n"));
        QVERIFY(area->documents()->openFile(path));
        QTRY_VERIFY_WITH_TIMEOUT(bar->isVisible(), kTimeoutMs);
        QVERIFY2(bar->message().contains(QStringLiteral("already open")), qPrintable(bar->message()));
        QCOMPARE(ed->text(), QStringLiteral("J 7\nJ 8\n"));
        QTest::mouseClick(bar->reloadButton(), Qt::LeftButton);
        QCOMPARE(ed->text(), QStringLiteral("J 7\n"));
        QVERIFY(!ed->isModified());
        QVERIFY(!bar->isVisible());
    }

    // A file that changed into one the editor refuses (item 7) is not loaded, in part or whole, on reload.
    void aChangedFileTheEditorCannotShowLeavesTheTabAsItWas() {
        QTemporaryDir dir;
        const QString path = writeFile(dir, QStringLiteral("A.BDS"), "J 1\n");
        MainWindow window;
        window.show();
        app::EditorArea* area = window.editorArea();
        app::DiskChangeBar* bar = area->diskChangeBar();
        QVERIFY(area->documents()->openFile(path));
        editor::ProgramEditor* ed = window.editor();

        writeFile(dir, QStringLiteral("A.BDS"), QByteArray("J 1\n\0\x01\x02", 7)); // binary now
        QTRY_VERIFY_WITH_TIMEOUT(bar->isVisible(), kTimeoutMs);
        QVERIFY2(bar->message().contains(QStringLiteral("not a text file")), qPrintable(bar->message()));
        QCOMPARE(ed->text(), QStringLiteral("J 1\n"));
        QVERIFY(!ed->isModified());
        QCOMPARE(bar->keepButton()->text(), QStringLiteral("&Keep This Text"));
        QTest::mouseClick(bar->keepButton(), Qt::LeftButton);
        QVERIFY(!bar->isVisible());

        writeFile(dir, QStringLiteral("A.BDS"), QByteArray(2 << 20, 'J')); // larger than any drive program
        QTRY_VERIFY_WITH_TIMEOUT(bar->isVisible(), kTimeoutMs);
        QVERIFY2(bar->message().contains(QStringLiteral("more than any drive program")), qPrintable(bar->message()));
        QCOMPARE(ed->text(), QStringLiteral("J 1\n"));

        writeFile(dir, QStringLiteral("A.BDS"), "J 2\n"); // text again: shown, and the question goes
        QTRY_COMPARE_WITH_TIMEOUT(ed->text(), QStringLiteral("J 2\n"), kTimeoutMs);
        QVERIFY(!bar->isVisible());
    }

private:
    QTemporaryDir m_recovery;
};

QTEST_MAIN(EditorTabsTest)
#include "editor_tabs_test.moc"
