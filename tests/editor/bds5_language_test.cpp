// The BDS5 editor as a user meets it: the colour of every token class, IF blocks that fold, the drive's
// error text under the line as you type (and gone once fixed), the outline of the manual's pretzel
// template, F1 help for VMAX / MA / ERR 25, and completion for "VM".
#include "editor/bds5_completion.h"
#include "editor/bds5_diagnostics.h"
#include "editor/bds5_help.h"
#include "editor/bds5_language.h"
#include "editor/bds5_lexer.h"
#include "editor/bds5_outline.h"
#include "editor/help_popup.h"
#include "editor/outline_view.h"
#include "editor/program_editor.h"

#include <QLineEdit>
#include <QSignalSpy>
#include <QTest>
#include <QTreeWidget>

using namespace editor;

namespace {

// One letter per byte: d default, c comment, s string, l label, n number, C command, k keyword, v variable,
// w switch, K constant, g condition, o operator, E unknown.
QByteArray styleCodes(const QByteArray& line) {
    QByteArray codes;
    for (const char style : Bds5Lexer::styleLine(line)) codes += "dcslnCkvwKgoE"[int(style)];
    return codes;
}

// The manual's pretzel machine template (L5477-5580) with the OCR damage INDEX.md names repaired:
// AS 17 OFF -> A$ I7 OFF, AUTOS/MANUALS/BACKGROUNDS -> AUTO$/MANUAL$/BACKGROUND$, "..." -> a 10$ routine.
const QString kPretzel = QStringLiteral(";NAME OF APPLICATION: PRETZEL MACHINE\n"
                                        "; APPLICATION PROGRAM\n"
                                        ";\n"
                                        "POWER-UP$                ;POWER-UP LABEL\n"
                                        "PLIM OFF                 ;SOFTWARE LIMITS NOT USED HERE\n"
                                        "END\n"
                                        ";\n"
                                        "A$ I7 OFF\n"
                                        "P \"THERMOSTAT (INPUT 7) OPENED\"\n"
                                        "DIS                      ;DISABLE THE BDS5\n"
                                        "B                        ;BREAK PROGRAM EXECUTION\n"
                                        ";\n"
                                        "VARIABLE$\n"
                                        "INPUT \"ENTER NEW SPEED\" X1\n"
                                        "END\n"
                                        ";\n"
                                        "AUTO$                    ;AUTO LABEL\n"
                                        "END\n"
                                        ";\n"
                                        "MANUAL$                  ;MANUAL LABEL\n"
                                        "END\n"
                                        ";\n"
                                        "10$                      ;MORE PROGRAMS\n"
                                        "END\n"
                                        ";\n"
                                        "BACKGROUND$\n"
                                        "END\n"
                                        ";\n"
                                        "ERROR$                   ;ERROR HANDLER\n"
                                        "B                        ;END OF SAMPLE PROGRAM\n");

// Types text into the editor as key presses (Return for '\n').
void type(ProgramEditor& ed, const QString& text) {
    for (const QChar ch : text) {
        if (ch == QLatin1Char('\n'))
            QTest::keyClick(&ed, Qt::Key_Return);
        else
            QTest::keyClicks(&ed, QString(ch));
    }
}

int styleAt(ProgramEditor& ed, int line, int column) {
    const long pos = ed.SendScintilla(QsciScintilla::SCI_POSITIONFROMLINE, line) + column;
    return int(ed.SendScintilla(QsciScintilla::SCI_GETSTYLEAT, pos));
}

int foldLevel(ProgramEditor& ed, int line) {
    return int(ed.SendScintilla(QsciScintilla::SCI_GETFOLDLEVEL, line));
}

} // namespace

