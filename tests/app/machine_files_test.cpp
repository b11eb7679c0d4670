// The machine's files (issue 21): machine.sdm read and written, and the per-variable and per-line compare the
// backup, compare and restore report from. Pure: no drive.
#include "machine/axis_compare.h"
#include "machine/machine_project.h"

#include <QtTest>

using namespace app::machine;
using drive_core::DriveFamily;

class MachineFilesTest : public QObject {
    Q_OBJECT
private slots:
    void projectRoundTrip() {
        const QString text = QStringLiteral("# a machine\nmachine Line 3 palletiser\nport rfc2217://gw:4001 19200\n"
                                            "backed-up 2026-11-28T08:12:03\n\naxis A bds5 axis-A.bds axis-A.var\n"
                                            "axis B bds5 - axis-B.var\n");
        QString error;
        const auto p = MachineProject::parse(text, error);
        QVERIFY2(p, qPrintable(error));
        QCOMPARE(p->name, QStringLiteral("Line 3 palletiser"));
        QCOMPARE(p->port, QStringLiteral("rfc2217://gw:4001"));
        QCOMPARE(p->baud, 19200);
        QCOMPARE(p->axes.size(), 2);
        QCOMPARE(p->axes[1].programFile, QString()); // "-": no program kept
        const auto again = MachineProject::parse(p->toText(), error);
        QVERIFY(again);
        QCOMPARE(again->toText(), p->toText());
        QCOMPARE(again->axes[0].variablesFile, QStringLiteral("axis-A.var"));
    }

    void projectErrorsNameTheLine_data() {
        QTest::addColumn<QString>("text");
        QTest::addColumn<QString>("error");
        QTest::newRow("twice") << "axis A bds5 a b\naxis A bds5 c d\n" << "line 2: axis A is named twice";
        QTest::newRow("family") << "axis A bds6 a b\n" << "line 1: unknown family \"bds6\"";
        QTest::newRow("mixed") << "axis A bds5 a b\naxis B pmc960 c d\n" << "line 2: one line carries one family";
        QTest::newRow("sc750 id") << "axis 255 sc750 a b\n" << "line 1: \"255\" is not an SC750 multidrop address";
        QTest::newRow("word") << "axes A\n" << "line 1: \"axes\" is not a machine project word";
        QTest::newRow("baud") << "port /dev/ttyS0 fast\naxis A bds5 a b\n" << "line 1: \"fast\" is not a baud rate";
        QTest::newRow("empty") << "# nothing\n" << "the project names no axis";
    }
    void projectErrorsNameTheLine() {
        QFETCH(QString, text);
        QFETCH(QString, error);
        QString why;
        QVERIFY(!MachineProject::parse(text, why));
        QVERIFY2(why.contains(error), qPrintable(why));
    }

    void backupFileNamesUseTheFamilysSuffixes() {
        QCOMPARE(MachineProject::axisNamed("B", DriveFamily::Bds5).programFile, QStringLiteral("axis-B.bds"));
        QCOMPARE(MachineProject::axisNamed("7", DriveFamily::Sc750).variablesFile, QStringLiteral("axis-7.prm"));
        QCOMPARE(MachineProject::axisNamed("A", DriveFamily::Pmc960).programFile, QStringLiteral("axis-A.mpl"));
    }

    // Values are compared as the drive would take them: "3000" and "3000.0" are one value.
    void variablesCompareByNameAndValue() {
        const QString file = QStringLiteral("; header\nVMAX 3000\nX1 5\nACC 100000\n");
        const QString drive = QStringLiteral("VMAX 3000.0\nX1 7\nACC 100000\nX2 1\n");
        const QList<CompareRow> rows = compareVariables(DriveFamily::Bds5, file, drive);
        QCOMPARE(rows.size(), 4);
        const QList<CompareRow> d = differences(rows);
        QCOMPARE(d.size(), 2);
        QCOMPARE(d[0].key, QStringLiteral("X1"));
        QCOMPARE(d[0].left, QStringLiteral("5"));
        QCOMPARE(d[0].right, QStringLiteral("7"));
        QCOMPARE(d[0].leftLine, 3);
        QCOMPARE(d[1].key, QStringLiteral("X2")); // only on the drive
        QCOMPARE(d[1].left, QString());
    }

