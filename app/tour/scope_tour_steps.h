// The screenshot tour's steps for the Scope menu and the tuning panel: a recorded velocity step with the
// cursors placed, its data table, and the tuning panel after three runs with KV changed between them.
// Appended to ScreenshotTour's list by buildSteps().
#pragma once

#include "screenshot_tour.h"

#include <vector>

namespace app {

class MainWindow;
class TuningPanel;

std::vector<ScreenshotTour::Step> scopeTourSteps(MainWindow& window);

// The velocity loop alone at the power-up KV (position loop off), driven by a true step of amplitude RPM held
// for the record: the loop's own response, for the Bode and spectrum shots.
void setVelocityStep(MainWindow& window, TuningPanel& panel, int amplitude);

} // namespace app