class Bds5LanguageTest : public QObject {
    Q_OBJECT
private slots:
    void lexerStylesEveryTokenClass() {
        QCOMPARE(styleCodes("MA 1000 VMAX"), QByteArray("CCdnnnndvvvv"));
        QCOMPARE(styleCodes("IF X1 GT 0FFH ;HEX"), QByteArray("CCdvvdggdnnnndcccc"));
        QCOMPARE(styleCodes("X1=X2+5"), QByteArray("vvovvon"));
        QCOMPARE(styleCodes("PROP ON"), QByteArray("wwwwdKK"));
        QCOMPARE(styleCodes("O1 N"), QByteArray("wwdK"));
        QCOMPARE(styleCodes("TMR1 1000"), QByteArray("vvvvdnnnn"));
        QCOMPARE(styleCodes("A$ I1 ON"), QByteArray("lldwwdKK"));
        QCOMPARE(styleCodes("POWER-UP$ ;START"), QByteArray("llllllllldcccccc"));
        QCOMPARE(styleCodes("10$"), QByteArray("lll"));
        QCOMPARE(styleCodes("P \"HI\" X1[8.2]"), QByteArray("Cdssssdvvonnno"));
        QCOMPARE(styleCodes("DUMP VERSION"), QByteArray("CCCCdkkkkkkk"));
        QCOMPARE(styleCodes("? I1 EQ ON GOTO 10 : B"), QByteArray("CdwwdggdKKdCCCCdnndCdC"));
        QCOMPARE(styleCodes("X(X5)=1"), QByteArray("vovvoon"));
        QCOMPARE(styleCodes("  ;INDENTED"), QByteArray("ddccccccccc"));
    }
    void lexerMarksWhatTheDriveWouldRefuseInRed() {
        QCOMPARE(styleCodes("FOO 10"), QByteArray("EEEdnn"));     // unknown word
        QCOMPARE(styleCodes("X1 = FFH"), QByteArray("vvdodEEE")); // hex must start with a digit
        QCOMPARE(styleCodes("LOOP$"), QByteArray("EEEEE"));       // no such label
        QCOMPARE(styleCodes("J 10;X"), QByteArray("CdnnEE"));     // `;` needs a blank before it
    }
    void lexerLeavesAnUnclosedStringAtTheLineEnd() { QCOMPARE(styleCodes("P \"AB"), QByteArray("Cdsss")); }

    void editorShowsTheStylesInTheDocument() {
        ProgramEditor ed;
        Bds5Language::install(ed);
        ed.setText(QStringLiteral("10$\nMA 1000 ;GO\nPROP ON\n"));
        ed.SendScintilla(QsciScintilla::SCI_COLOURISE, 0, -1);
        QCOMPARE(styleAt(ed, 0, 0), int(Bds5Lexer::Label));
        QCOMPARE(styleAt(ed, 1, 0), int(Bds5Lexer::Command));
        QCOMPARE(styleAt(ed, 1, 3), int(Bds5Lexer::Number));
        QCOMPARE(styleAt(ed, 1, 9), int(Bds5Lexer::Comment));
        QCOMPARE(styleAt(ed, 2, 0), int(Bds5Lexer::Switch));
        QCOMPARE(styleAt(ed, 2, 5), int(Bds5Lexer::Constant));
        QCOMPARE(Bds5Language::install(ed), Bds5Language::of(&ed)); // once per editor
    }

    void nestedIfBlocksFold() {
        ProgramEditor ed;
        Bds5Language::install(ed);
        ed.setText(QStringLiteral("55$\n"          // 0 label section header
                                  "IF X1 GT 0\n"   // 1 header, level 1
                                  "  IF X2 GT 0\n" // 2 header, level 2
                                  "    P 1\n"      // 3 level 3
                                  "  ELSE\n"       // 4 header, level 2
                                  "    P 2\n"      // 5 level 3
                                  "  ENDIF\n"      // 6 level 3 (last line of the ELSE part)
                                  "ELIF X1 LT 0\n" // 7 header, level 1
                                  "  P 3\n"        // 8 level 2
                                  "ENDIF\n"        // 9 level 2
                                  "END\n"          // 10 level 1
                                  "60$\n"));       // 11 header, level 0
        ed.SendScintilla(QsciScintilla::SCI_COLOURISE, 0, -1);
        const int base = QsciScintilla::SC_FOLDLEVELBASE;
        const int header = QsciScintilla::SC_FOLDLEVELHEADERFLAG;
        const int expected[] = {base | header,
                                (base + 1) | header,
                                (base + 2) | header,
                                base + 3,
                                (base + 2) | header,
                                base + 3,
                                base + 3,
                                (base + 1) | header,
                                base + 2,
                                base + 2,
                                base + 1,
                                base | header};
        for (int line = 0; line < 12; ++line)
            QCOMPARE(foldLevel(ed, line) & (QsciScintilla::SC_FOLDLEVELNUMBERMASK | header), expected[line]);
        // Folding the outer IF hides its first part only (up to ELIF).
        ed.SendScintilla(QsciScintilla::SCI_FOLDLINE, 1, QsciScintilla::SC_FOLDACTION_CONTRACT);
        QVERIFY(!ed.SendScintilla(QsciScintilla::SCI_GETLINEVISIBLE, 3));
        QVERIFY(!ed.SendScintilla(QsciScintilla::SCI_GETLINEVISIBLE, 6));
        QVERIFY(ed.SendScintilla(QsciScintilla::SCI_GETLINEVISIBLE, 7));
    }

