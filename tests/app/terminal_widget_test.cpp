// TerminalWidget: what the user sees for the bytes a drive sends, and the bytes their keys send; that the
// newest line stays in view through hiding and resizing unless the user scrolled up; folded PLAY listings.
#include "app/drive/terminal_widget.h"
#include "families/bds5/record/play_terminal_fold.h"

#include <QScrollBar>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTest>
#include <QTextBlock>

using app::PlayTerminalFold;
using app::TerminalWidget;

namespace {
constexpr int kTimeoutMs = 30000;

// "LINE from" CR LF ... "LINE to-1" CR LF, then a prompt, as a drive sends them.
QByteArray numberedLines(int from, int to) {
    QByteArray bytes;
    for (int i = from; i < to; ++i) bytes += "LINE " + QByteArray::number(i) + "\r\n";
    return bytes + "-->";
}

// Whether the user sees the terminal's last line (the drive's prompt) in the view.
bool lastLineVisible(const TerminalWidget& t) {
    QTextCursor end(t.document());
    end.movePosition(QTextCursor::End);
    const QRect line = t.cursorRect(end);
    return line.top() >= 0 && line.top() < t.viewport()->height();
}

// The text of the line at the top of the view.
QString topLine(const TerminalWidget& t) {
    return t.cursorForPosition(QPoint(8, 8)).block().text();
}

bool isPlayListing(const QString& line) {
    return PlayTerminalFold::isHeaderLine(line) || PlayTerminalFold::isSampleLine(line);
}
} // namespace

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

    // Issue 19 (13): hidden (the dock closed or behind another tab) or resized, the terminal stayed where it
    // was and new output went on below the view.
    void newOutputStaysInViewAfterHideShowAndResize() {
        TerminalWidget t;
        t.resize(480, 160);
        t.show();
        QVERIFY(QTest::qWaitForWindowExposed(&t));
        t.displayBytes(numberedLines(0, 60));
        QTRY_VERIFY_WITH_TIMEOUT(lastLineVisible(t), kTimeoutMs);

        t.hide();
        t.displayBytes("\r\n" + numberedLines(60, 120));
        t.show();
        QVERIFY(QTest::qWaitForWindowExposed(&t));
        QTRY_VERIFY_WITH_TIMEOUT(lastLineVisible(t), kTimeoutMs);
        QCOMPARE(t.document()->lastBlock().previous().text(), QStringLiteral("LINE 119"));

        t.resize(480, 90); // lower: more lines above the view than before
        QTRY_VERIFY_WITH_TIMEOUT(lastLineVisible(t), kTimeoutMs);
        t.displayBytes("\r\n" + numberedLines(120, 130));
        QTRY_VERIFY_WITH_TIMEOUT(lastLineVisible(t), kTimeoutMs);

        t.resize(140, 200); // narrower: long lines wrap into more lines
        t.displayBytes("\r\n" + QByteArray(120, 'W') + "\r\n" + numberedLines(130, 140));
        QTRY_VERIFY_WITH_TIMEOUT(lastLineVisible(t), kTimeoutMs);
        QVERIFY(t.isFollowingOutput());
    }

    void scrolledUpTheViewStaysUntilTheUserScrollsBackOrTypes() {
        TerminalWidget t;
        t.resize(480, 160);
        t.show();
        QVERIFY(QTest::qWaitForWindowExposed(&t));
        t.displayBytes(numberedLines(0, 80));
        QTRY_VERIFY_WITH_TIMEOUT(lastLineVisible(t), kTimeoutMs);

        QScrollBar* bar = t.verticalScrollBar();
        bar->triggerAction(QAbstractSlider::SliderPageStepSub); // a click on the scroll bar above the handle
        QVERIFY(!t.isFollowingOutput());
        const QString reading = topLine(t);
        t.displayBytes("\r\n" + numberedLines(80, 120));
        t.hide();
        t.show();
        QVERIFY(QTest::qWaitForWindowExposed(&t));
        QCOMPARE(topLine(t), reading); // what the user scrolled to is still there
        QVERIFY(!lastLineVisible(t));

        bar->triggerAction(QAbstractSlider::SliderToMaximum); // dragged back to the bottom
        QVERIFY(t.isFollowingOutput());
        t.displayBytes("\r\n" + numberedLines(120, 160));
        QTRY_VERIFY_WITH_TIMEOUT(lastLineVisible(t), kTimeoutMs);

        bar->triggerAction(QAbstractSlider::SliderToMinimum);
        QVERIFY(!t.isFollowingOutput());
        QTest::keyClick(&t, Qt::Key_P); // typing goes to the drive's newest line: it is shown again
        QVERIFY(t.isFollowingOutput());
        t.displayBytes("P");
        QTRY_VERIFY_WITH_TIMEOUT(lastLineVisible(t), kTimeoutMs);
    }

    // Issue 19 (13): each Scope record or tuning run put its PLAY listing, 250-300 lines, in the terminal.
    void aFoldedPlayListingIsOneLineBetweenEchoAndPrompt() {
        TerminalWidget t;
        t.displayBytes("-->");
        const int fold = t.beginFold(isPlayListing);
        QVERIFY(t.isFolding());
        // As the drive sends it, cut anywhere: the echo, the header, a sample per line, the prompt.
        t.displayBytes("PL");
        t.displayBytes("AY\r\nRECORD 3 1 VCMD VFB\r\n           0           0\r\n        10");
        t.displayBytes("00          40\r\n        1000         -12\r\n--");
        t.displayBytes(">");
        QCOMPARE(t.text(), QStringLiteral("-->PLAY\n")); // the listing is not shown; the prompt waits
        t.endFold(fold, QStringLiteral("PLAY: 3 samples \u2192 Scope"));
        QCOMPARE(t.text(), QStringLiteral("-->PLAY\nPLAY: 3 samples \u2192 Scope\n-->"));
        QVERIFY(!t.isFolding());
        t.displayBytes("P 1\r\n           1\r\n-->"); // after the fold every line shows again
        QVERIFY(t.text().endsWith(QStringLiteral("Scope\n-->P 1\n           1\n-->")));
    }

    void aFoldShowsTheLinesItDoesNotFoldAndOnlyItsOwnEnd() {
        TerminalWidget t;
        t.displayBytes("-->");
        const int fold = t.beginFold(isPlayListing);
        t.displayBytes("PLAY\r\nERR 65 RECORD NOT READY\r\n-->");
        QCOMPARE(t.text(), QStringLiteral("-->PLAY\nERR 65 RECORD NOT READY\n"));
        t.endFold(fold + 1, QStringLiteral("not this fold's")); // another fold's end changes nothing
        QVERIFY(t.isFolding());
        t.endFold(fold, QString()); // nothing folded: no summary line
        QCOMPARE(t.text(), QStringLiteral("-->PLAY\nERR 65 RECORD NOT READY\n-->"));
    }

    void playListingLinesAreTold() {
        QVERIFY(PlayTerminalFold::isHeaderLine(QStringLiteral("RECORD 250 2 VCMD VFB")));
        QVERIFY(PlayTerminalFold::isSampleLine(QStringLiteral("           0        -125")));
        QVERIFY(PlayTerminalFold::isSampleLine(QStringLiteral("        1000")));
        QVERIFY(!PlayTerminalFold::isSampleLine(QStringLiteral("-->")));
        QVERIFY(!PlayTerminalFold::isSampleLine(QStringLiteral("-")));
        QVERIFY(!PlayTerminalFold::isSampleLine(QStringLiteral("ERR 65 RECORD NOT READY")));
        QVERIFY(!PlayTerminalFold::isSampleLine(QString()));
    }
};

QTEST_MAIN(TerminalWidgetTest)
#include "terminal_widget_test.moc"
