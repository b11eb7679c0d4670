// Math and trigger tour steps: added through the Math dialog and the trigger bar as a user would.
#include "math_trigger_tour_steps.h"

#include "families/bds5/drive_connection.h"
#include "main_window.h"
#include "scope/math_channel_dialog.h"
#include "scope/scope_controller.h"
#include "scope/scope_view.h"
#include "scope/trigger_bar.h"
#include "app/tuning/tuning_panel.h"
#include "families/bds5/tuning/bds5_tuning_controls.h"
#include "families/bds5/tuning/tuning_runner.h"
#include "scope/variable_watcher.h"
#include "scope/watch_trigger.h"
#include "scope/watch_view.h"

#include "scope/scope_plot.h"

#include <QDockWidget>
#include <QPointer>

#include <memory>

namespace app {

namespace {

void addMath(ScopeView* view, scope::MathOp op, const QString& a, const QString& b = {}) {
    MathChannelDialog* dialog = view->openMathDialog();
    dialog->choose(op, a, b);
    dialog->accept();
}

// The trigger step's progress: the value at rest read, the level set above it, the jog sent.
struct TriggerRun {
    QPointer<WatchView> view;
    bool levelSet = false;
    bool jogging = false;
};

} // namespace

std::vector<ScreenshotTour::Step> mathTriggerTourSteps(MainWindow& window) {
    ScopeController& scope = window.scopeController();
    std::vector<ScreenshotTour::Step> steps;
    // The step response recorded by scopeTourSteps, with its following error and VFB's acceleration.
    steps.push_back({.name = QStringLiteral("scope-math"),
                     .act =
                         [&scope] {
                             scope.viewAgain();
                             addMath(scope.view(), scope::MathOp::FollowingError, QStringLiteral("VCMD"),
                                     QStringLiteral("VFB"));
                             addMath(scope.view(), scope::MathOp::Derivative, QStringLiteral("VFB"));
                         },
                     .ready =
                         [&window, &scope] {
                             if (!scope.view()->plot()->store().find("d/dt(VFB)")) return false;
                             // Taller than scope-step-response's: the math channels' measurements show too.
                             window.resizeDocks({scope.scopeDock()}, {560}, Qt::Vertical);
                             return true;
                         },
                     .grab = [&window] { return TourShot::of(&window); },
                     .cleanUp =
                         [&scope] {
                             scope.view()->removeMathChannel(QStringLiteral("FE(VCMD-VFB)"));
                             scope.view()->removeMathChannel(QStringLiteral("d/dt(VFB)"));
                         }});
    // Watch Variables with a Single rising-level trigger on PFB, 25 % pre-trigger, and a jog through it.
    auto run = std::make_shared<TriggerRun>();
    steps.push_back(
        {.name = QStringLiteral("watch-trigger"),
         .act =
             [&window, &scope, run] {
                 scope.tuningRunner().setGain(QStringLiteral("PLIM"), 0); // a jog past PMAX
                 window.connection().sendCommand(QStringLiteral("EN"));
                 WatchView* view = run->view = scope.watchVariables();
                 view->resize(1000, 560);
                 TriggerBar* bar = view->triggerBar();
                 bar->setMode(scope::TriggerMode::Single);
                 bar->setKind(scope::TriggerKind::Level);
                 bar->setSlope(scope::TriggerSlope::Rising);
                 bar->setPreTrigger(25);
                 bar->setFrameSamples(48);
                 bar->setLevel(1e9); // nothing reaches it until the value at rest is known
                 view->watch({QStringLiteral("PFB"), QStringLiteral("VFB")});
             },
         .ready =
             [&window, run] {
                 if (!run->view) return false;
                 const scope::SeriesStore& store = run->view->watcher().store();
                 if (!run->levelSet) {
                     // The channels come in the chooser's order, which need not be the order asked for.
                     const auto pfb = std::size_t(run->view->watcher().variables().indexOf(QStringLiteral("PFB")));
                     if (store.channelCount() < 2 || store.channel(pfb).samples.size() < 2) return false;
                     run->view->triggerBar()->setSource(int(pfb));
                     run->view->triggerBar()->setLevel(store.channel(pfb).samples.back().value + 2000);
                     return run->levelSet = true, false;
                 }
                 if (!run->jogging) {
                     if (run->view->trigger().status() != WatchTrigger::Status::Waiting) return false;
                     window.connection().sendCommand(QStringLiteral("J 100"));
                     return run->jogging = true, false;
                 }
                 return run->view->trigger().frameCount() == 1 && !run->view->watcher().isRunning();
             },
         .grab = [run] { return TourShot::of(run->view); },
         .text = [run] { return run->view ? run->view->triggerBar()->stateText() : QString(); },
         .cleanUp =
             [&window, run] {
                 window.connection().sendCommand(QStringLiteral("J 0"));
                 window.connection().sendCommand(QStringLiteral("DIS"));
                 if (run->view) run->view->close();
             },
         .state = [run] { return run->view ? run->view->triggerBar()->stateText() : QStringLiteral("no view"); }});
    return steps;
}

} // namespace app