    void typedErrorShowsTheDrivesTextAtItsLineAndFixingClearsIt() {
        ProgramEditor ed;
        Bds5Language* bds5 = Bds5Language::install(ed);
        Bds5Diagnostics* diagnostics = bds5->diagnostics();
        QSignalSpy changed(diagnostics, &Bds5Diagnostics::changed);
        ed.show();
        ed.setFocus();
        type(ed, QStringLiteral("10$\nKP 1500\nPROP 2\nMA 1000\n"));
        QVERIFY(diagnostics->pending()); // not while typing: after the debounce
        QTRY_COMPARE(diagnostics->errorCount(), 1);
        QCOMPARE(ed.annotation(2), QStringLiteral("ERR 83 '2'  BAD OR OUT OF RANGE"));
        QCOMPARE(ed.annotation(1), QString());
        QCOMPARE(ed.markersAtLine(2) & (1 << Bds5Diagnostics::kErrorMarker), 1 << Bds5Diagnostics::kErrorMarker);
        QCOMPARE(ed.markersAtLine(1), 0u);
        const long two = ed.SendScintilla(QsciScintilla::SCI_POSITIONFROMLINE, 2) + 5; // the '2'
        QVERIFY(ed.SendScintilla(QsciScintilla::SCI_INDICATORVALUEAT, Bds5Diagnostics::kErrorIndicator, two));
        QVERIFY(!ed.SendScintilla(QsciScintilla::SCI_INDICATORVALUEAT, Bds5Diagnostics::kErrorIndicator, two - 2));
        QCOMPARE(changed.last().at(0).toInt(), 1);

        // Fix it the way a user would: to the end of line 3, erase the 2, type 1.
        ed.setCursorPosition(2, 6);
        QTest::keyClick(&ed, Qt::Key_Backspace);
        type(ed, QStringLiteral("1"));
        QTRY_COMPARE(diagnostics->errorCount(), 0);
        QCOMPARE(ed.annotation(2), QString());
        QCOMPARE(ed.markersAtLine(2), 0u);
        QCOMPARE(changed.last().at(0).toInt(), 0);
    }

    void programWideErrorsLandOnTheirLines() {
        ProgramEditor ed;
        Bds5Diagnostics* diagnostics = Bds5Language::install(ed)->diagnostics();
        ed.setText(QStringLiteral("10$\nGOTO 20\n10$\nERROR$\nB\n30$\nP \"UNCLOSED\n"));
        diagnostics->checkNow();
        QCOMPARE(ed.annotation(1), QStringLiteral("ERR 70 '20'  LABEL NOT FOUND"));
        QVERIFY2(ed.annotation(2).startsWith(QStringLiteral("ERR 71 '10$'")), qPrintable(ed.annotation(2)));
        QVERIFY2(ed.annotation(6).startsWith(QStringLiteral("ERR 88")), qPrintable(ed.annotation(6)));
        QCOMPARE(diagnostics->nextLine(2), 6);
    }

    void othersAnnotationsSurviveARecheck() { // a drive error marked after a download stays put
        ProgramEditor ed;
        Bds5Diagnostics* diagnostics = Bds5Language::install(ed)->diagnostics();
        ed.setText(QStringLiteral("10$\nPROP 2\nB\n"));
        ed.annotate(1, QStringLiteral("ERR 25 LINE 2  PE OVERFLOW"), 0);
        diagnostics->checkNow();
        QCOMPARE(ed.annotation(1), QStringLiteral("ERR 83 '2'  BAD OR OUT OF RANGE\nERR 25 LINE 2  PE OVERFLOW"));
        ed.insertAt(QStringLiteral("; A COMMENT LINE\n"), 0, 0); // lines move, annotations with them
        ed.setSelection(2, 5, 2, 6);
        ed.replaceSelectedText(QStringLiteral("1"));
        diagnostics->checkNow();
        QCOMPARE(ed.annotation(2), QStringLiteral("ERR 25 LINE 2  PE OVERFLOW"));
        QCOMPARE(diagnostics->errorCount(), 0);
    }

