// The screenshot tour's steps for issue 22: a velocity step with its current, cursors A and B placed and the
// readout showing Δt, 1/Δt and each channel's Δy, on two value axes (VEL and %); and the same recording on the
// XY tab, the current ICMD against the velocity VFB. Appended to ScreenshotTour's list by buildSteps().
#pragma once

#include "screenshot_tour.h"

#include <vector>

namespace app {

class MainWindow;

std::vector<ScreenshotTour::Step> cursorsXyTourSteps(MainWindow& window);

} // namespace app
