// The Outline dock in every drive language: each language's labels and entry points (taken from the
// manuals' own examples), the dock following the language installed in an editor, and the line that says
// why the list is empty.
#include "editor/bds5_language.h"
#include "editor/bds5_outline.h"
#include "editor/mpl_language.h"
#include "editor/mpl_outline.h"
#include "editor/outline_view.h"
#include "editor/program_editor.h"
#include "editor/servobasic_language.h"
#include "editor/servobasic_outline.h"

#include <QLabel>
#include <QLineEdit>
#include <QTest>
#include <QTreeWidget>

using namespace editor;

namespace {

QStringList namesOf(const Outline& outline) {
    QStringList names;
    for (const OutlineEntry& e : outline) names << e.name;
    return names;
}

// PMC-960 manual 7.1 (L1025-1036) and the loop example with routines G and W (L1330-1337).
const QString kMplLabels = QStringLiteral("@.This_is_a_comment_line\n"
                                          " @X_Comment_after_a_program_label_'X'\n"
                                          "@G\n"
                                          "I+,\n"
                                          "BW1\n"
                                          "LG2999\n"
                                          "@W\n"
                                          "I,-\n"
                                          "LW19\n");

// SC750 manual: a label (L1121-1136), the SEEKHOME subroutine with its DONE: label (L3400-3501) and the
// FAULT interrupt routine (L1895-1928), each as the manual writes it.
const QString kServoBasic = QStringLiteral("Loop_Again:\n"
                                           "    PRINT \"All work and no play\"\n"
                                           "GOTO Loop_Again\n"
                                           "END 'Main Program\n"
                                           "'-----Subroutines-----\n"
                                           "SUB SEEKHOME\n"
                                           "HomeSwSearchDir = 1 'CounterClockwise search\n"
                                           "IF HOMED THEN GOTO DONE\n"
                                           "PRINT \"Time: 10:30\"\n"
                                           "DONE:\n"
                                           "END SUB\n"
                                           "INTERRUPT FAULT\n"
                                           "Print \"The controller has faulted\"\n"
                                           "RESTART\n"
                                           "END INTERRUPT\n");

} // namespace

class OutlineTest : public QObject {
    Q_OBJECT
private slots:
    void mplListsRoutinesButNotCommentLines() {
        const Outline outline = mplOutline(kMplLabels);
        QCOMPARE(namesOf(outline), QStringList({"X", "G", "W"}));
        QCOMPARE(outline[0].line, 1);
        QCOMPARE(outline[0].detail, QStringLiteral("Comment after a program label 'X'"));
        QCOMPARE(outline[2].line, 6);
        QCOMPARE(outline[2].kind, OutlineEntry::Kind::Label);
    }

    void mplSaysWhenALabelCanNeverBeReached() {
        const Outline outline = mplOutline(QStringLiteral("@A_first\r\nQ\r\n@A_second\r\n@~\r\n"));
        QCOMPARE(namesOf(outline), QStringList({"A", "A"})); // '~' (7EH) is not a label P can enter
        QCOMPARE(outline[0].detail, QStringLiteral("first"));
        QVERIFY2(outline[1].detail.startsWith(QStringLiteral("never reached")) &&
                     outline[1].detail.contains(QStringLiteral("line 1")) && outline[1].detail.endsWith("second"),
                 qPrintable(outline[1].detail));
    }

    void servoBasicListsLabelsSubsAndInterrupts() {
        const Outline outline = servoBasicOutline(kServoBasic);
        QCOMPARE(namesOf(outline), QStringList({"Loop_Again", "SEEKHOME", "DONE", "FAULT"}));
        QCOMPARE(outline[0].kind, OutlineEntry::Kind::Label);
        QCOMPARE(outline[1].kind, OutlineEntry::Kind::Task);
        QCOMPARE(outline[1].line, 5);
        QCOMPARE(outline[1].detail, QStringLiteral("subroutine: CALL SEEKHOME"));
        QCOMPARE(outline[2].line, 9);
        QCOMPARE(outline[3].kind, OutlineEntry::Kind::Handler);
        // L1856: the FAULT interrupt is for "when a controller fault is detected".
        QVERIFY2(outline[3].detail.contains(QStringLiteral("fault")), qPrintable(outline[3].detail));
    }