    void outlineListsThePretzelTemplatesLabelsAndTasks() {
        const auto entries = bds5Outline(kPretzel);
        QStringList names;
        for (const auto& e : entries) names << e.name;
        QCOMPARE(names,
                 QStringList({"POWER-UP$", "A$", "VARIABLE$", "AUTO$", "MANUAL$", "10$", "BACKGROUND$", "ERROR$"}));
        QCOMPARE(entries[1].detail, QStringLiteral("I7 OFF"));
        QCOMPARE(entries[1].kind, OutlineEntry::Kind::Handler);
        QCOMPARE(entries[0].detail, QStringLiteral("POWER-UP LABEL"));
        QCOMPARE(entries[5].line, 22);

        ProgramEditor ed;
        Bds5Language::install(ed);
        ed.setText(kPretzel);
        OutlineView outline;
        outline.setEditor(&ed);
        QCOMPARE(outline.tree()->topLevelItemCount(), 8);
        QCOMPARE(outline.tree()->topLevelItem(3)->text(0), QStringLiteral("AUTO$"));
        // Go to label: type in the filter, Enter jumps.
        outline.show();
        outline.focusFilter();
        QTest::keyClicks(outline.filterField(), QStringLiteral("back"));
        QTest::keyClick(outline.filterField(), Qt::Key_Return);
        int line = -1, index = -1;
        ed.getCursorPosition(&line, &index);
        QCOMPARE(line, 25);
        // Lines added or removed: the outline is rebuilt at once, so no entry shows a stale line number.
        ed.setText(QStringLiteral("1$\n2$\n"));
        QCOMPARE(outline.tree()->topLevelItemCount(), 2);
        QCOMPARE(outline.tree()->topLevelItem(1)->text(1), QStringLiteral("2"));
        // An edit within a line: after the pause in typing.
        ed.setSelection(1, 0, 1, 1);
        ed.replaceSelectedText(QStringLiteral("3"));
        QCOMPARE(outline.tree()->topLevelItem(1)->text(0), QStringLiteral("2$"));
        QTRY_COMPARE(outline.tree()->topLevelItem(1)->text(0), QStringLiteral("3$"));
    }

    void helpExplainsVariablesCommandsAndErrors() {
        const QString vmax = bds5HelpHtml(QStringLiteral("VMAX"));
        QVERIFY2(vmax.contains(QStringLiteral("Units: VEL")) && vmax.contains(QStringLiteral("factory")),
                 qPrintable(vmax));
        QVERIFY(vmax.contains(QStringLiteral("Maximum speed")));
        const QString ma = bds5HelpHtml(QStringLiteral("MA"));
        QVERIFY2(ma.contains(QStringLiteral("MOVE ABSOLUTE")) && ma.contains(QStringLiteral("MA &lt;")),
                 qPrintable(ma));
        const QString err = bds5HelpHtml(QStringLiteral("25"));
        QVERIFY2(err.contains(QStringLiteral("ERR 25")) && err.contains(QStringLiteral("PE OVERFLOW")),
                 qPrintable(err));
        QVERIFY(err.contains(QStringLiteral("PEMAX")));
        QCOMPARE(bds5HelpHtml(QStringLiteral("ERR 25")), err);
        QVERIFY(bds5HelpHtml(QStringLiteral("X12")).contains(QStringLiteral("X1..X250")));
        QVERIFY(bds5HelpHtml(QStringLiteral("NOSUCH")).isEmpty());

        QCOMPARE(bds5TopicAt(QStringLiteral("ERR 25"), 5), QStringLiteral("ERR 25"));
        QCOMPARE(bds5TopicAt(QStringLiteral("ERR 25"), 1), QStringLiteral("ERR 25"));
        QCOMPARE(bds5TopicAt(QStringLiteral("MA 25"), 4), QString()); // a number that is no error code
        QCOMPARE(bds5TopicAt(QStringLiteral("X1=VMAX/2"), 5), QStringLiteral("VMAX"));
        QCOMPARE(bds5TopicAt(QStringLiteral("X1=VMAX/2"), 7), QStringLiteral("VMAX")); // just after the word
        QCOMPARE(bds5TopicAt(QStringLiteral("P \"VMAX\""), 4), QString());             // in a string
        QCOMPARE(bds5TopicAt(QStringLiteral("10$ ;VMAX"), 1), QStringLiteral("$"));
    }

