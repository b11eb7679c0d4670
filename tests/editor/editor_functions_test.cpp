// Motion Link's editor functions on a ProgramEditor: go to line counting (or not) comment lines, size
// figures against 2,000 lines / 24,000 bytes, delete/undelete line, words, blocks, merge, find/replace,
// the two keymaps' keys, and printing to PDF — each checked by what the editor then shows.
#include "editor/block_marker.h"
#include "editor/editor_size.h"
#include "editor/find_bar.h"
#include "editor/go_to_line_dialog.h"
#include "editor/key_chord_filter.h"
#include "editor/line_commands.h"
#include "editor/line_numbering.h"
#include "editor/program_editor.h"
#include "editor/program_printer.h"

#include <QFile>
#include <QLabel>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

using namespace editor;

namespace {
// Line 1-3 comments/blank, then code; drive line 1 (without comments) is editor line 4.
const QString kProgram = QStringLiteral("; HEADER\n"
                                        "\n"
                                        "   ; INDENTED COMMENT\n"
                                        "10$ ;START\n"
                                        "J 100\n"
                                        "; MIDDLE\n"
                                        "W 2\n"
                                        "B\n");

int cursorLine(const QsciScintilla& editor) {
    int line = 0;
    int index = 0;
    editor.getCursorPosition(&line, &index);
    return line;
}

QByteArray readAll(const QString& path) {
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

void typeKey(QWidget* editor, int key, Qt::KeyboardModifiers modifiers) {
    // As the window system delivers it: ShortcutOverride first, then the key press if nobody took it as
    // a shortcut.
    QKeyEvent override(QEvent::ShortcutOverride, key, modifiers);
    QCoreApplication::sendEvent(editor, &override);
    QKeyEvent press(QEvent::KeyPress, key, modifiers);
    QCoreApplication::sendEvent(editor, &press);
}
} // namespace

class EditorFunctionsTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        qRegisterMetaType<QsciScintilla*>();
    }

    void driveLinesSkipCommentAndBlankLinesOnlyWhenAsked() {
        const QStringList lines = splitLines(kProgram);
        QCOMPARE(lines.size(), 8);
        QCOMPARE(editorLineForDriveLine(lines, 4, LineCounting::AllLines), 3);
        QCOMPARE(editorLineForDriveLine(lines, 1, LineCounting::WithoutComments), 3); // "10$ ;START"
        QCOMPARE(editorLineForDriveLine(lines, 3, LineCounting::WithoutComments), 6); // "W 2" after "; MIDDLE"
        QCOMPARE(editorLineForDriveLine(lines, 5, LineCounting::WithoutComments), -1);
        QCOMPARE(driveLineForEditorLine(lines, 6, LineCounting::WithoutComments), 3);
        QCOMPARE(driveLineForEditorLine(lines, 5, LineCounting::WithoutComments), 3); // a comment: next code
        QCOMPARE(driveLineCount(lines, LineCounting::WithoutComments), 4);
        QVERIFY(isCommentLine(u"  ;X"));
        QVERIFY(!isCommentLine(u"J 10 ;X"));
    }

    void goToLineDialogLandsOnTheDrivesLine() {
        ProgramEditor ed;
        ed.setText(kProgram);
        GoToLineDialog dialog(ed);
        dialog.setLineNumber(3);
        dialog.setCounting(LineCounting::AllLines);
        QCOMPARE(dialog.targetEditorLine(), 2);
        dialog.setCounting(LineCounting::WithoutComments);
        QCOMPARE(dialog.targetEditorLine(), 6);
        auto* preview = dialog.findChild<QLabel*>(QStringLiteral("goToLinePreview"));
        QVERIFY(preview);
        QCOMPARE(preview->text(), QStringLiteral("Editor line 7:  W 2"));
        dialog.accept();
        QCOMPARE(cursorLine(ed), 6);
    }

    void sizeCountsLinesAndBytesAsSaved() {
        const EditorSize lf = measureText(QStringLiteral("AB\nC\n"), false);
        QCOMPARE(lf.lines, 2);
        QCOMPARE(lf.bytes, 5);
        const EditorSize crlf = measureText(QStringLiteral("AB\r\nC"), true);
        QCOMPARE(crlf.lines, 2);
        QCOMPARE(crlf.bytes, 5);
        QCOMPARE(measureText(QStringLiteral("\u00b5"), false).bytes, 2);       // UTF-8
        QCOMPARE(measureText(QStringLiteral("\u00b5"), false, true).bytes, 1); // Latin-1 file
        QString big;
        for (int i = 0; i < 2001; ++i) big += QStringLiteral("J 1\n");
        const EditorSize over = measureText(big, false);
        QCOMPARE(over.lines, 2001);
        QCOMPARE(over.linesLeft(), -1);
        QVERIFY(!over.fits());
        QCOMPARE(over.summary(), QStringLiteral("2,001 lines, 8,004 bytes"));
    }

    void deleteLineThenUndeleteBringsItBack() {
        ProgramEditor ed;
        ed.setText(QStringLiteral("A\nJ 100\nB\n"));
        ed.setCursorPosition(1, 2);
        QCOMPARE(deleteLine(ed), QStringLiteral("J 100"));
        QCOMPARE(ed.text(), QStringLiteral("A\nB\n"));
        QCOMPARE(cursorLine(ed), 1);
        ed.setCursorPosition(0, 0);
        undeleteLine(ed, QStringLiteral("J 100"));
        QCOMPARE(ed.text(), QStringLiteral("J 100\nA\nB\n"));
        ed.undo(); // one step each
        QCOMPARE(ed.text(), QStringLiteral("A\nB\n"));
    }

    void deleteWordToEndOfLineInsertLineAndClear() {
        ProgramEditor ed;
        ed.setText(QStringLiteral("MI X1 X2 ;STEP\nB"));
        ed.setCursorPosition(0, 3);
        deleteWord(ed);
        QCOMPARE(ed.text(), QStringLiteral("MI X2 ;STEP\nB"));
        deleteToEndOfLine(ed);
        QCOMPARE(ed.text(), QStringLiteral("MI \nB"));
        ed.setCursorPosition(1, 0);
        insertNewLine(ed);
        QCOMPARE(ed.text(), QStringLiteral("MI \n\nB"));
        QCOMPARE(cursorLine(ed), 1);
        deleteEntireEditor(ed);
        QCOMPARE(ed.text(), QString());
        ed.undo();
        QCOMPARE(ed.text(), QStringLiteral("MI \n\nB"));
    }

    void blockMarkedWithStartAndEndFollowsEdits() {
        ProgramEditor ed;
        ed.setText(QStringLiteral("AAA\nBBB\nCCC\n"));
        ed.setCursorPosition(1, 0);
        BlockMarker& marker = BlockMarker::of(ed);
        marker.markStart();
        ed.insertAt(QStringLiteral("ZZ\n"), 0, 0); // a line above: the mark moves with BBB
        ed.setCursorPosition(4, 0);
        QVERIFY(marker.markEnd());
        QCOMPARE(ed.selectedText(), QStringLiteral("BBB\nCCC\n"));
    }

    void saveBlockWritesTheSelectionMergeInsertsAFile() {
        QTemporaryDir dir;
        ProgramEditor ed;
        ed.setEolMode(QsciScintilla::EolWindows);
        ed.setText(QStringLiteral("A\r\nJ 1\r\nW 2\r\nB\r\n"));
        ed.setSelection(1, 0, 3, 0);
        const QString block = dir.filePath(QStringLiteral("BLOCK.BDS"));
        QVERIFY(ed.saveSelectedText(block).ok);
        QCOMPARE(readAll(block), QByteArray("J 1\r\nW 2\r\n"));
        QFile unix(dir.filePath(QStringLiteral("PART.BDS")));
        QVERIFY(unix.open(QIODevice::WriteOnly));
        unix.write("X1 = 5\nX2 = 6\n");
        unix.close();
        ed.setCursorPosition(3, 0);
        QVERIFY(ed.insertFile(unix.fileName()).ok);
        QCOMPARE(ed.text(), QStringLiteral("A\r\nJ 1\r\nW 2\r\nX1 = 5\r\nX2 = 6\r\nB\r\n"));
        QCOMPARE(cursorLine(ed), 5);
        ed.undo();
        QCOMPARE(ed.text(), QStringLiteral("A\r\nJ 1\r\nW 2\r\nB\r\n"));
        QVERIFY(!ed.insertFile(dir.filePath(QStringLiteral("NONE.BDS"))).ok);
    }

    void findWrapsCountsAndReplaces() {
        ProgramEditor ed;
        ed.setText(QStringLiteral("X1 = 1\nX12 = 2\nP X1\n"));
        FindBar bar;
        bar.setEditor(&ed);
        bar.setSearchText(QStringLiteral("X1"));
        bar.setWholeWords(true);
        QVERIFY(bar.findNext());
        QCOMPARE(bar.statusText(), QStringLiteral("Match 1 of 2"));
        QVERIFY(bar.findNext());
        QCOMPARE(cursorLine(ed), 2);
        QVERIFY(bar.findNext()); // repeat last find wraps to the top
        QCOMPARE(bar.statusText(), QStringLiteral("Match 1 of 2 (wrapped)"));
        QVERIFY(bar.findPrevious());
        QCOMPARE(cursorLine(ed), 2);
        bar.setReplaceText(QStringLiteral("X9"));
        QVERIFY(bar.replaceCurrent());
        QCOMPARE(ed.text(), QStringLiteral("X1 = 1\nX12 = 2\nP X9\n"));
        QCOMPARE(bar.replaceAll(), 1);
        QCOMPARE(ed.text(), QStringLiteral("X9 = 1\nX12 = 2\nP X9\n"));
        QCOMPARE(bar.statusText(), QStringLiteral("Replaced 1"));
        bar.setSearchText(QStringLiteral("VMAX"));
        QVERIFY(!bar.findNext());
        QCOMPARE(bar.statusText(), QStringLiteral("Not found"));
    }

    void classicKeysDeleteLinesModernKeysDoNot() {
        ProgramEditor ed;
        KeyChordFilter filter;
        filter.watch(&ed);
        QSignalSpy commands(&filter, &KeyChordFilter::commandTriggered);
        ed.setText(QStringLiteral("A\nB\nC\n"));

        // Modern: ^Y is not the keymap's; it goes on to QScintilla (redo), no command.
        typeKey(&ed, Qt::Key_Y, Qt::ControlModifier);
        QCOMPARE(commands.size(), 1); // Ctrl+Y is Redo in the modern keymap
        QCOMPARE(commands.takeFirst().at(0).value<EditorCommand>(), EditorCommand::Redo);

        filter.setKeymap(Keymap::classic());
        typeKey(&ed, Qt::Key_Y, Qt::ControlModifier);
        QCOMPARE(commands.takeFirst().at(0).value<EditorCommand>(), EditorCommand::DeleteLine);
        // ^K then B, with or without Ctrl on the second key.
        QSignalSpy pending(&filter, &KeyChordFilter::pendingChanged);
        typeKey(&ed, Qt::Key_K, Qt::ControlModifier);
        QCOMPARE(pending.takeFirst().at(0).toString(), QStringLiteral("^K"));
        QVERIFY(commands.isEmpty());
        typeKey(&ed, Qt::Key_B, Qt::NoModifier);
        QCOMPARE(commands.takeFirst().at(0).value<EditorCommand>(), EditorCommand::MarkBlockStart);
        typeKey(&ed, Qt::Key_Q, Qt::ControlModifier);
        typeKey(&ed, Qt::Key_F, Qt::ControlModifier);
        QCOMPARE(commands.takeFirst().at(0).value<EditorCommand>(), EditorCommand::Find);
        // Cursor keys of Table 2.1 move the cursor in the editor itself: ^X down, ^E up.
        ed.setCursorPosition(0, 0);
        typeKey(&ed, Qt::Key_X, Qt::ControlModifier);
        typeKey(&ed, Qt::Key_X, Qt::ControlModifier);
        QCOMPARE(cursorLine(ed), 2);
        typeKey(&ed, Qt::Key_E, Qt::ControlModifier);
        QCOMPARE(cursorLine(ed), 1);
        QVERIFY(commands.isEmpty());
        QCOMPARE(ed.text(), QStringLiteral("A\nB\nC\n")); // no key reached the text
        // A chord that means nothing is swallowed and reported.
        QSignalSpy unknown(&filter, &KeyChordFilter::unknownChord);
        typeKey(&ed, Qt::Key_K, Qt::ControlModifier);
        typeKey(&ed, Qt::Key_Z, Qt::NoModifier);
        QCOMPARE(unknown.takeFirst().at(0).toString(), QStringLiteral("^KZ"));
        QCOMPARE(ed.text(), QStringLiteral("A\nB\nC\n"));
    }

    void keymapNotation() {
        QCOMPARE(Keymap::caretNotation(QKeySequence(Qt::CTRL | Qt::Key_K, Qt::CTRL | Qt::Key_B)),
                 QStringLiteral("^K^B"));
        QCOMPARE(Keymap::classic().keysFor(EditorCommand::FindNext).first(), QKeySequence(Qt::CTRL | Qt::Key_L));
        QCOMPARE(Keymap::modern().keysFor(EditorCommand::GoToLine).first(), QKeySequence(Qt::CTRL | Qt::Key_G));
        QCOMPARE(Keymap::named(QStringLiteral("nonsense")).name(), Keymap::kModern);
    }

    void printsToANonEmptyPdf() {
        QTemporaryDir dir;
        ProgramEditor ed;
        QString text;
        for (int i = 0; i < 150; ++i) text += QStringLiteral("J %1 ;LINE %1\n").arg(i);
        ed.setText(text);
        const QString pdf = dir.filePath(QStringLiteral("program.pdf"));
        QVERIFY(printToPdf(ed, QStringLiteral("MOTION.BDS"), pdf).ok);
        const QByteArray bytes = readAll(pdf);
        QVERIFY(bytes.startsWith("%PDF-"));
        QVERIFY2(bytes.size() > 2000, QByteArray::number(bytes.size()));
        QVERIFY2(bytes.count("/Type /Page\n") + bytes.count("/Type /Page\r") + bytes.count("/Type /Page ") +
                         bytes.count("/Type/Page") >=
                     2,
                 "150 lines take more than one page");
    }
};

QTEST_MAIN(EditorFunctionsTest)
#include "editor_functions_test.moc"
