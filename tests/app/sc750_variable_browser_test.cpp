// The SC750's variable browser (issue 8: "the variable browser works for this family too"): every
// predefined variable of the catalog in its group, live values read with G frames, an edit checked against
// the catalog before a P frame goes out, the controller's refusal while a program runs, Add to Watch.
#include "family_window.h"
#include "app/main_window.h"
#include "families/sc750/sc750_controller_menu.h"
#include "families/sc750/sc750_debugger.h"
#include "variables/variable_browser.h"
#include "variables/variable_model.h"
#include "families/sc750/sc750_variable_groups.h"
#include "families/sc750/sc750_variables_dock.h"
#include "families/sc750/sc750_workspace.h"

#include "drive_core/catalog/sc750_catalog.h"
#include "editor/program_editor.h"
#include "serialport/sc750_parameter_file.h"
#include "serialport/sc750_session.h"

#include <QMap>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTest>
#include <QTreeWidget>

using app::MainWindow;
using app::VariableBrowser;
using drive_core::DriveFamily;
namespace catalog = drive_core::catalog::sc750;

namespace {
constexpr int kTimeoutMs = 20000;

const catalog::VariableInfo& info(const char* name) {
    return *catalog::findVariable(name);
}
} // namespace

class Sc750VariableBrowserTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QCoreApplication::setOrganizationName(QStringLiteral("ServoDesk"));
        QCoreApplication::setApplicationName(QStringLiteral("ServoDeskSc750VariableBrowserTest"));
        QSettings().clear();
    }

    void everyVariableHasItsGroupAndEditsAreChecked() {
        const QStringList groups = app::sc750VariableGroups();
        for (const catalog::VariableInfo& v : catalog::variables())
            QVERIFY2(app::sc750VariableGroup(v) != groups.last(), v.name.data()); // none left in "Other"
        QCOMPARE(app::sc750VariableGroup(info("KVI")), QStringLiteral("Set-up parameters"));
        QCOMPARE(app::sc750VariableGroup(info("RUN.SPEED")), QStringLiteral("Motion profile"));
        QCOMPARE(app::sc750VariableGroup(info("POSITION")), QStringLiteral("Position, velocity, current"));
        QCOMPARE(app::sc750VariableGroup(info("INP3")), QStringLiteral("I/O"));
        QCOMPARE(app::sc750VariableGroup(info("WHEN.POS")), QStringLiteral("WHEN latches"));
        QCOMPARE(app::sc750VariableGroup(info("TMOUT_2")), QStringLiteral("Timers"));
        QCOMPARE(app::sc750VariableGroup(info("ENC.FREQ")), QStringLiteral("Gearing and encoder"));

        QVERIFY(!app::sc750CheckValue(info("KVI"), QStringLiteral("20")));
        QCOMPARE(*app::sc750CheckValue(info("KVI"), QStringLiteral("5000")), QStringLiteral("KVI must lie within 0 \u2013 1000."));
        QVERIFY(app::sc750CheckValue(info("POLECOUNT"), QStringLiteral("4.5"))->contains(QStringLiteral("INTEGER")));
        QVERIFY(app::sc750CheckValue(info("POSITION"), QStringLiteral("1"))->contains(QStringLiteral("read only")));
        QVERIFY(app::sc750CheckValue(info("RUN.SPEED"), QStringLiteral("fast"))->contains(QStringLiteral("number")));
    }

    void liveValuesEditsAndRefusals() {
        MainWindow window;
        window.show();
        auto& ws = family_window::connectSc750(window);
        QTRY_VERIFY_WITH_TIMEOUT(ws.isConnected(), kTimeoutMs);
        app::Sc750VariablesDock* dock = ws.variablesDock();
        dock->showAllVariables();
        dock->setFloating(true);
        dock->resize(900, 700);
        VariableBrowser* browser = dock->browser();
        QVERIFY(browser->isVisible());
        QCOMPARE(browser->model().variableCount(), int(catalog::variables().size()));

        // The set-up parameters are at the top, in view: their power-up values arrive by themselves.
        QTRY_COMPARE_WITH_TIMEOUT(browser->value(QStringLiteral("KVI")), QStringLiteral("5"), kTimeoutMs);
        QTRY_COMPARE_WITH_TIMEOUT(browser->value(QStringLiteral("POLECOUNT")), QStringLiteral("4"), kTimeoutMs);

        // Copy as .PRM: the watch list's set-up parameters as the PARAMS block Edit Parameters reads back; a
        // run-time variable (POSITION) cannot be in it.
        for (const char* name : {"KVI", "POSITION", "POLECOUNT"}) browser->model().setPinned(QString::fromLatin1(name), true);
        browser->showWatchList(true);
        QTRY_VERIFY_WITH_TIMEOUT(!browser->value(QStringLiteral("POSITION")).isEmpty(), kTimeoutMs);
        QCOMPARE(browser->copyButton()->text(), QStringLiteral("Copy as .PRM"));
        const auto prm = browser->selectionAsFile();
        QCOMPARE(prm.count, 2);
        const auto parsed = serialport::Sc750ParameterFile::parse(prm.text);
        QVERIFY(parsed.hasBlock() && parsed.problems().isEmpty());
        QMap<QString, QString> assigned;
        for (const auto& a : parsed.assignments()) assigned.insert(a.name, a.value);
        QCOMPARE(assigned.keys(), QStringList({"KVI", "POLECOUNT"}));
        QCOMPARE(assigned.value(QStringLiteral("KVI")).toDouble(), 5.0);
        QCOMPARE(assigned.value(QStringLiteral("POLECOUNT")), QStringLiteral("4"));
        browser->copyButton()->click();
        QCOMPARE(browser->statusText(), QStringLiteral("Copied 2 value(s) as .PRM"));
        browser->showWatchList(false);

        // A value written through the browser is what the controller reports, read back with G.
        browser->reveal(QStringLiteral("RUN.SPEED"));
        QTRY_COMPARE_WITH_TIMEOUT(browser->value(QStringLiteral("RUN.SPEED")), QStringLiteral("1000"), kTimeoutMs);
        QSignalSpy written(browser, &VariableBrowser::written);
        QVERIFY(browser->editValue(QStringLiteral("RUN.SPEED"), QStringLiteral("1234")));
        QTRY_COMPARE_WITH_TIMEOUT(written.count(), 1, kTimeoutMs);
        QVERIFY(written.at(0).at(1).toBool());
        QCOMPARE(browser->value(QStringLiteral("RUN.SPEED")), QStringLiteral("1234"));
        QVERIFY(browser->isChanged(QStringLiteral("RUN.SPEED"))); // highlighted: it was 1000
        QString readBack;
        ws.send('G', QStringLiteral("RUN.SPEED"), [&readBack](const serialport::Sc750Reply& r) { readBack = r.payload; });
        QTRY_COMPARE_WITH_TIMEOUT(readBack, QStringLiteral("RUN.SPEED=1234"), kTimeoutMs);

        // Out of range: refused with the range, and no P frame goes out (the front-panel display's status
        // requests still do).
        browser->setLive(false);
        QSignalSpy sent(ws.session(), &serialport::Sc750Session::rawSent);
        QVERIFY(!browser->editValue(QStringLiteral("KVI"), QStringLiteral("5000")));
        QVERIFY2(browser->statusText().contains(QStringLiteral("0 \u2013 1000")), qPrintable(browser->statusText()));
        // One command at a time on one queue (PROTOCOL.md 3): a read queued after the refused write and
        // answered leaves no room for a P frame of that write.
        QString marker;
        ws.send('G', QStringLiteral("RUN.SPEED"), [&marker](const serialport::Sc750Reply& r) { marker = r.payload; });
        QTRY_COMPARE_WITH_TIMEOUT(marker, QStringLiteral("RUN.SPEED=1234"), kTimeoutMs);
        for (const QList<QVariant>& frame : sent) // SOH and the letter: no P frame at all
            QVERIFY2(!frame.at(0).toByteArray().startsWith("\x01P"), frame.at(0).toByteArray().constData());
        browser->setLive(true);

        // Search narrows the tree.
        browser->setFilter(QStringLiteral("registration"));
        const int shownGroups = browser->allView()->model()->rowCount();
        QVERIFY2(shownGroups >= 1 && shownGroups < browser->model().rowCount(), qPrintable(QString::number(shownGroups)));
        browser->setFilter(QString());

        // While a program runs the controller refuses writes: its own answer is shown.
        family_window::newBasProgram(ws, QStringLiteral("Spin:\n  PAUSE.TIME = 0.1\n  PAUSE\nGOTO Spin\n"));
        ws.debugger().run();
        QTRY_COMPARE_WITH_TIMEOUT(ws.debugger().state(), app::Sc750Debugger::State::Running, kTimeoutMs);
        dock->showAllVariables();
        QVERIFY(browser->editValue(QStringLiteral("RUN.SPEED"), QStringLiteral("500")));
        QTRY_COMPARE_WITH_TIMEOUT(written.count(), 2, kTimeoutMs);
        QVERIFY(!written.at(1).at(1).toBool());
        QVERIFY2(browser->statusText().contains(QStringLiteral("PROGRAM RUNNING")), qPrintable(browser->statusText()));
        QTRY_COMPARE_WITH_TIMEOUT(browser->value(QStringLiteral("RUN.SPEED")), QStringLiteral("1234"), kTimeoutMs);

        // Add to Watch: the Motion Dialogue list reads it.
        emit browser->listRequested(QStringLiteral("KVI"));
        QTRY_COMPARE_WITH_TIMEOUT(dock->value(QStringLiteral("KVI")), QStringLiteral("5"), kTimeoutMs);
    }
};

QTEST_MAIN(Sc750VariableBrowserTest)
#include "sc750_variable_browser_test.moc"