    void servoBasicIgnoresStatementsCommentsAndStrings() {
        // A statement separator, a keyword, a predefined variable and a colon in a string are no labels.
        const Outline outline = servoBasicOutline(QStringLiteral("X = 1 : Y = 2\n"
                                                                 "CLS: BEEP\n"
                                                                 "ENABLE: PRINT 1\n"
                                                                 "' Comment_Label:\n"
                                                                 "REM Another:\n"
                                                                 "PRINT \"Start: now\"\n"
                                                                 "Start: ' the main loop\n"));
        QCOMPARE(namesOf(outline), QStringList({"Start"}));
        QCOMPARE(outline[0].detail, QStringLiteral("the main loop"));
    }

    // A program saved on DOS or uploaded from a drive ends its lines in CR LF: a label alone on its line (no
    // comment after it) is still a label, at the line the editor shows. Found in the tour: MOTION.BDS listed
    // 1$ (it has a comment) and not 10$.
    void crLfLineEndsKeepEveryLabel_data() {
        QTest::addColumn<int>("language"); // 0 BDS5, 1 MPL, 2 ServoBASIC
        QTest::addColumn<QString>("text");
        QTest::addColumn<QStringList>("names");
        QTest::addColumn<int>("lastLine");
        QTest::newRow("bds5") << 0 << QStringLiteral("1$ ;START\r\nX1=1\r\n10$\r\nGOTO 10\r\n") << QStringList{"1$", "10$"} << 2;
        QTest::newRow("mpl") << 1 << QStringLiteral("@G\r\nI+,\r\n@W\r\nLW19\r\n") << QStringList{"G", "W"} << 2;
        QTest::newRow("servobasic") << 2 << QStringLiteral("Start:\r\nGOTO Start\r\nDONE:\r\nEND\r\n")
                                    << QStringList{"Start", "DONE"} << 2;
        QTest::newRow("cr only") << 0 << QStringLiteral("1$\rX1=1\r10$\r") << QStringList{"1$", "10$"} << 2;
    }
    void crLfLineEndsKeepEveryLabel() {
        QFETCH(int, language);
        QFETCH(QString, text);
        QFETCH(QStringList, names);
        QFETCH(int, lastLine);
        const OutlineOf of[] = {bds5Outline, mplOutline, servoBasicOutline};
        const Outline outline = of[language](text);
        QCOMPARE(namesOf(outline), names);
        QCOMPARE(outline.back().line, lastLine);
    }

    void theDockListsWhateverLanguageTheEditorHas_data() {
        QTest::addColumn<QString>("language");
        QTest::addColumn<QString>("text");
        QTest::addColumn<QString>("label");
        QTest::addColumn<int>("line");
        QTest::newRow("BDS5") << "bds5" << QStringLiteral("; PROGRAM\n10$ ; START\nMI 100\n20$\nB 10$\n") << "20$" << 3;
        QTest::newRow("MPL") << "mpl" << kMplLabels << "W" << 6;
        QTest::newRow("ServoBASIC") << "servobasic" << kServoBasic << "done" << 9;
    }

    // The dock follows the language installed after it was given the editor, lists its entries, and Go to
    // label (type part of a name, Enter) jumps in each.
    void theDockListsWhateverLanguageTheEditorHas() {
        QFETCH(QString, language);
        QFETCH(QString, text);
        QFETCH(QString, label);
        QFETCH(int, line);
        ProgramEditor ed;
        ed.setText(text);
        OutlineView outline;
        outline.setEditor(&ed);
        outline.show();
        QCOMPARE(outline.tree()->topLevelItemCount(), 0); // plain text until a language is installed
        QVERIFY(outline.emptyNote()->isVisible());
        QVERIFY2(outline.emptyNote()->text().contains(QStringLiteral("Plain text")),
                 qPrintable(outline.emptyNote()->text()));

        if (language == QLatin1String("bds5")) Bds5Language::install(ed);
        else if (language == QLatin1String("mpl")) MplLanguage::install(ed);
        else ServoBasicLanguage::install(ed);
        QTRY_VERIFY(outline.tree()->topLevelItemCount() > 0);
        QVERIFY(!outline.emptyNote()->isVisible());

        outline.focusFilter();
        QTest::keyClicks(outline.filterField(), label);
        QTest::keyClick(outline.filterField(), Qt::Key_Return);
        int at = -1, index = -1;
        ed.getCursorPosition(&at, &index);
        QCOMPARE(at, line);

        // A program with nothing to list says what would be listed.
        ed.setText(QStringLiteral("\n"));
        QTRY_COMPARE(outline.tree()->topLevelItemCount(), 0);
        QVERIFY(outline.emptyNote()->isVisible());
        QVERIFY2(outline.emptyNote()->text().contains(QStringLiteral("in this program yet")),
                 qPrintable(outline.emptyNote()->text()));
    }
};

QTEST_MAIN(OutlineTest)
#include "outline_test.moc"
