// Tour steps for the SC750's and the PMC-960's Tuning Panel (issue 18): each connects its simulated drive,
// runs the first test move twice with a gain raised between, and grabs the panel with both runs overlaid.
#pragma once

#include "screenshot_tour.h"

#include <vector>

namespace app {

class MainWindow;

std::vector<ScreenshotTour::Step> tuningTourSteps(MainWindow& window);

} // namespace app
