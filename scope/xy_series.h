// An XY plot's data, widget-free: one channel of a capture against another, sample by sample (following
// error against velocity, current against position), and the axis titles naming them with their units.
#pragma once

#include "capture.h"

#include <string>
#include <vector>

namespace scope {

struct XySeries {
    std::vector<double> x; // channel X's values, in time order
    std::vector<double> y; // channel Y's value at the same sample
    std::string xTitle;    // "VFB [VEL]"
    std::string yTitle;    // "PE [POS]"
};

// Empty when either channel index is out of range.
XySeries xySeries(const Capture& capture, std::size_t xChannel, std::size_t yChannel);

} // namespace scope
