// The screenshot tour's steps for issue 22 in the IDE: the Scope dock with math channels (the following
// error and d/dt of the recorded step response) and Watch Variables holding a triggered frame of a BDS5 jog.
// Appended to ScreenshotTour's list by buildSteps(), after the scope's steps (they need its recorded step).
#pragma once

#include "screenshot_tour.h"

#include <vector>

namespace app {

class MainWindow;

std::vector<ScreenshotTour::Step> mathTriggerTourSteps(MainWindow& window);

} // namespace app