    void pmc960SettingLinesSplitIntoNameAndValue() {
        const QString file = QStringLiteral("@.table\nSW1\nTGP16\nTGV16\nSW0\n");
        const QString drive = QStringLiteral("SW1\nTGP20\nTGV16\nSW0\n");
        const QList<CompareRow> d = differences(compareVariables(DriveFamily::Pmc960, file, drive));
        QCOMPARE(d.size(), 1);
        QCOMPARE(d[0].key, QStringLiteral("TGP"));
        QCOMPARE(d[0].left, QStringLiteral("16"));
        QCOMPARE(d[0].right, QStringLiteral("20"));
    }

    // An inserted line is one row, not a difference on every line after it; a changed line pairs side by side.
    void programLinesAlign() {
        const QStringList file{"10$", "X1=1", "X2=2", "B"};
        const QStringList drive{"10$", "X1=1", "X9=9", "X2=2   ", "B"};
        QList<CompareRow> d = differences(compareProgram(file, drive));
        QCOMPARE(d.size(), 1);
        QCOMPARE(d[0].leftLine, 0);
        QCOMPARE(d[0].rightLine, 3);
        QCOMPARE(d[0].right, QStringLiteral("X9=9"));
        d = differences(compareProgram(file, {"10$", "X1=1", "X2=3", "B"}));
        QCOMPARE(d.size(), 1);
        QCOMPARE(d[0].leftLine, 3);
        QCOMPARE(d[0].left, QStringLiteral("X2=2"));
        QCOMPARE(d[0].right, QStringLiteral("X2=3"));
    }

    // "Take the drive's value" rewrites that one line of the file and keeps the rest as it was.
    void takingAValueRewritesItsLine() {
        QCOMPARE(withValue(DriveFamily::Bds5, "; h\nVMAX 3000\nX1 5\n", "X1", "7"), QStringLiteral("; h\nVMAX 3000\nX1 7\n"));
        QCOMPARE(withValue(DriveFamily::Bds5, "VMAX 3000\n", "X2", "1"), QStringLiteral("VMAX 3000\nX2 1\n"));
        QCOMPARE(withValue(DriveFamily::Sc750, "PARAMS START\nKVP = 0.087086\nPARAMS END", "KVP", "0.05"),
                 QStringLiteral("PARAMS START\nKVP = 0.05\nPARAMS END"));
        QCOMPARE(withValue(DriveFamily::Sc750, "PARAMS START\nPARAMS END", "ILC", "59"),
                 QStringLiteral("PARAMS START\nILC = 59\nPARAMS END"));
        QCOMPARE(withValue(DriveFamily::Pmc960, "SW1\nTGP16\nSW0\n", "TGV", "20"), QStringLiteral("SW1\nTGP16\nTGV20\nSW0\n"));
        QCOMPARE(settingLine(DriveFamily::Sc750, "KVP", "0.05"), QStringLiteral("KVP=0.05"));
    }

    // A restore leaves each BDS5 axis the ADDR it answers by (a new ADDR puts it to sleep, L5424).
    void restoreKeepsTheLinkSettings() {
        const QString file = QStringLiteral("ACC 1000\nADDR 65\nBAUD 9600\nX1 2\n");
        QCOMPARE(withoutVariables(DriveFamily::Bds5, file, linkSettings(DriveFamily::Bds5)), QStringLiteral("ACC 1000\nX1 2\n"));
    }
};

QTEST_GUILESS_MAIN(MachineFilesTest)
#include "machine_files_test.moc"
