// Cursor-readout and XY tour steps: real RECORD/PLAY against the simulated drive, shown in the Scope dock.
#include "cursors_xy_tour_steps.h"

#include "families/bds5/drive_connection.h"
#include "main_window.h"
#include "scope/scope_controller.h"
#include "scope/scope_view.h"
#include "app/tuning/tuning_panel.h"
#include "families/bds5/tuning/bds5_tuning_controls.h"
#include "families/bds5/tuning/tuning_runner.h"
#include "transfer_dialog.h"

#include "scope/scope_plot.h"
#include "scope/xy_plot.h"

#include <QTabWidget>

namespace app {

namespace {

// A 1000 velocity step held 110 ms, sampled every millisecond (as the scope tour's own step).
serialport::Bds5RecordPlan step(const QStringList& variables) {
    serialport::Bds5RecordPlan plan;
    plan.samples = 200;
    plan.intervalMs = 1;
    plan.variables = variables;
    plan.commands = {{0, QStringLiteral("J 1000")}, {110, QStringLiteral("J 0")}};
    plan.onCancel = QStringLiteral("J 0");
    return plan;
}

void enableAndRecord(MainWindow& window, const QStringList& variables) {
    // The factory PMAX/PMIN (+-100 counts) would stop the jog at once (ERR 23): PLIM off first.
    window.scopeController().tuningRunner().setGain(QStringLiteral("PLIM"), 0);
    window.connection().sendCommand(QStringLiteral("EN"));
    window.scopeController().record(step(variables));
}

// The recording of these variables is shown (an earlier one of others may still be the last capture).
bool recorded(const ScopeController& scope, const QStringList& variables) {
    if (!scope.lastCapture() || TransferDialog::active()) return false;
    QStringList names;
    for (const scope::CaptureChannel& c : scope.lastCapture()->channels) names << QString::fromStdString(c.name);
    return names == variables;
}

} // namespace

std::vector<ScreenshotTour::Step> cursorsXyTourSteps(MainWindow& window) {
    ScopeController& scope = window.scopeController();
    std::vector<ScreenshotTour::Step> steps;
    const QStringList withCurrent = {QStringLiteral("VCMD"), QStringLiteral("VFB"), QStringLiteral("ICMD")};
    steps.push_back({.name = QStringLiteral("scope-cursors-axes"),
                     .act = [&window, withCurrent] { enableAndRecord(window, withCurrent); },
                     .ready =
                         [&window, &scope, withCurrent] {
                             if (!recorded(scope, withCurrent)) return false;
                             // A where VCMD leaves rest (the J goes out a host round trip after RECORD), B 40 ms
                             // later, in the rise: Δt, 1/Δt and how far each channel moved.
                             const scope::Capture& capture = *scope.lastCapture();
                             const auto& vcmd = capture.channels[0].values;
                             std::size_t start = 0;
                             while (start + 1 < vcmd.size() && vcmd[start + 1] == vcmd[0]) ++start;
                             scope.view()->plot()->setCursors(capture.timeAt(start), capture.timeAt(start) + 0.040);
                             window.resizeDocks({scope.scopeDock()}, {470}, Qt::Vertical);
                             return true;
                         },
                     .grab = [&window] { return TourShot::of(&window); },
                     .text = [&scope] { return QString::fromStdString(scope.view()->plot()->readout().text()); }});
    // The same recording on the XY tab: the current against the velocity (PE, the following error, cannot be
    // recorded: ERR 89).
    steps.push_back({.name = QStringLiteral("scope-xy"),
                     .ready =
                         [&window, &scope, withCurrent] {
                             if (!recorded(scope, withCurrent)) return false;
                             ScopeView* view = scope.view();
                             view->tabs()->setCurrentWidget(view->xyPlot());
                             view->xyPlot()->setChannels(1, 2); // ICMD against VFB
                             window.resizeDocks({scope.scopeDock()}, {470}, Qt::Vertical);
                             return true;
                         },
                     .grab = [&window] { return TourShot::of(&window); },
                     .cleanUp =
                         [&window, &scope] {
                             scope.view()->tabs()->setCurrentIndex(0);
                             window.connection().sendCommand(QStringLiteral("DIS"));
                         }});
    return steps;
}

} // namespace app