    void darkThemeReachesTextAnnotationsAndPopup() {
        ProgramEditor ed;
        Bds5Language* bds5 = Bds5Language::install(ed);
        bds5->setTheme(Bds5Lexer::Theme::Dark);
        QCOMPARE(bds5->lexer()->paper(), QColor(0x1e, 0x1e, 0x1e));
        QCOMPARE(bds5->lexer()->color(Bds5Lexer::Command), QColor(0x56, 0x9c, 0xd6));
        ed.setText(QStringLiteral("VMAX\n"));
        ed.show();
        ed.setCursorPosition(0, 1);
        bds5->showHelpAtCursor();
        const QImage popup = bds5->helpPopup()->grab().toImage();
        QVERIFY2(QColor(popup.pixel(popup.width() / 2, popup.height() - 3)).lightness() < 80,
                 qPrintable(QColor(popup.pixel(popup.width() / 2, popup.height() - 3)).name()));
    }

    void f1ShowsThePopupAndAsksForHelp() {
        ProgramEditor ed;
        Bds5Language* bds5 = Bds5Language::install(ed);
        QSignalSpy help(&ed, &ProgramEditor::helpRequested);
        ed.setText(QStringLiteral("ERR 25\nMA 1000 VMAX\n"));
        ed.show();
        ed.setFocus();
        ed.setCursorPosition(0, 5);
        QTest::keyClick(&ed, Qt::Key_F1);
        QVERIFY(bds5->helpPopup()->isVisible());
        QVERIFY(bds5->helpPopup()->html().contains(QStringLiteral("PE OVERFLOW")));
        QCOMPARE(help.count(), 1);
        QCOMPARE(help.last().at(0).toString(), QStringLiteral("ERR 25"));
        QTest::keyClick(&ed, Qt::Key_Escape); // Esc closes it
        QVERIFY(!bds5->helpPopup()->isVisible());
        ed.setCursorPosition(1, 1);
        QTest::keyClick(&ed, Qt::Key_F1);
        QVERIFY(bds5->helpPopup()->html().contains(QStringLiteral("MOVE ABSOLUTE")));
        QCOMPARE(help.last().at(0).toString(), QStringLiteral("MA"));
        QTest::keyClick(&ed, Qt::Key_Right); // any key closes it
        QVERIFY(!bds5->helpPopup()->isVisible());
    }

    void completionOffersVariablesWithUnitsAndRanges() {
        QStringList vm;
        for (const auto& c : bds5Completions(QStringLiteral("vm"))) vm << c.display;
        QCOMPARE(vm, QStringList({QStringLiteral("VMAX \u2014 VEL, factory")}));
        QStringList x;
        for (const auto& c : bds5Completions(QStringLiteral("X"))) x << c.display;
        QVERIFY2(x.contains(QStringLiteral("X1..X250 \u2014 User variables X1-X250")), qPrintable(x.join('|')));
        QStringList ma;
        for (const auto& c : bds5Completions(QStringLiteral("MA"))) ma << c.display;
        QVERIFY2(ma.contains(QStringLiteral("MA \u2014 MOVE ABSOLUTE <position> [velocity]")),
                 qPrintable(ma.join('|')));
        QVERIFY2(ma.contains(QStringLiteral("MANUAL \u2014 switch, read-only")), qPrintable(ma.join('|')));
        QStringList kp;
        for (const auto& c : bds5Completions(QStringLiteral("KP"))) kp << c.display;
        QVERIFY2(kp.contains(QStringLiteral("KP \u2014 0..32767")), qPrintable(kp.join('|')));
    }

    void typingTwoLettersOpensTheListAndEnterPicks() {
        ProgramEditor ed;
        Bds5Language::install(ed);
        ed.show();
        ed.setFocus();
        type(ed, QStringLiteral("X1=vm"));
        QVERIFY(ed.isListActive());
        QTest::keyClick(&ed, Qt::Key_Return);
        QVERIFY(!ed.isListActive());
        QCOMPARE(ed.text(), QStringLiteral("X1=VMAX"));
        // A finished name and Enter: a new line, not a pick.
        type(ed, QStringLiteral("\nEN"));
        QVERIFY(ed.isListActive());
        QTest::keyClick(&ed, Qt::Key_Return);
        QCOMPARE(ed.text(), QStringLiteral("X1=VMAX\nEN\n"));
        // Ctrl+Space lists everything that starts with what is there, even one letter.
        type(ed, QStringLiteral("K"));
        QVERIFY(!ed.isListActive());
        QTest::keyClick(&ed, Qt::Key_Space, Qt::ControlModifier);
        QVERIFY(ed.isListActive());
        QTest::keyClick(&ed, Qt::Key_Escape);
        // Not in a comment.
        type(ed, QStringLiteral(" ;MAKE"));
        QVERIFY(!ed.isListActive());
    }
};

QTEST_MAIN(Bds5LanguageTest)
#include "bds5_language_test.moc"
