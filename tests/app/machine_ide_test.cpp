// The machine in the IDE (issue 21), for every family, as a new user does it: the Axes panel scans a
// simulated 4-axis line, backs the machine up, Use Axis points the IDE at one axis (the title and the link
// name it) where a variable is changed; Compare shows exactly that difference, Take File's puts the file's
// value back, a second change is undone by Restore, and Compare is then clean.
#include "main_window.h"

#include "families/bds5/drive_connection.h"
#include "family_workspace.h"
#include "families/sc750/sc750_workspace.h"
#include "machine/axes_dock.h"
#include "machine/axis_compare.h"

#include "serialport/drive_session.h"
#include "serialport/link.h"

#include <QCheckBox>
#include <QDir>
#include <QFile>
#include <QListWidget>
#include <QPushButton>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QtTest>

using namespace app;
using drive_core::DriveFamily;

namespace {
constexpr int kJobMs = 120000; // a generous bound: the drives run 20 times faster than real time
}

class MachineIdeTest : public QObject {
    Q_OBJECT

    // One line as the user types it on the axis in use; its answer accepted.
    static bool typeLine(MainWindow& window, const QString& line) {
        serialport::DriveSession* session = window.workspace(window.activeFamily())->driveSession();
        QSignalSpy answered(session, &serialport::DriveSession::answered);
        session->sendLine(line);
        return answered.wait(kJobMs) && answered.last()[1].value<serialport::LineAnswer>().ok();
    }
    static bool connected(MainWindow& window) {
        const FamilyWorkspace* w = window.workspace(window.activeFamily());
        return w->driveSession() && w->driveSession()->isReady();
    }
    static QString linkText(MainWindow& window) {
        const FamilyWorkspace* w = window.workspace(window.activeFamily());
        return w->link() ? w->link()->description() : QString();
    }
    static bool runJob(AxesDock& dock, const std::function<void()>& start) {
        QSignalSpy finished(&dock, &AxesDock::jobFinished);
        start();
        return finished.wait(kJobMs) && finished.last()[0].toBool();
    }

private slots:
    void backupCompareRestore_data() {
        QTest::addColumn<int>("family");
        QTest::addColumn<QString>("ids");
        QTest::addColumn<QString>("axis");
        QTest::addColumn<QStringList>("change");
        QTest::addColumn<QString>("variable");
        QTest::addColumn<double>("value");
        QTest::newRow("bds5") << int(DriveFamily::Bds5) << "A,B,C,D" << "B" << QStringList{"X1=5"} << "X1" << 5.0;
        QTest::newRow("sc750") << int(DriveFamily::Sc750) << "1,2,3,4" << "2" << QStringList{"KVP=0.05"} << "KVP" << 0.05;
        QTest::newRow("pmc960") << int(DriveFamily::Pmc960) << "A,B,C,D" << "B" << QStringList{"SW1", "TGP20", "SW0"}
                                << "TGP" << 20.0;
    }
    void backupCompareRestore() {
        QFETCH(int, family);
        QFETCH(QString, ids);
        QFETCH(QString, axis);
        QFETCH(QStringList, change);
        QFETCH(QString, variable);
        QFETCH(double, value);
        MainWindow window{DriveFamily(family)};
        window.show();
        AxesDock& dock = *window.axesDock();
        dock.setSimulatorSpeed(20);
        dock.setSimulatedLine(DriveFamily(family), ids);

        QSignalSpy scanned(&dock, &AxesDock::scanFinished);
        dock.scan();
        QVERIFY(scanned.wait(kJobMs));
        QCOMPARE(dock.table()->rowCount(), 4);
        QStringList found;
        for (int r = 0; r < 4; ++r) found << dock.table()->item(r, 0)->text();
        QCOMPARE(found.join(u','), ids);
        for (int r = 0; r < 4; ++r) // each axis's status, read after the scan: powered up, not yet enabled
            QVERIFY2(dock.table()->item(r, 3)->text().contains("disabled"), qPrintable(dock.table()->item(r, 3)->text()));

        QTemporaryDir tmp;
        const QString dir = tmp.filePath("backup");
        QVERIFY2(runJob(dock, [&] { dock.backUpTo(dir); }), qPrintable(dock.statusText()));
        QVERIFY(QFile::exists(dir + "/machine.sdm"));

        // Use Axis: every tool talks to that axis; the title and the link say which.
        dock.useAxis(axis);
        QTRY_VERIFY_WITH_TIMEOUT(connected(window), kJobMs);
        QVERIFY2(window.windowTitle().contains("axis " + axis), qPrintable(window.windowTitle()));
        QVERIFY2(linkText(window).startsWith("axis " + axis + " on Simulated"), qPrintable(linkText(window)));
        if (DriveFamily(family) == DriveFamily::Sc750) // its own axis field (Controller > Axis, the status bar)
            QCOMPARE(static_cast<app::Sc750Workspace*>(window.workspace(DriveFamily::Sc750))->axis(), axis.toInt());
        for (const QString& line : change) QVERIFY2(typeLine(window, line), qPrintable(line));

        // Compare: exactly the one variable, on that axis, the file's value beside the drive's.
        QVERIFY(!runJob(dock, [&] { dock.compareWith(dir); })); // not every axis matches
        QVERIFY(window.axisInUse().isEmpty()); // the panel took the line
        MachineCompareDialog* compare = dock.compareDialog();
        QVERIFY(compare && compare->isVisible());
        QCOMPARE(compare->differenceCount(), 1);
        QCOMPARE(compare->table()->rowCount(), 1);
        QCOMPARE(compare->table()->item(0, 0)->text(), variable);
        QCOMPARE(compare->table()->item(0, 2)->text().toDouble(), value);
        QVERIFY(compare->axesList()->currentItem()->text().startsWith("Axis " + axis));

        // Take File's: the file's value goes back to the drive, and the row matches.
        compare->table()->selectRow(0);
        QSignalSpy busy(&dock, &AxesDock::busyChanged);
        compare->takeFilesButton()->click();
        QTRY_VERIFY_WITH_TIMEOUT(!dock.isBusy() && !busy.isEmpty(), kJobMs);
        QCOMPARE(compare->differenceCount(), 0);
        QVERIFY2(runJob(dock, [&] { dock.compareWith(dir); }), qPrintable(dock.statusText()));
        QCOMPARE(dock.compareDialog()->differenceCount(), 0);

        // Another change, undone by Restore; Compare is clean after it.
        dock.useAxis(axis);
        QTRY_VERIFY_WITH_TIMEOUT(connected(window), kJobMs);
        for (const QString& line : change) QVERIFY(typeLine(window, line));
        QVERIFY2(runJob(dock, [&] { dock.restoreFrom(dir); }), qPrintable(dock.statusText()));
        for (int r = 0; r < 4; ++r)
            QVERIFY2(dock.table()->item(r, 4)->text().startsWith("done"), qPrintable(dock.table()->item(r, 4)->text()));
        QVERIFY2(runJob(dock, [&] { dock.compareWith(dir); }), qPrintable(dock.statusText()));
        QCOMPARE(dock.compareDialog()->differenceCount(), 0);

        // Two backups, no drive: a copy with one value changed shows that one row; Take Right writes it.
        const QString copy = tmp.filePath("copy");
        QVERIFY(QDir().mkpath(copy));
        for (const QString& name : QDir(dir).entryList(QDir::Files)) QVERIFY(QFile::copy(dir + "/" + name, copy + "/" + name));
        QString error;
        const auto project = machine::readMachineProject(copy, error);
        QVERIFY2(project, qPrintable(error));
        const QString varFile = copy + "/" + project->axis(axis)->variablesFile;
        QFile vars(varFile);
        QVERIFY(vars.open(QIODevice::ReadOnly));
        const QString text = QString::fromLatin1(vars.readAll());
        vars.close();
        const auto values = machine::namedValues(DriveFamily(family), text);
        const auto it = std::find_if(values.begin(), values.end(), [&](const machine::NamedValue& v) { return v.name == variable; });
        QVERIFY(it != values.end());
        QVERIFY(vars.open(QIODevice::WriteOnly | QIODevice::Truncate));
        vars.write(machine::withValue(DriveFamily(family), text, variable, "7").toLatin1());
        vars.close();
        dock.compareBackups(dir, copy);
        QCOMPARE(dock.compareDialog()->differenceCount(), 1);
        QCOMPARE(dock.compareDialog()->table()->item(0, 0)->text(), variable);
        QCOMPARE(dock.compareDialog()->table()->item(0, 2)->text(), QStringLiteral("7"));
        QVERIFY(!dock.compareDialog()->takeFilesButton()->isVisible()); // no drive to send to

        // The backup's project sets the panel up again: its line and its axes.
        dock.setSimulatedLine(DriveFamily(family), axis);
        dock.openProject(dir);
        QCOMPARE(dock.table()->rowCount(), 4);
        QCOMPARE(dock.table()->item(3, 2)->text(), QStringLiteral("in the project"));
        QVERIFY2(dock.statusText().contains("backed up 20"), qPrintable(dock.statusText()));
        QVERIFY2(dock.line()->description().contains(ids), qPrintable(dock.line()->description()));
    }

