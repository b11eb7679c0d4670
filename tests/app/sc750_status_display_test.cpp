// The SC750 front-panel status display in the status bar, against the simulated controller: 0 after
// connecting and 8 once enabled, the decimal point lit while a program runs and dark after Stop, and a
// run-time error flashing F and 4 in turn (seed-sc750 §6.1), all learnt from the controller's `?` answers.
#include "family_window.h"
#include "app/main_window.h"
#include "families/sc750/sc750_controller_menu.h"
#include "families/sc750/sc750_debugger.h"
#include "families/sc750/sc750_seven_segment.h"
#include "families/sc750/sc750_status_display.h"
#include "families/sc750/sc750_workspace.h"

#include "editor/program_editor.h"

#include <QImage>
#include <QSettings>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTest>

using app::MainWindow;
using app::Sc750Debugger;
using app::Sc750SevenSegment;
using app::Sc750StatusDisplay;
using app::Sc750Workspace;
using drive_core::DriveFamily;

namespace {
constexpr int kTimeoutMs = 20000;
constexpr int kSegmentsF = 0x71, kSegments4 = 0x66, kSegments8 = 0x7F, kSegments0 = 0x3F;

using family_window::connectSc750WithProgram;

// Is the decimal point painted red? What the user sees, from the widget's pixels at its centre.
bool decimalPointLooksLit(Sc750SevenSegment& digit) {
    const QImage image = digit.grab().toImage();
    const QPointF centre = digit.decimalPointRect().center() * image.devicePixelRatio();
    const QColor c = image.pixelColor(centre.toPoint());
    return c.red() > 200 && c.green() < 100;
}
} // namespace

class Sc750StatusDisplayTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QCoreApplication::setOrganizationName(QStringLiteral("ServoDesk"));
        QCoreApplication::setApplicationName(QStringLiteral("ServoDeskSc750StatusDisplayTest"));
        QSettings().clear();
    }

    // Connected: "0" (no fault, disabled); ENABLE = 1 turns it to "8" (L1527, L1538); no decimal point.
    void showsZeroThenEightWhenEnabled() {
        MainWindow window;
        window.show();
        Sc750Workspace& ws = connectSc750WithProgram(window);
        Sc750StatusDisplay* display = ws.statusDisplay();
        QVERIFY(display);
        QVERIFY(window.statusBar()->isAncestorOf(display));
        QTRY_VERIFY_WITH_TIMEOUT(display->isVisible(), kTimeoutMs);
        QTRY_COMPARE_WITH_TIMEOUT(display->digit()->litSegments(), kSegments0, kTimeoutMs);
        QCOMPARE(display->digit()->shown(), QLatin1Char('0'));
        QCOMPARE(display->meaning(), QStringLiteral("No fault, disabled"));
        QVERIFY(!display->digit()->decimalPoint());
        QVERIFY(!decimalPointLooksLit(*display->digit()));
        bool enabled = false;
        ws.send('P', QStringLiteral("ENABLE=1"), [&enabled](const serialport::Sc750Reply&) { enabled = true; });
        QTRY_VERIFY_WITH_TIMEOUT(enabled, kTimeoutMs);
        QTRY_COMPARE_WITH_TIMEOUT(display->digit()->litSegments(), kSegments8, kTimeoutMs); // the poll sees it
        QCOMPARE(display->meaning(), QStringLiteral("No fault, enabled"));
    }

    // Run: the decimal point lights (L2676); Stop (Ctrl C): it goes out, the fault code stays.
    void decimalPointWhileRunning() {
        MainWindow window;
        window.show();
        Sc750Workspace& ws =
            connectSc750WithProgram(window, QStringLiteral("DIM n AS INTEGER\nTop:\n  n = n + 1\n  GOTO Top\nEND\n"));
        Sc750SevenSegment* digit = ws.statusDisplay()->digit();
        QTRY_COMPARE_WITH_TIMEOUT(digit->shown(), QLatin1Char('0'), kTimeoutMs);
        ws.debugger().run();
        QTRY_COMPARE_WITH_TIMEOUT(ws.debugger().state(), Sc750Debugger::State::Running, kTimeoutMs);
        QTRY_VERIFY_WITH_TIMEOUT(digit->decimalPoint(), kTimeoutMs);
        QVERIFY(decimalPointLooksLit(*digit));
        QCOMPARE(digit->shown(), QLatin1Char('0'));
        ws.debugger().stop();
        QTRY_COMPARE_WITH_TIMEOUT(ws.debugger().state(), Sc750Debugger::State::Stopped, kTimeoutMs);
        QTRY_VERIFY_WITH_TIMEOUT(!digit->decimalPoint(), kTimeoutMs);
        QVERIFY(!decimalPointLooksLit(*digit));
        QCOMPARE(digit->shown(), QLatin1Char('0'));
    }

    // A subscript out of range: FAULTCODE 244, the display alternates F and 4 (L1553, §6.3), the program
    // has ended so the decimal point is dark. Reset Program clears it back to 0.
    void runTimeErrorFlashesF4() {
        MainWindow window;
        window.show();
        Sc750Workspace& ws =
            connectSc750WithProgram(window, QStringLiteral("DIM a(3) AS INTEGER\nDIM i AS INTEGER\ni = 5\na(i) = 1\nEND\n"));
        app::Sc750StatusDisplay* display = ws.statusDisplay();
        QTRY_COMPARE_WITH_TIMEOUT(display->digit()->shown(), QLatin1Char('0'), kTimeoutMs);
        ws.debugger().run();
        QTRY_COMPARE_WITH_TIMEOUT(ws.debugger().state(), Sc750Debugger::State::Faulted, kTimeoutMs);
        QTRY_COMPARE_WITH_TIMEOUT(display->digit()->characters(), QStringLiteral("F4"), kTimeoutMs);
        QCOMPARE(display->meaning(), QStringLiteral("Run time error"));
        QVERIFY(!display->digit()->decimalPoint());
        // Both characters come round, one after the other, each for a flash period.
        QTRY_COMPARE_WITH_TIMEOUT(display->digit()->litSegments(), kSegmentsF, 3 * Sc750SevenSegment::kFlashMs);
        QTRY_COMPARE_WITH_TIMEOUT(display->digit()->litSegments(), kSegments4, 3 * Sc750SevenSegment::kFlashMs);
        QTRY_COMPARE_WITH_TIMEOUT(display->digit()->litSegments(), kSegmentsF, 3 * Sc750SevenSegment::kFlashMs);
        ws.debugger().reset();
        QTRY_COMPARE_WITH_TIMEOUT(display->digit()->characters(), QStringLiteral("0"), kTimeoutMs);
    }

    // Every character of the manual's table lights its own segment pattern (b and 6 differ by one segment).
    void segmentPatternsAreDistinct() {
        const QString chars = QStringLiteral("0123456789AbcdEFUC");
        for (int i = 0; i < chars.size(); ++i) {
            QVERIFY2(Sc750SevenSegment::segmentsOf(chars[i]) != 0, qPrintable(QString(chars[i])));
            for (int j = i + 1; j < chars.size(); ++j)
                QVERIFY2(Sc750SevenSegment::segmentsOf(chars[i]) != Sc750SevenSegment::segmentsOf(chars[j]),
                         qPrintable(QString(chars[i]) + chars[j]));
        }
    }
};

QTEST_MAIN(Sc750StatusDisplayTest)
#include "sc750_status_display_test.moc"
