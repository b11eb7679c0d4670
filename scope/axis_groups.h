// Which value axis each scope channel is drawn against, widget-free. One axis per unit (the default): VCMD and
// VFB in VEL share one, ICMD in % gets its own, so a small current is not flattened by a large velocity;
// or one shared axis for every channel, to compare sizes directly. The first axis is on the left, the
// second on the right, then left and right again, each further out.
#pragma once

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace scope {

enum class AxisMode { PerUnit, Shared };

struct ValueAxisGroup {
    std::string unit;                  // the channels' unit; "" for none, or mixed units on a shared axis
    std::vector<std::size_t> channels; // in channel order
    bool left = true;
    std::string label; // "VCMD, VFB [VEL]", "ICMD [%]"; on a shared axis of mixed units "VCMD [VEL], ICMD [%]"
};

struct AxisLayout {
    std::vector<ValueAxisGroup> axes;
    std::vector<std::size_t> axisOf; // per channel, an index into axes
};

// namesAndUnits: the channels in order, as ScopePlot::beginLive takes them. No channels: no axes.
AxisLayout groupAxes(const std::vector<std::pair<std::string, std::string>>& namesAndUnits, AxisMode mode);

} // namespace scope
