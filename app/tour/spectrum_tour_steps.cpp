// Spectrum tour steps: two tuning runs on a two-mass bench, before and after the low-pass filter, as a user
// makes them (bench fields, gain editors, Run Once), then the Spectrum view grabbed.
#include "spectrum_tour_steps.h"

#include "families/bds5/bds5_workspace.h"

#include "scope_tour_steps.h"

#include "families/bds5/drive_connection.h"
#include "families/bds5/io_panel.h"
#include "main_window.h"
#include "scope/scope_controller.h"
#include "scope/spectrum_view.h"
#include "app/tuning/tuning_panel.h"
#include "families/bds5/tuning/bds5_tuning_controls.h"
#include "families/bds5/tuning/tuning_runner.h"

#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QSpinBox>

#include <memory>

namespace app {

namespace {
// The bench of tests/app/spectrum_test.cpp: a load as heavy as the rotor on a spring, resonance 250 Hz, which
// the velocity loop at its power-up gains makes ring.
constexpr double kLoadInertia_kgm2 = 1.5e-4;
constexpr double kStiffness_NmPerRad = 185;
constexpr double kDamping_NmsPerRad = 0.007;
constexpr int kLpfHz = 62;        // a quarter of the resonance
} // namespace

std::vector<ScreenshotTour::Step> spectrumTourSteps(MainWindow& window) {
    ScopeController& scope = window.scopeController();
    TuningPanel* panel = scope.tuningPanel();
    auto runsBefore = std::make_shared<qsizetype>(0);
    auto runDone = [panel, runsBefore](qsizetype more) {
        return [panel, runsBefore, more] {
            return panel->runner<app::TuningRunner>().runs().size() >= *runsBefore + more && !panel->runner<app::TuningRunner>().isRunning();
        };
    };
    std::vector<ScreenshotTour::Step> steps;
    steps.push_back({.name = QStringLiteral("spectrum-run-1"),
                     .act =
                         [&window, panel, runsBefore] {
                             *runsBefore = panel->runner<app::TuningRunner>().runs().size();
                             IoPanel& bench = *window.bds5().ioPanel();
                             bench.loadInertiaField()->setValue(kLoadInertia_kgm2);
                             bench.couplingStiffnessField()->setValue(kStiffness_NmPerRad);
                             bench.couplingDampingField()->setValue(kDamping_NmsPerRad);
                             panel->runner<app::TuningRunner>().setGain(QStringLiteral("PLIM"), 0);
                             setVelocityStep(window, *panel, 300); // as scope-bode
                             panel->runner<app::TuningRunner>().runOnce();
                         },
                     .ready = runDone(1)});
    auto view = std::make_shared<QPointer<SpectrumView>>();
    steps.push_back({.name = QStringLiteral("spectrum"),
                     .act =
                         [panel] {
                             panel->gainEditor(QStringLiteral("LPFHZ"))->setValue(kLpfHz);
                             panel->gainSwitch(QStringLiteral("LPF"))->setChecked(true);
                             panel->runner<app::TuningRunner>().runOnce();
                         },
                     .ready =
                         [&scope, view, done = runDone(2)] {
                             if (!done()) return false;
                             if (!*view) *view = scope.spectrum(); // "Peak above: auto" finds the resonance
                             return (*view)->isVisible() && (*view)->overlay().has_value();
                         },
                     .grab = [view] { return TourShot::of(*view); },
                     .text = [view] { return (*view)->readout(); },
                     .cleanUp =
                         [&window, panel, view] {
                             if (*view) (*view)->close();
                             panel->gainSwitch(QStringLiteral("LPF"))->setChecked(false);
                             window.bds5().ioPanel()->couplingStiffnessField()->setValue(0); // rigid again
                             window.connection().sendCommand(QStringLiteral("DIS"));
                         }});
    return steps;
}

} // namespace app
