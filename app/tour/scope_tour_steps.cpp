// Scope tour steps: real RECORD/PLAY against the simulated drive at 9600 baud, grabbed as a user sees them.
#include "scope_tour_steps.h"

#include "families/bds5/drive_connection.h"
#include "main_window.h"
#include "scope/bode_view.h"
#include "scope/scope_controller.h"
#include "scope/scope_view.h"
#include "app/tuning/tuning_panel.h"
#include "families/bds5/tuning/bds5_tuning_controls.h"
#include "families/bds5/tuning/tuning_runner.h"
#include "transfer_dialog.h"

#include "scope/scope_plot.h"

#include <QDialog>
#include <QDockWidget>
#include <QPointer>
#include <QSpinBox>
#include <QStatusBar>

namespace app {

namespace {

serialport::Bds5RecordPlan tourStep() {
    serialport::Bds5RecordPlan plan;
    plan.samples = 200;
    plan.intervalMs = 1;
    plan.variables = {QStringLiteral("VCMD"), QStringLiteral("VFB")};
    plan.commands = {{0, QStringLiteral("J 1000")}, {110, QStringLiteral("J 0")}};
    plan.onCancel = QStringLiteral("J 0");
    return plan;
}

// One tuning run with KV set first (0: leave the gains).
ScreenshotTour::Step tuningRun(MainWindow& window, const QString& name, int runs, int kv) {
    TuningPanel* panel = window.scopeController().tuningPanel();
    ScreenshotTour::Step step;
    step.name = name;
    step.act = [panel, kv] {
        if (kv > 0) panel->gainEditor(QStringLiteral("KV"))->setValue(kv);
        panel->runner<app::TuningRunner>().runOnce();
    };
    step.ready = [panel, runs] { return panel->runner<app::TuningRunner>().runs().size() >= runs && !panel->runner<app::TuningRunner>().isRunning(); };
    return step;
}

} // namespace

void setVelocityStep(MainWindow& window, TuningPanel& panel, int amplitude) {
    panel.runner<app::TuningRunner>().setGain(QStringLiteral("KV"), 2000);
    panel.runner<app::TuningRunner>().setGain(QStringLiteral("PL"), 0);
    // ACC may not pass AMAX (L2186), which changes only while disabled (L2180).
    for (const char* line : {"DIS", "AMAX=1000000", "ACC=1000000", "EN"})
        window.connection().sendCommand(QString::fromLatin1(line));
    TestMove move;
    move.kind = TestMove::Kind::FrequencyStep;
    move.amplitude = amplitude;
    move.durationMs = 400;
    app::setTestMove(panel, move);
}

std::vector<ScreenshotTour::Step> scopeTourSteps(MainWindow& window) {
    ScopeController& scope = window.scopeController();
    std::vector<ScreenshotTour::Step> steps;
    steps.push_back({.name = QStringLiteral("scope-step-response"),
                     .act =
                         [&window, &scope] {
                             // As the manual's remedy for ERR 23 says: the factory PMAX/PMIN (+-100 counts)
                             // would stop a jog at once.
                             window.scopeController().tuningRunner().setGain(QStringLiteral("PLIM"), 0);
                             window.connection().sendCommand(QStringLiteral("EN"));
                             scope.record(tourStep());
                         },
                     .ready =
                         [&window, &scope] {
                             if (!scope.lastCapture() || TransferDialog::active()) return false;
                             scope.view()->plot()->setCursors(0.020, 0.070);
                             // Here, not at the grab: the layout must have turns of the event loop to apply it.
                             window.resizeDocks({scope.scopeDock()}, {470}, Qt::Vertical);
                             return true;
                         },
                     .grab = [&window] { return TourShot::of(&window); },
                     .text = [&scope] { return QString::fromStdString(scope.view()->plot()->readout().text()); }});
    auto data = std::make_shared<QPointer<QDialog>>();
    steps.push_back({.name = QStringLiteral("scope-data"),
                     .act = [&scope, data] { *data = scope.viewData(); },
                     .ready = [data] { return *data && (*data)->isVisible(); },
                     .grab = [data] { return TourShot::of(*data); },
                     .cleanUp =
                         [data] {
                             if (*data) (*data)->close();
                         }});
    // The tuning panel floats at the tour's window size so its plot, gains and runs table all show.
    TuningPanel* panel = scope.tuningPanel();
    ScreenshotTour::Step first = tuningRun(window, QStringLiteral("tuning-run-1"), 1, 0);
    const auto runFirst = first.act;
    first.act = [&scope, panel, runFirst] {
        QDockWidget* dock = scope.tuningDock();
        dock->setFloating(true);
        dock->resize(ScreenshotTour::kWindowSize);
        dock->show();
        TestMove move;
        move.durationMs = 80;
        app::setTestMove(*panel, move);
        runFirst();
    };
    steps.push_back(first);
    steps.push_back(tuningRun(window, QStringLiteral("tuning-run-2"), 2, 3000));
    ScreenshotTour::Step third = tuningRun(window, QStringLiteral("tuning-panel"), 3, 1200);
    third.grab = [&scope] { return TourShot::of(scope.tuningDock()); };
    third.text = [panel] { return panel->statusText(); };
    third.cleanUp = [&window, &scope] {
        scope.tuningDock()->hide();
        window.connection().sendCommand(QStringLiteral("DIS"));
    };
    steps.push_back(third);
    // The Bode view of a run with the frequency-response preset (a held velocity step of VCMD and VFB).
    auto bode = std::make_shared<QPointer<BodeView>>();
    ScreenshotTour::Step response = tuningRun(window, QStringLiteral("scope-bode"), 4, 0);
    const auto runFourth = response.act;
    response.act = [&window, panel, runFourth] {
        setVelocityStep(window, *panel, 500);
        runFourth();
    };
    const auto fourthDone = response.ready;
    response.ready = [&scope, bode, fourthDone] {
        if (!fourthDone()) return false;
        if (!*bode) *bode = scope.frequencyResponse();
        return (*bode)->isVisible();
    };
    response.grab = [bode] { return TourShot::of(*bode); };
    response.text = [bode] { return (*bode)->summary(); };
    response.cleanUp = [&window, bode] {
        if (*bode) (*bode)->close();
        window.connection().sendCommand(QStringLiteral("DIS"));
    };
    steps.push_back(response);
    return steps;
}

} // namespace app
