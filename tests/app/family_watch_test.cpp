// Scope > Watch Variables for the SC750 and the PMC-960 (issues 8 and 9): the polled rolling chart reads
// the family's own values over the simulated link — the SC750's POSITION and VELOCITY with G frames while
// its program moves the motor, the PMC-960's position and following error with status polls during an
// index — and plots them, labelled with the measured sample rate. A name the controller does not know
// stops the chart with its answer.
#include "family_window.h"
#include "app/main_window.h"
#include "families/pmc960/pmc960_status_dock.h"
#include "families/pmc960/pmc960_workspace.h"
#include "families/sc750/sc750_controller_menu.h"
#include "families/sc750/sc750_debugger.h"
#include "families/sc750/sc750_workspace.h"
#include "app/scope/variable_watcher.h"
#include "app/scope/watch_source.h"
#include "app/scope/watch_view.h"

#include "editor/program_editor.h"

#include <qcustomplot.h>

#include <QListWidget>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTest>

#include <algorithm>

using app::MainWindow;
using drive_core::DriveFamily;

namespace {
constexpr int kTimeoutMs = 30000;

std::vector<double> valuesOf(const app::VariableWatcher& watcher, std::size_t channel) {
    std::vector<double> values;
    for (const auto& s : watcher.store().channel(channel).samples) values.push_back(s.value);
    return values;
}

// A chart that shows something: every graph has points, and the plot grabbed is not one colour.
bool plotShowsData(QCustomPlot* plot) {
    for (int g = 0; g < plot->graphCount(); ++g)
        if (plot->graph(g)->dataCount() == 0) return false;
    plot->replot();
    const QImage image = plot->toPixmap().toImage();
    const QRgb first = image.pixel(image.width() / 2, image.height() / 2);
    for (int y = 0; y < image.height(); y += 3)
        for (int x = 0; x < image.width(); x += 3)
            if (image.pixel(x, y) != first && qGray(image.pixel(x, y)) < 200 && qBlue(image.pixel(x, y)) > 100)
                return true;
    return false;
}
} // namespace

class FamilyWatchTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QCoreApplication::setOrganizationName(QStringLiteral("ServoDesk"));
        QCoreApplication::setApplicationName(QStringLiteral("ServoDeskFamilyWatchTest"));
        QSettings().clear();
    }

    void sc750PositionAndVelocityWhileAProgramMoves() {
        MainWindow window;
        window.show();
        auto& ws = family_window::connectSc750(window);
        QTRY_VERIFY_WITH_TIMEOUT(ws.isConnected(), kTimeoutMs);
        family_window::newBasProgram(ws, QStringLiteral("ENABLE = 1\nACCEL.RATE = 5000\nRUN.SPEED = 300\nGO.VEL\n"
                                                "Spin:\n  PAUSE.TIME = 0.1\n  PAUSE\nGOTO Spin\n"));

        app::WatchView* view = ws.watchVariables();
        QVERIFY(view->windowTitle().contains(QStringLiteral("SC750")));
        QVERIFY(view->chooser()->count() > 20); // the catalog's numeric variables
        QCOMPARE(view->chooser()->item(0)->text(), QStringLiteral("POSITION")); // what moves comes first

        ws.debugger().run();
        QTRY_COMPARE_WITH_TIMEOUT(ws.debugger().state(), app::Sc750Debugger::State::Running, kTimeoutMs);
        view->watch({QStringLiteral("POSITION"), QStringLiteral("VELOCITY")});
        const app::VariableWatcher& watcher = view->watcher();
        QTRY_VERIFY_WITH_TIMEOUT(watcher.store().channel(0).samples.size() >= 8, kTimeoutMs);
        QVERIFY2(watcher.isRunning(), qPrintable(view->rateLabel()));

        // The motor turns at 300 RPM: the position climbs from sample to sample, the velocity reaches the
        // run speed, and the program kept running throughout.
        const std::vector<double> position = valuesOf(watcher, 0);
        QVERIFY2(position.back() > position.front() + 100, qPrintable(QString::number(position.back())));
        QVERIFY(std::is_sorted(position.begin(), position.end()));
        const std::vector<double> velocity = valuesOf(watcher, 1);
        QVERIFY2(std::abs(velocity.back() - 300) < 15, qPrintable(QString::number(velocity.back())));
        QCOMPARE(ws.debugger().state(), app::Sc750Debugger::State::Running);
        QVERIFY2(view->rateLabel().contains(QStringLiteral("samples/s")), qPrintable(view->rateLabel()));
        QVERIFY(watcher.rate_hz() > 1);
        QVERIFY(view->plot()->graph(0)->name().contains(QStringLiteral("POSITION")));
        QVERIFY(plotShowsData(view->plot()));
        view->stop();
        QVERIFY(!watcher.isRunning());
    }

    void sc750UnknownNameStopsWithTheControllersAnswer() {
        MainWindow window;
        window.show();
        auto& ws = family_window::connectSc750(window);
        QTRY_VERIFY_WITH_TIMEOUT(ws.isConnected(), kTimeoutMs);
        app::WatchView* view = ws.watchVariables();
        app::VariableWatcher& watcher = view->watcher();
        QSignalSpy messages(&watcher, &app::VariableWatcher::message);
        watcher.setVariables({QStringLiteral("NO.SUCH.THING")});
        watcher.start();
        QTRY_VERIFY_WITH_TIMEOUT(!watcher.isRunning(), kTimeoutMs);
        QVERIFY(!messages.isEmpty());
        QVERIFY2(messages.last().at(0).toString().contains(QStringLiteral("UNKNOWN")),
                 qPrintable(messages.last().at(0).toString()));
    }

    void pmc960PositionAndFollowingErrorDuringAnIndex() {
        MainWindow window;
        window.show();
        auto& ws = family_window::connectPmc960(window);
        QTRY_VERIFY_WITH_TIMEOUT(ws.isConnected(), kTimeoutMs);
        app::Pmc960StatusDock* status = ws.statusDock();
        QTRY_VERIFY_WITH_TIMEOUT(status->value(QStringLiteral("mode")).startsWith(QStringLiteral("SM0")), kTimeoutMs);

        app::WatchView* view = ws.watchVariables();
        QVERIFY(view->windowTitle().contains(QStringLiteral("PMC-960")));
        QCOMPARE(view->chooser()->count(), 4);
        view->watch({QStringLiteral("G"), QStringLiteral("SF")});
        const app::VariableWatcher& watcher = view->watcher();
        QTRY_VERIFY_WITH_TIMEOUT(watcher.store().channel(0).samples.size() >= 3, kTimeoutMs);
        QCOMPARE(valuesOf(watcher, 0).back(), 0.0); // at rest where it powered up

        status->sendCommand(QStringLiteral("SM2"));
        status->sendCommand(QStringLiteral("I40000+"));
        // Samples keep coming while the index runs and after it: the position climbs to 40000.
        QTRY_COMPARE_WITH_TIMEOUT(valuesOf(watcher, 0).back(), 40000.0, kTimeoutMs);
        const std::vector<double> position = valuesOf(watcher, 0);
        const auto moving = std::count_if(position.begin(), position.end(), [](double p) { return p > 0 && p < 40000; });
        QString seen;
        for (double p : position) seen += QString::number(p) + QLatin1Char(' ');
        QVERIFY2(moving >= 2, qPrintable(seen));
        QVERIFY(std::is_sorted(position.begin(), position.end()));
        const std::vector<double> following = valuesOf(watcher, 1);
        QVERIFY(std::any_of(following.begin(), following.end(), [](double f) { return f != 0; }));
        QVERIFY(view->plot()->graph(1)->name().contains(QStringLiteral("Following error (SF!) [counts]")));
        QVERIFY2(view->rateLabel().contains(QStringLiteral("samples/s")), qPrintable(view->rateLabel()));
        QVERIFY(plotShowsData(view->plot()));
    }
};

QTEST_MAIN(FamilyWatchTest)
#include "family_watch_test.moc"
