// TerminalWidget: what the user sees for the bytes a drive sends, and the bytes their keys send.
#include "app/drive/terminal_widget.h"

#include <QSignalSpy>
#include <QStandardPaths>
#include <QTest>

using app::TerminalWidget;

class TerminalWidgetTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true); // the command history lives in QSettings
        QCoreApplication::setOrganizationName(QStringLiteral("ServoDesk"));
        QCoreApplication::setApplicationName(QStringLiteral("ServoDeskTerminalTest"));
    }
    void crLfStartsALine() {
        TerminalWidget t;
        t.displayBytes("-->P 1\r\n           1\r\n-->");
        QCOMPARE(t.text(), QStringLiteral("-->P 1\n           1\n-->"));
    }
    void crLfSplitAcrossReadsIsOneLineEnd() {
        TerminalWidget t;
        t.displayBytes("ABC\r");
        t.displayBytes("\nDEF");
        QCOMPARE(t.text(), QStringLiteral("ABC\nDEF"));
    }
    void loneLfStartsALine() {
        TerminalWidget t;
        t.displayBytes("A\nB");
        QCOMPARE(t.text(), QStringLiteral("A\nB"));
    }
    void backspaceErasesAndLoneCrOverwrites() {
        TerminalWidget t;
        t.displayBytes("AB\bC\r\nX\rY");
        QCOMPARE(t.text(), QStringLiteral("AC\nY"));
    }
    void loneCrRewritesTheLineInPlace() { // the BDS5 R command refreshes a line this way
        TerminalWidget t;
        t.displayBytes("PFB    1000\rPFB    2000");
        QCOMPARE(t.text(), QStringLiteral("PFB    2000"));
        t.displayBytes("\rAB");
        QCOMPARE(t.text(), QStringLiteral("ABB    2000"));
    }
    void backspaceSpaceBackspaceErasesOneCharacter() {
        TerminalWidget t;
        t.displayBytes("-->PX\b \b1");
        QCOMPARE(t.text(), QStringLiteral("-->P1"));
    }
    void backspaceStopsAtTheStartOfTheLine() {
        TerminalWidget t;
        t.displayBytes("A\r\n\b\bB");
        QCOMPARE(t.text(), QStringLiteral("A\nB"));
    }
    void bellAndOtherControlCharactersAreNotPrinted() {
        TerminalWidget t;
        t.displayBytes("\aERR 17 FEEDBACK LOSS\x01\x1b\x7f!");
        QCOMPARE(t.text(), QStringLiteral("ERR 17 FEEDBACK LOSS!"));
    }
    void bytesAreLatin1() {
        TerminalWidget t;
        t.displayBytes("90\xb0");
        QCOMPARE(t.text(), QStringLiteral("90\u00b0"));
    }
    void noticeGoesOnItsOwnLine() {
        TerminalWidget t;
        t.displayBytes("-->");
        t.displayNotice(QStringLiteral("link lost"));
        t.displayBytes("X");
        QCOMPARE(t.text(), QStringLiteral("-->\n[link lost]\nX"));
    }
    void scrollbackIsBounded() {
        TerminalWidget t;
        QByteArray lots;
        for (int i = 0; i < TerminalWidget::kMaxLines + 500; ++i)
            lots += "LINE " + QByteArray::number(i) + "\r\n";
        t.displayBytes(lots + "-->");
        QVERIFY(t.document()->blockCount() <= TerminalWidget::kMaxLines);
        QVERIFY(t.text().endsWith(QStringLiteral("LINE %1\n-->").arg(TerminalWidget::kMaxLines + 499)));
    }
    void keysSendWhatABds5TerminalSends() {
        TerminalWidget t;
        QByteArray sent, urgent;
        connect(&t, &TerminalWidget::bytesTyped, &t, [&sent](const QByteArray& b) { sent += b; });
        connect(&t, &TerminalWidget::urgentBytesTyped, &t, [&sent, &urgent](const QByteArray& b) {
            sent += b;
            urgent += b;
        });
        QTest::keyClicks(&t, QStringLiteral("P \"a,1\""));
        QTest::keyClick(&t, Qt::Key_Return);
        QTest::keyClick(&t, Qt::Key_Backspace);
        QTest::keyClick(&t, Qt::Key_Escape);
        QTest::keyClick(&t, Qt::Key_X, Qt::ControlModifier);
        QTest::keyClick(&t, Qt::Key_V, Qt::ControlModifier);
        QCOMPARE(sent, QByteArray("P \"a,1\"\r\b\x1b\x18\x16"));
        QCOMPARE(urgent, QByteArray("\x1b\x18")); // Esc and ^X overtake anything queued
        QCOMPARE(t.text(), QString()); // no local echo: the drive echoes
    }
};

QTEST_MAIN(TerminalWidgetTest)
#include "terminal_widget_test.moc"
