// The variable browser (issue 7): the catalog as a grouped model, edit validation naming the drive's own
// error, and — against the simulated BDS5 — an edit that reaches the drive and comes back, an out-of-range
// edit refused before sending, a write the drive itself refuses, live polling of the rows in view, the
// watch list and "Copy as .VAR", the search filter, and polling that pauses while a program runs (no prompt).
#include "app_test_support.h"
#include "app/families/bds5/bds5_workspace.h"
#include "families/bds5/drive_actions.h"
#include "families/bds5/drive_connection.h"
#include "app/drive/terminal_widget.h"
#include "app/main_window.h"
#include "app/variables/variable_model.h"
#include "app/variables/variable_sync.h"
#include "app/variables/variable_validator.h"
#include "app/variables/variable_browser.h"
#include "app/variables/variables_dock.h"

#include "serialport/bds5_session.h"

#include <QAction>
#include <QLabel>
#include <QLineEdit>
#include <QSettings>
#include <QPushButton>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTest>
#include <QTreeView>

using app::MainWindow;
using app::VariableModel;
using app::VariableValidator;

namespace {
using app_test::kDriveTimeoutMs;

bool ready(const MainWindow& window) {
    const auto* session = window.connection().session();
    return session && session->state() == serialport::Bds5Session::State::Ready;
}

// A command typed by the test, with its answer.
struct Asked {
    QStringList lines;
    bool done = false;
};
std::shared_ptr<Asked> ask(MainWindow& window, const QString& line) {
    auto asked = std::make_shared<Asked>();
    auto* session = window.connection().session();
    const quint64 id = session->send(line);
    QObject::connect(session, &serialport::Bds5Session::finished, session,
                     [asked, id](quint64 done, const serialport::Bds5Response& response) {
                         if (done != id) return;
                         asked->lines = response.lines;
                         for (const auto& e : response.errors) asked->lines << QStringLiteral("ERR %1").arg(e.code);
                         asked->done = true;
                     });
    return asked;
}
// The variable names the All Variables view shows (groups expanded), as a user scrolling it would read them.
QStringList shownNames(const QAbstractItemModel& model, const QModelIndex& parent = {}) {
    QStringList names;
    for (int r = 0; r < model.rowCount(parent); ++r) {
        const QModelIndex index = model.index(r, 0, parent);
        if (model.rowCount(index) > 0)
            names << shownNames(model, index);
        else
            names << index.data().toString();
    }
    return names;
}

QByteArray allSent(const QSignalSpy& spy) {
    QByteArray bytes;
    for (const QList<QVariant>& s : spy) bytes += s.first().toByteArray() + '\n';
    return bytes;
}
} // namespace

class VariableBrowserTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QCoreApplication::setOrganizationName(QStringLiteral("ServoDesk"));
        QCoreApplication::setApplicationName(QStringLiteral("ServoDeskVariableBrowserTest"));
        QSettings().clear();
    }

    void theCatalogIsGroupedWithUnitsLimitsAndConditions() {
        VariableModel model;
        const QStringList groups = model.groupNames();
        for (const char* g : {"Position", "Velocity", "Current", "Loop gains", "Limits", "Units", "Inputs and outputs",
                              "Switches", "Communication", "User variables"})
            QVERIFY2(groups.contains(QString::fromLatin1(g)), g);
        QVERIFY(model.indexOf(QStringLiteral("X250")).isValid());
        QVERIFY(model.indexOf(QStringLiteral("XS50")).isValid());
        QVERIFY(model.indexOf(QStringLiteral("I16")).isValid());
        QVERIFY(!model.indexOf(QStringLiteral("X251")).isValid());
        QCOMPARE(model.indexOf(QStringLiteral("VMAX"), VariableModel::Unit).data().toString(), QStringLiteral("VEL"));
        QCOMPARE(model.indexOf(QStringLiteral("ADDR"), VariableModel::Limits).data().toString(),
                 QStringLiteral("0 \u2026 90"));
        QCOMPARE(model.indexOf(QStringLiteral("AMAX"), VariableModel::Condition).data().toString(),
                 QStringLiteral("drive disabled"));
        QVERIFY(!(model.indexOf(QStringLiteral("ACTIVE"), VariableModel::Value).flags() & Qt::ItemIsEditable));
        QVERIFY(model.indexOf(QStringLiteral("X1"), VariableModel::Value).flags() & Qt::ItemIsEditable);
        // Limits of scaled variables follow the drive's units once NUM/DEN are known: ACC in RPM/s.
        QVERIFY(!VariableValidator::userLimits(*drive_core::catalog::bds5::findVariable("ACC")->info,
                                               model.validationContext()));
        model.setValue(QStringLiteral("ANUM"), QStringLiteral("4474"));
        model.setValue(QStringLiteral("ADEN"), QStringLiteral("1000"));
        const auto limits = VariableValidator::userLimits(*drive_core::catalog::bds5::findVariable("ACC")->info,
                                                          model.validationContext());
        QVERIFY(limits);
        QCOMPARE(limits->first, 0.0);
        QCOMPARE(qRound64(limits->second), qRound64(2147483647.0 * 1000 / 4474));
    }

    void editsAreCheckedAsTheDriveWouldAndNameItsError() {
        VariableModel model;
        const auto ctx = model.validationContext();
        QCOMPARE(VariableValidator::check(QStringLiteral("X1"), QStringLiteral("42"), ctx).instruction,
                 QStringLiteral("X1 42"));
        QCOMPARE(VariableValidator::check(QStringLiteral("PL"), QStringLiteral("on"), ctx).instruction,
                 QStringLiteral("PL 1"));
        const auto range = VariableValidator::check(QStringLiteral("ADDR"), QStringLiteral("91"), ctx);
        QVERIFY(!range.ok);
        QVERIFY2(range.message.startsWith(QStringLiteral("ERR 83 BAD OR OUT OF RANGE")), qPrintable(range.message));
        QVERIFY(VariableValidator::check(QStringLiteral("VFB"), QStringLiteral("1"), ctx)
                    .message.startsWith(QStringLiteral("ERR 81")));
        model.setValue(QStringLiteral("ACTIVE"), QStringLiteral("1"));
        QVERIFY(VariableValidator::check(QStringLiteral("AMAX"), QStringLiteral("1000"), model.validationContext())
                    .message.startsWith(QStringLiteral("ERR 51")));
        // A value that differs from the last read is highlighted until the highlight fades.
        model.setValue(QStringLiteral("X3"), QStringLiteral("1"));
        QVERIFY(!model.isChanged(QStringLiteral("X3")));
        model.setValue(QStringLiteral("X3"), QStringLiteral("2"));
        QVERIFY(model.isChanged(QStringLiteral("X3")));
        QVERIFY(model.indexOf(QStringLiteral("X3"), VariableModel::Value).data(Qt::BackgroundRole).isValid());
        model.clearChanged();
        QVERIFY(!model.isChanged(QStringLiteral("X3")));
    }

    void anEditReachesTheDriveAndComesBack() {
        MainWindow window;
        window.connectDrive(app::ConnectionChoice::simulator());
        window.show();
        QTRY_VERIFY_WITH_TIMEOUT(ready(window), kDriveTimeoutMs);
        app::VariablesDock& variables = *window.bds5().variablesDock();
        variables.show();
        app::VariableBrowser& dock = *variables.browser();
        dock.reveal(QStringLiteral("X1"));
        dock.editValue(QStringLiteral("X1"), QStringLiteral("1234"));
        QTRY_COMPARE_WITH_TIMEOUT(dock.model().value(QStringLiteral("X1")), QStringLiteral("1234"), kDriveTimeoutMs);
        QCOMPARE(dock.statusText(), QStringLiteral("X1 1234 sent"));
        auto asked = ask(window, QStringLiteral("P X1"));
        QTRY_VERIFY_WITH_TIMEOUT(asked->done, kDriveTimeoutMs);
        QCOMPARE(asked->lines, QStringList{QStringLiteral("        1234")});

        // The watch list and Copy as .VAR.
        dock.model().setPinned(QStringLiteral("X1"), true);
        dock.showWatchList(true);
        QTRY_VERIFY(dock.watchView()->model()->rowCount() == 1);
        QCOMPARE(dock.selectionAsFile().text, QStringLiteral("X1 1234\n"));
        QCOMPARE(dock.copyButton()->text(), QStringLiteral("Copy as .VAR"));

        // Live values: the rows in view are read, VMAX among them once it is scrolled to.
        dock.reveal(QStringLiteral("VMAX"));
        QTRY_COMPARE_WITH_TIMEOUT(dock.model().value(QStringLiteral("VMAX")), QStringLiteral("7500"), kDriveTimeoutMs);
        // A value changed behind the browser's back shows, highlighted.
        asked = ask(window, QStringLiteral("X1=77"));
        QTRY_VERIFY_WITH_TIMEOUT(asked->done, kDriveTimeoutMs);
        QTRY_COMPARE_WITH_TIMEOUT(dock.model().value(QStringLiteral("X1")), QStringLiteral("77"), kDriveTimeoutMs);

        // The polls stay out of the terminal: it shows the edit the user made, not the browser's reads.
        const QString terminal = window.terminal()->text();
        QVERIFY2(terminal.contains(QStringLiteral("-->X1 1234")), qPrintable(terminal.right(400)));
        QVERIFY2(!terminal.contains(QStringLiteral("VMAX")) && !terminal.contains(QStringLiteral("P KP")),
                 qPrintable(terminal.right(400)));
    }

    void anOutOfRangeEditIsRefusedWithTheDrivesError() {
        MainWindow window;
        window.connectDrive(app::ConnectionChoice::simulator());
        window.show();
        QTRY_VERIFY_WITH_TIMEOUT(ready(window), kDriveTimeoutMs);
        app::VariablesDock& variables = *window.bds5().variablesDock();
        variables.show();
        app::VariableBrowser& dock = *variables.browser();
        QSignalSpy sent(&window.connection(), &app::DriveConnection::rawSent);
        dock.editValue(QStringLiteral("ADDR"), QStringLiteral("91"));
        QVERIFY2(dock.statusText().startsWith(QStringLiteral("ERR 83 BAD OR OUT OF RANGE")),
                 qPrintable(dock.statusText()));
        for (const QList<QVariant>& bytes : sent) QVERIFY(!bytes.first().toByteArray().contains("ADDR"));

        // The drive's own refusal: EXTLOOP may change only while disabled, and the browser has not read
        // ACTIVE, so the drive is the one to say no (ERR 51).
        variables.hide(); // no polling: ACTIVE stays unknown
        for (const char* line : {"PLIM OFF", "EN"}) window.connection().sendCommand(QString::fromLatin1(line));
        dock.editValue(QStringLiteral("EXTLOOP"), QStringLiteral("ON"));
        QTRY_VERIFY_WITH_TIMEOUT(dock.statusText().startsWith(QStringLiteral("The drive refused EXTLOOP 1: ERR 51")),
                                 kDriveTimeoutMs);
    }

    void searchNarrowsTheRows() {
        MainWindow window;
        window.connectDrive(app::ConnectionChoice::simulator());
        window.show();
        app::VariablesDock& variables = *window.bds5().variablesDock();
        variables.show();
        app::VariableBrowser& dock = *variables.browser();
        const QAbstractItemModel& shown = *dock.allView()->model();
        const QStringList all = shownNames(shown);
        QVERIFY(all.contains(QStringLiteral("ACC")) && all.contains(QStringLiteral("KVI")));
        QTest::keyClicks(dock.searchField(), QStringLiteral("KV"));
        const QStringList found = shownNames(shown);
        QVERIFY2(found.contains(QStringLiteral("KV")) && found.contains(QStringLiteral("KVI")),
                 qPrintable(found.join(' ')));
        QVERIFY2(!found.contains(QStringLiteral("ACC")), qPrintable(found.join(' ')));
        QVERIFY(found.size() < all.size() / 10);
        dock.searchField()->clear();
        QCOMPARE(shownNames(shown), all);
    }

    void pollingPausesWhileAProgramRuns() {
        MainWindow window;
        window.connectDrive(app::ConnectionChoice::simulator());
        window.show();
        QTRY_VERIFY_WITH_TIMEOUT(ready(window), kDriveTimeoutMs);
        app::VariablesDock& variables = *window.bds5().variablesDock();
        variables.show();
        app::VariableBrowser& dock = *variables.browser();
        dock.reveal(QStringLiteral("VFB"));
        QSignalSpy sent(&window.connection(), &app::DriveConnection::rawSent);
        QTRY_VERIFY_WITH_TIMEOUT(allSent(sent).contains("P "), kDriveTimeoutMs); // the rows in view are polled

        // A program that runs until told otherwise: while it runs the drive shows no prompt to answer P.
        serialport::Bds5Session* session = window.connection().session();
        for (const char* line : {">BDS", "7$", "D 100", "GOTO 7", "B"}) session->send(QString::fromLatin1(line));
        session->sendEscape();
        QTRY_VERIFY_WITH_TIMEOUT(ready(window), kDriveTimeoutMs);
        window.driveActions().run(7);
        QTRY_VERIFY_WITH_TIMEOUT(session->mode() == serialport::Bds5Mode::Running, kDriveTimeoutMs);
        const QString paused = QStringLiteral("paused: the drive runs a program (no prompt)");
        auto pauseShown = [&dock, &paused] {
            for (const QLabel* label : dock.findChildren<QLabel*>())
                if (label->text() == paused && label->isVisible()) return true;
            return false;
        };
        QTRY_VERIFY_WITH_TIMEOUT(pauseShown(), kDriveTimeoutMs);
        sent.clear();
        QTest::qWait(1500); // many poll intervals
        QVERIFY2(!allSent(sent).contains("P "), allSent(sent).constData());

        window.driveActions().breakAction()->trigger();
        QTRY_VERIFY_WITH_TIMEOUT(session->mode() == serialport::Bds5Mode::Interactive && ready(window),
                                 kDriveTimeoutMs);
        QTRY_VERIFY_WITH_TIMEOUT(!pauseShown() && allSent(sent).contains("P "), kDriveTimeoutMs); // polling again
    }
};

QTEST_MAIN(VariableBrowserTest)
#include "variable_browser_test.moc"
