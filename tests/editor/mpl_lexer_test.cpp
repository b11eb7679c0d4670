// The MPL lexer's character classes and the program check, on the manual's examples (digest §8).
#include "editor/mpl_help.h"
#include "editor/mpl_lexer.h"

#include <QTest>

using namespace editor;

class MplLexerTest : public QObject {
    Q_OBJECT

    static QByteArray classes(const QByteArray& line) {
        // One letter per byte: d c l C n s y p e (default comment label command number sign sync display error)
        static const char kLetters[] = "dclCnsype";
        QByteArray out;
        for (const char s : MplLexer::styleLine(line)) out += kLetters[int(s)];
        return out;
    }

private slots:
    void labelLinesAreLabelAndComment() { QCOMPARE(classes("@X_Comment"), QByteArray("llcccccccc")); }
    void motionWithSignsAndSyncs() { QCOMPARE(classes("I,+,-"), QByteArray("Cysys")); }
    void jogReversals() { QCOMPARE(classes("J,-*+*-"), QByteArray("Cysssss")); }
    void conditionsAreHex() { QCOMPARE(classes("BQ10:F0"), QByteArray("Clnnsnn")); }
    void tableGainChains() { QCOMPARE(classes("TGP++V5--"), QByteArray("CCCssCnss")); }
    void threeLetterCommands() { QCOMPARE(classes("THCC0"), QByteArray("CCCnn")); }
    void displaysEndACommand() { QCOMPARE(classes("A?V!"), QByteArray("CpCp")); }
    void loopCounter() { QCOMPARE(classes("LBX20"), QByteArray("ClCnn")); }
    void unknownLetterIsAnError() { QCOMPARE(classes("W5"), QByteArray("ee")); }
    void decimalCommandRejectsHexLetters() { QCOMPARE(classes("A3F"), QByteArray("Cne")); }

    void helpTopicsFromTheCatalog() {
        QCOMPARE(mplTopicAt(QStringLiteral("TGP++V5--"), 5), QStringLiteral("TGV"));
        QCOMPARE(mplTopicAt(QStringLiteral("TGP++V5--"), 3), QStringLiteral("TGP"));
        QCOMPARE(mplTopicAt(QStringLiteral("SM2"), 2), QStringLiteral("SM"));
        QCOMPARE(mplTopicAt(QStringLiteral("I,+,-"), 3), QStringLiteral("I"));
        QCOMPARE(mplTopicAt(QStringLiteral("A0#92"), 3), QStringLiteral("#92"));
        QVERIFY(mplHelpHtml(QStringLiteral("#92")).contains(QStringLiteral("Acceleration")));
        QVERIFY(mplHelpHtml(QStringLiteral("SF")).contains(QStringLiteral("2048")));
        QVERIFY(mplHelpHtml(QStringLiteral("TGP")).contains(QStringLiteral("kept without power")));
        QVERIFY(mplHelpHtml(QStringLiteral("XYZ")).isEmpty());
    }

    void checkFindsUndefinedLabelsAndSize() {
        const auto ok = checkMplProgram("@T\nI+,\nLT9\nE\n");
        QVERIFY(ok.isEmpty());
        const auto missing = checkMplProgram("@T\nBW1\n");
        QCOMPARE(missing.size(), 1);
        QCOMPARE(missing[0].line, 1);
        QVERIFY(missing[0].message.contains("#C2"));
        const auto big = checkMplProgram(QByteArray(2000, '.'));
        QVERIFY(!big.isEmpty());
        QVERIFY(big.last().message.contains("#C1"));
    }
};

QTEST_GUILESS_MAIN(MplLexerTest)
#include "mpl_lexer_test.moc"
