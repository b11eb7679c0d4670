// The screenshot tour's steps for the Scope menu and the tuning panel: a recorded velocity step with the
// cursors placed, its data table, and the tuning panel after three runs with KV changed between them.
// Appended to ScreenshotTour's list by buildSteps().
#pragma once

#include "screenshot_tour.h"

#include <vector>

namespace app {

class MainWindow;

std::vector<ScreenshotTour::Step> scopeTourSteps(MainWindow& window);

} // namespace app