    // Broadcast (the BDS5's '\*'): every axis takes the line, none answers; the SC750's line has none.
    void broadcastReachesEveryAxis() {
        MainWindow window;
        AxesDock& dock = *window.axesDock();
        dock.setSimulatorSpeed(20);
        dock.setSimulatedLine(DriveFamily::Bds5, "A,B,C");
        QSignalSpy scanned(&dock, &AxesDock::scanFinished);
        dock.scan();
        QVERIFY(scanned.wait(kJobMs));
        dock.broadcast("X7=9");
        QVERIFY2(dock.statusText().startsWith("Broadcast"), qPrintable(dock.statusText()));
        for (const QString axis : {"A", "C"}) {
            dock.useAxis(axis);
            QTRY_VERIFY_WITH_TIMEOUT(connected(window), kJobMs);
            QSignalSpy done(window.connection().session(), &serialport::Bds5Session::finished);
            window.connection().sendCommand("P X7");
            QVERIFY(done.wait(kJobMs));
            QCOMPARE(done.last()[1].value<serialport::Bds5Response>().lines.join("").trimmed(), QStringLiteral("9"));
        }
        dock.setSimulatedLine(DriveFamily::Sc750, "1,2");
        dock.broadcast("KVP=1");
        QVERIFY2(dock.statusText().contains("has no broadcast"), qPrintable(dock.statusText()));
    }

    // A project of another family, or a folder without one, is refused where the user looks.
    void wrongFoldersAreRefused() {
        MainWindow window;
        AxesDock& dock = *window.axesDock();
        QTemporaryDir tmp;
        dock.compareWith(tmp.path());
        QVERIFY2(dock.statusText().contains("machine.sdm"), qPrintable(dock.statusText()));
        QFile f(tmp.filePath("machine.sdm"));
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("axis 1 sc750 a.bas a.prm\n");
        f.close();
        dock.restoreFrom(tmp.path());
        QVERIFY2(dock.statusText().contains("SC750 machine"), qPrintable(dock.statusText()));
        QVERIFY(!dock.isBusy());
        dock.backUpTo(tmp.filePath("x"));
        QVERIFY2(dock.statusText().contains("Scan the line first"), qPrintable(dock.statusText()));
    }
};

QTEST_MAIN(MachineIdeTest)
#include "machine_ide_test.moc"
