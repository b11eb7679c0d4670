// The screenshot tour's Spectrum steps (issue 22): the simulated BDS5's bench given a compliant coupling, a
// velocity step run, LPF set against the resonance, a second run, and Scope > Spectrum showing the resonance
// peak of the first run as the overlay above the filtered one. Appended after the scope's steps.
#pragma once

#include "screenshot_tour.h"

#include <vector>

namespace app {

class MainWindow;

std::vector<ScreenshotTour::Step> spectrumTourSteps(MainWindow& window);

} // namespace app
