// Every family's editor colours a manual line's tokens as the manual names them: one test body, the three
// languages as data. The lines are the manuals' own (line numbers beside each); the expected class of each
// token is what the manual calls it (a BDS5 "condition", a ServoBASIC "predefined variable", an MPL label),
// read in the editor as the user sees it, so the shared line-styling lexer is tested for all three.
#include "editor/bds5_language.h"
#include "editor/mpl_language.h"
#include "editor/mpl_lexer.h"
#include "editor/program_editor.h"
#include "editor/servobasic_language.h"
#include "editor/servobasic_lexer.h"

#include <QTest>

using namespace editor;

namespace {

enum class Family { Bds5, Sc750, Pmc960 };

struct Token {
    QByteArray text; // found in the line after the previous token
    int style;
};
using Tokens = QList<Token>;

void install(Family family, ProgramEditor& editor) {
    switch (family) {
    case Family::Bds5: Bds5Language::install(editor); break;
    case Family::Sc750: ServoBasicLanguage::install(editor); break;
    case Family::Pmc960: MplLanguage::install(editor); break;
    }
}

} // namespace

Q_DECLARE_METATYPE(Family)
Q_DECLARE_METATYPE(Tokens)

class LanguageStylesTest : public QObject {
    Q_OBJECT

private slots:
    void manualLinesAreColouredByTokenClass_data() {
        QTest::addColumn<Family>("family");
        QTest::addColumn<QByteArray>("line");
        QTest::addColumn<Tokens>("tokens");

        // BDS5 (seed-bds5 §4.1-4.5): IF is a command (App. C), PFB a variable, GT a condition (§4.4), 50 a
        // decimal constant (§4.2), `;` to the end of the line a comment (§4.1).
        QTest::newRow("bds5 block IF, L4017") << Family::Bds5 << QByteArray("IF PFB GT 50      ;BEGIN BLOCK-IF")
                                              << Tokens{{"IF", Bds5Command},
                                                        {"PFB", Bds5Variable},
                                                        {"GT", Bds5Condition},
                                                        {"50", Bds5Number},
                                                        {";BEGIN BLOCK-IF", Bds5Comment}};
        // O3 is an output switch, ON a special constant (§4.2).
        QTest::newRow("bds5 switch, L1806") << Family::Bds5 << QByteArray("O3 ON      ;TURN ON THE THIRD")
                                            << Tokens{{"O3", Bds5Switch}, {"ON", Bds5Constant}, {";TURN", Bds5Comment}};
        // P prints quoted text (§4.1, §4.9); a dedicated label ends in $ (§4.5).
        QTest::newRow("bds5 print, L3394") << Family::Bds5 << QByteArray("P \"STOP HAS BEEN ISSUED\"")
                                           << Tokens{{"P", Bds5Command}, {"\"STOP HAS BEEN ISSUED\"", Bds5String}};
        QTest::newRow("bds5 label, L5541") << Family::Bds5 << QByteArray("POWER-UP$                ;POWER-UP LABEL")
                                           << Tokens{{"POWER-UP$", Bds5Label}, {";POWER-UP LABEL", Bds5Comment}};

        // ServoBASIC Plus (seed-sc750 §4.1, §4.3): a label is terminated by a colon (L1121-L1136), PRINT a
        // statement, "..." a string literal, ' and REM comments (L1222), RUN.SPEED a predefined variable
        // (L1151-L1188), LEN a function, a user's variable plain.
        QTest::newRow("sc750 label, L1134")
            << Family::Sc750 << QByteArray("Loop_Again:") << Tokens{{"Loop_Again:", BasicLabel}};
        QTest::newRow("sc750 print, L1135")
            << Family::Sc750 << QByteArray("    PRINT \"All work and no play\"")
            << Tokens{{"PRINT", BasicKeyword}, {"\"All work and no play\"", BasicString}};
        QTest::newRow("sc750 trailing comment, L2961")
            << Family::Sc750 << QByteArray("Pitch = 0.5 'lead screw pitch (inches per rev)")
            << Tokens{
                   {"Pitch", BasicDefault}, {"0.5", BasicNumber}, {"'lead screw pitch (inches per rev)", BasicComment}};
        QTest::newRow("sc750 predefined variable, L2026")
            << Family::Sc750 << QByteArray("RUN.SPEED = 1000")
            << Tokens{{"RUN.SPEED", BasicVariable}, {"1000", BasicNumber}};
        QTest::newRow("sc750 function, L3048") << Family::Sc750 << QByteArray("IF LEN(STR1$) <> 10 THEN")
                                               << Tokens{{"IF", BasicKeyword},
                                                         {"LEN", BasicFunction},
                                                         {"STR1$", BasicDefault},
                                                         {"10", BasicNumber},
                                                         {"THEN", BasicKeyword}};
        QTest::newRow("sc750 REM, L3547")
            << Family::Sc750 << QByteArray("REM The Home switch (INP1) is active on falling edge")
            << Tokens{{"REM The Home switch (INP1) is active on falling edge", BasicComment}};

        // MPL (seed-pmc960 §5.9, §7): @ and one character mark a routine's label, the text after it to CR is a
        // comment (L571-L572); I is the index command, + its direction sign, `,` a synchronisation character;
        // L loops to a label a count of times (L1310-L1345).
        QTest::newRow("pmc960 routine label and its comment, L1328, L572")
            << Family::Pmc960 << QByteArray("@G_INDEX_LOOP") << Tokens{{"@G", MplLabel}, {"_INDEX_LOOP", MplComment}};
        QTest::newRow("pmc960 index, L1329")
            << Family::Pmc960 << QByteArray("I+,") << Tokens{{"I", MplCommand}, {"+", MplSign}, {",", MplSync}};
        QTest::newRow("pmc960 loop, L1331") << Family::Pmc960 << QByteArray("LG2999")
                                            << Tokens{{"L", MplCommand}, {"G", MplLabel}, {"2999", MplNumber}};
    }

    void manualLinesAreColouredByTokenClass() {
        QFETCH(Family, family);
        QFETCH(QByteArray, line);
        QFETCH(Tokens, tokens);
        ProgramEditor ed;
        install(family, ed);
        ed.setText(QString::fromLatin1(line + "\n"));
        ed.SendScintilla(QsciScintilla::SCI_COLOURISE, 0, -1);
        qsizetype from = 0;
        for (const Token& token : tokens) {
            const qsizetype at = line.indexOf(token.text, from);
            QVERIFY2(at >= 0, token.text.constData());
            for (qsizetype k = at; k < at + token.text.size(); ++k) {
                const int style = int(ed.SendScintilla(QsciScintilla::SCI_GETSTYLEAT, static_cast<unsigned long>(k)));
                QVERIFY2(style == token.style, qPrintable(QStringLiteral("'%1' byte %2: style %3, expected %4 (%5)")
                                                              .arg(QString::fromLatin1(token.text))
                                                              .arg(k - at)
                                                              .arg(style)
                                                              .arg(token.style)
                                                              .arg(ed.lexer()->description(token.style))));
            }
            from = at + token.text.size();
        }
    }
};

QTEST_MAIN(LanguageStylesTest)
#include "language_styles_test.moc"
