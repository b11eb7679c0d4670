// The I/O panel (issue 7) against the simulated BDS5: toggling I1 in the panel fires the manual's A$ I1 ON
// alarm (L4783-4790, example 43: DIS, OUT = 0, B) — the outputs go dark in the panel and the drive says so —
// and the bench goes through SimulatorLink::control, never the serial line; a load torque on the bench is held
// by the motor's current, and Power Cycle brings the sign-on back with the drive disabled. Plus the DEP-01.
#include "app_test_support.h"
#include "app/families/bds5/bds5_workspace.h"
#include "families/bds5/dep01/dep01_panel.h"
#include "families/bds5/dep01/dep01_screen.h"
#include "families/bds5/drive_connection.h"
#include "families/bds5/io_panel.h"
#include "app/main_window.h"

#include "drive_core/bds5/bds5_drive.h"
#include "serialport/bds5_session.h"

#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QFile>
#include <QPushButton>
#include <QRegularExpression>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTest>

using app::MainWindow;

namespace {
using app_test::kDriveTimeoutMs;

bool ready(const MainWindow& window) {
    const auto* session = window.connection().session();
    return session && session->state() == serialport::Bds5Session::State::Ready;
}

// The manual's example as the spec keeps it, with its OCR damage ("AS" for "A$") mended, comments cut.
QStringList alarmExample() {
    QFile file(QStringLiteral(SERVODESK_EXAMPLES "/43-alarm-a.bds"));
    if (!file.open(QIODevice::ReadOnly)) return {};
    QStringList lines;
    for (QString line : QString::fromLatin1(file.readAll()).split(QLatin1Char('\n'))) {
        line = line.section(QLatin1Char(';'), 0, 0).trimmed();
        if (line.startsWith(QLatin1String("AS "))) line.replace(0, 2, QStringLiteral("A$"));
        if (!line.isEmpty()) lines << line;
    }
    return lines;
}
} // namespace

class IoPanelTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QCoreApplication::setOrganizationName(QStringLiteral("ServoDesk"));
        QCoreApplication::setApplicationName(QStringLiteral("ServoDeskIoPanelTest"));
        QSettings().clear();
    }

    void togglingI1FiresTheManualsAlarm() {
        const QStringList program = alarmExample();
        QCOMPARE(program, (QStringList{"A$ I1 ON", "DIS", "OUT = 0", "B"}));
        MainWindow window;
        window.connectDrive(app::ConnectionChoice::simulator());
        window.show();
        QTRY_VERIFY_WITH_TIMEOUT(ready(window), kDriveTimeoutMs);
        app::IoPanel& panel = *window.bds5().ioPanel();
        panel.show();
        QVERIFY(panel.isSimulated());
        auto* session = window.connection().session();
        session->send(QStringLiteral(">BDS"));
        for (const QString& line : program) session->send(line);
        session->sendEscape();
        for (const char* line : {"O1 ON", "O3 ON", "PLIM OFF", "EN"}) session->send(QString::fromLatin1(line));
        QTRY_VERIFY_WITH_TIMEOUT(panel.outputLit(1) && panel.outputLit(3), kDriveTimeoutMs);
        QTRY_VERIFY_WITH_TIMEOUT(ready(window), kDriveTimeoutMs);
        window.connection().sendRaw("RUN\r"); // the program waits; the alarm watches I1
        QTRY_COMPARE_WITH_TIMEOUT(session->mode(), serialport::Bds5Mode::Running, kDriveTimeoutMs); // no prompt
        QVERIFY(panel.outputLit(1));

        QSignalSpy sent(&window.connection(), &app::DriveConnection::rawSent);
        QTest::mouseClick(panel.inputButton(1), Qt::LeftButton);
        QVERIFY(panel.inputButton(1)->isChecked());
        QTRY_VERIFY_WITH_TIMEOUT(!panel.outputLit(1) && !panel.outputLit(3), kDriveTimeoutMs); // OUT = 0
        QVERIFY2(sent.isEmpty(), "the bench does not use the serial line");
        QTRY_VERIFY_WITH_TIMEOUT(ready(window), kDriveTimeoutMs); // B: back at the prompt
        QTRY_VERIFY_WITH_TIMEOUT(window.connection().session()->lastPrompt() == QStringLiteral("-->"), kDriveTimeoutMs);
        QStringList answer;
        const quint64 id = session->send(QStringLiteral("PS OUT ACTIVE"));
        connect(session, &serialport::Bds5Session::finished, this,
                [&answer, id](quint64 done, const serialport::Bds5Response& r) {
                    if (done == id) answer = r.lines;
                });
        QTRY_VERIFY_WITH_TIMEOUT(!answer.isEmpty(), kDriveTimeoutMs);
        // OUT and ACTIVE both 0, and the drive's status word: outputs off, drive disabled.
        QCOMPARE(answer.join(' ').simplified(), QStringLiteral("0 0 OFF"));
    }

    void aLoadTorqueIsHeldByTheMotorsCurrentUntilPowerCycle() {
        MainWindow window;
        window.connectDrive(app::ConnectionChoice::simulator());
        window.show();
        QTRY_VERIFY_WITH_TIMEOUT(ready(window), kDriveTimeoutMs);
        app::IoPanel& panel = *window.bds5().ioPanel();
        panel.show();
        for (const char* line : {"PLIM OFF", "EN"}) window.connection().sendCommand(QString::fromLatin1(line));
        QTRY_VERIFY_WITH_TIMEOUT(panel.readoutText().startsWith(QStringLiteral("ACTIVE")), kDriveTimeoutMs);
        // "I 2.00 A" -> 2.0: the current the bench reports.
        auto amps = [&panel] {
            static const QRegularExpression kCurrent(QStringLiteral(" I (-?[0-9.]+) A"));
            return kCurrent.match(panel.readoutText()).captured(1).toDouble();
        };
        QTRY_VERIFY_WITH_TIMEOUT(std::abs(amps()) < 0.2, kDriveTimeoutMs);

        // 1.5 N m on the shaft of REF-MEDIUM (0.5 N m/A): holding position takes 3 A (plus friction).
        QSignalSpy sent(&window.connection(), &app::DriveConnection::rawSent);
        panel.loadTorqueField()->setValue(1.5);
        QTRY_VERIFY_WITH_TIMEOUT(std::abs(std::abs(amps()) - 3.0) < 0.3, kDriveTimeoutMs);
        QVERIFY2(panel.readoutText().startsWith(QStringLiteral("ACTIVE")), qPrintable(panel.readoutText()));
        QVERIFY2(sent.isEmpty(), "the bench does not use the serial line");

        // Power Cycle: the drive signs on again, powered up disabled, with no current.
        QSignalSpy received(&window.connection(), &app::DriveConnection::rawReceived);
        QTest::mouseClick(panel.powerCycleButton(), Qt::LeftButton);
        auto signedOn = [&received] {
            QByteArray bytes;
            for (const QList<QVariant>& r : received) bytes += r.first().toByteArray();
            return bytes.contains(drive_core::bds5::kSignOn);
        };
        QTRY_VERIFY_WITH_TIMEOUT(signedOn(), kDriveTimeoutMs);
        QTRY_VERIFY_WITH_TIMEOUT(panel.readoutText().startsWith(QStringLiteral("inactive")), kDriveTimeoutMs);
        QTRY_VERIFY_WITH_TIMEOUT(std::abs(amps()) < 0.2, kDriveTimeoutMs);
    }

    void theDep01ShowsTwoFortyColumnLinesWithCursorAddressing() {
        app::Dep01Screen screen;
        screen.feed("HELLO\r\nWORLD");
        QCOMPARE(screen.line(0).trimmed(), QStringLiteral("HELLO"));
        QCOMPARE(screen.line(1).trimmed(), QStringLiteral("WORLD"));
        screen.feed("\r\nTHIRD");
        QCOMPARE(screen.line(0).trimmed(), QStringLiteral("WORLD")); // scrolled
        QCOMPARE(screen.line(1).trimmed(), QStringLiteral("THIRD"));
        screen.feed(QByteArray("\x1b") + char(45) + "X"); // ESC + address 45: row 2, column 6
        QCOMPARE(screen.line(1), QStringLiteral("THIRDX").leftJustified(40));
        screen.feed(QByteArray(45, 'A'));
        QCOMPARE(screen.line(0).size(), 40);
    }

    void theDep01KeypadTalksToTheDrive() {
        MainWindow window;
        window.connectDrive(app::ConnectionChoice::simulator());
        window.show();
        QTRY_VERIFY_WITH_TIMEOUT(ready(window), kDriveTimeoutMs);
        app::Dep01Panel& dep = *window.bds5().dep01Panel();
        dep.show();
        // DEP ON: the drive cuts its messages to the panel's 40 columns (L6102-6108).
        QTest::mouseClick(dep.depSwitch(), Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(ready(window), kDriveTimeoutMs);
        dep.clearDisplay();
        QSignalSpy sent(&window.connection(), &app::DriveConnection::rawSent);
        for (const char* key : {"4", "2"}) QTest::mouseClick(dep.key(QString::fromLatin1(key)), Qt::LeftButton);
        QTest::mouseClick(dep.key(QStringLiteral("ENTER")), Qt::LeftButton);
        // The drive echoes the keys and refuses 42 (no instruction): its 40-character message fills a line.
        QTRY_VERIFY_WITH_TIMEOUT(dep.screen().line(1).startsWith(QStringLiteral("-->")), kDriveTimeoutMs);
        QVERIFY2(dep.screen().line(0).startsWith(QStringLiteral("ERR 80 '42'")), qPrintable(dep.screen().line(0)));
        QTest::mouseClick(dep.key(QStringLiteral("ATTN")), Qt::LeftButton);
        QByteArray all;
        for (const QList<QVariant>& bytes : sent) all += bytes.first().toByteArray();
        QVERIFY2(all.endsWith("\x16"), all.toHex().constData()); // ATTN is ^V
    }
};

QTEST_MAIN(IoPanelTest)
#include "io_panel_test.moc"
