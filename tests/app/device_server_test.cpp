// The IDE on a serial device server (issue 21): for each family, servodesk-sim --tcp serves the simulated drive
// on the loopback and the main window connects with rfc2217://127.0.0.1:PORT (as Drive > Connect or --port
// would): the family's workspace comes up connected and its drive answers. The connection dialog refuses a
// device server's address without a port, says why, and keeps what was typed.
#include "app/drive/connection_dialog.h"
#include "families/bds5/drive_connection.h"
#include "app/main_window.h"
#include "families/pmc960/pmc960_workspace.h"
#include "families/sc750/sc750_workspace.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QLabel>
#include <QLineEdit>
#include <QProcess>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTest>

using drive_core::DriveFamily;

namespace {
// A real servodesk-sim process over the loopback: each wait ends at its event; the bound is for a failure.
constexpr int kRealTimeMs = 60000;
} // namespace

class DeviceServerTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QCoreApplication::setOrganizationName(QStringLiteral("ServoDesk"));
        QCoreApplication::setApplicationName(QStringLiteral("ServoDeskDeviceServerTest"));
        QSettings().clear();
    }

    void eachFamilyOverRfc2217_data() {
        QTest::addColumn<DriveFamily>("family");
        QTest::newRow("BDS5") << DriveFamily::Bds5;
        QTest::newRow("SC750") << DriveFamily::Sc750;
        QTest::newRow("PMC-960") << DriveFamily::Pmc960;
    }
    void eachFamilyOverRfc2217() {
        QFETCH(DriveFamily, family);
        QProcess sim;
        sim.setProgram(QStringLiteral(SERVODESK_SIM));
        sim.setArguments({QStringLiteral("--drive"), app::ConnectionChoice::familyKey(family), QStringLiteral("--tcp"),
                          QStringLiteral("0")});
        sim.start();
        QVERIFY(sim.waitForStarted(5000));
        QTRY_VERIFY_WITH_TIMEOUT(sim.canReadLine(), kRealTimeMs);
        const QString first = QString::fromLatin1(sim.readLine()).trimmed();
        QVERIFY2(first.startsWith(QStringLiteral("TCP 127.0.0.1:")), qPrintable(first));
        const QString url = QStringLiteral("rfc2217://") + first.mid(4);

        app::MainWindow window;
        window.show();
        app::ConnectionChoice choice = app::ConnectionChoice::serialPort(url, 9600);
        choice.family = family;
        window.connectDrive(choice);
        if (family == DriveFamily::Bds5) {
            app::DriveConnection& connection = window.connection();
            QTRY_VERIFY_WITH_TIMEOUT(connection.session() &&
                                         connection.session()->state() == serialport::Bds5Session::State::Ready,
                                     kRealTimeMs);
            QCOMPARE(connection.linkDescription(), url + QStringLiteral(" 9600 8N1"));
            QSignalSpy finished(connection.session(), &serialport::Bds5Session::finished);
            connection.sendCommand(QStringLiteral("P \"OVER THE NETWORK\""));
            QVERIFY(finished.wait(kRealTimeMs));
            QCOMPARE(finished.first().at(1).value<serialport::Bds5Response>().lines,
                     QStringList{QStringLiteral("OVER THE NETWORK")});
        } else {
            app::FamilyWorkspace* ws = window.workspace(family);
            QVERIFY(ws);
            // Connected means the drive answered: the SC750 its identification, the PMC-960 its status poll.
            QTRY_VERIFY_WITH_TIMEOUT(ws->isConnected(), kRealTimeMs);
            QVERIFY2(ws->statusText().contains(url), qPrintable(ws->statusText()));
        }
        sim.terminate();
        QVERIFY(sim.waitForFinished(5000));
    }

    void theDialogRefusesAnAddressWithoutAPort() {
        app::MainWindow window;
        window.show();
        app::ConnectionDialog* dialog = window.showConnectionDialog();
        QVERIFY(dialog);
        dialog->setChoice(app::ConnectionChoice::serialPort(QStringLiteral("tcp://plant-gw"), 9600));
        dialog->findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Ok)->click();
        QVERIFY(dialog->isVisible()); // not accepted: nothing was connected
        bool said = false;
        for (const QLabel* label : dialog->findChildren<QLabel*>())
            said = said || label->text().contains(QStringLiteral("tcp://plant-gw is not a serial device server"));
        QVERIFY(said);
        QComboBox* port = nullptr;
        for (QComboBox* combo : dialog->findChildren<QComboBox*>())
            if (combo->isEditable()) port = combo;
        QVERIFY(port);
        QCOMPARE(port->currentText(), QStringLiteral("tcp://plant-gw")); // kept, to be corrected
        dialog->reject();
    }
};

QTEST_MAIN(DeviceServerTest)
#include "device_server_test.moc"
