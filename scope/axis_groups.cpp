// Channels grouped onto value axes.
#include "axis_groups.h"

namespace scope {

namespace {
std::string withUnit(const std::string& names, const std::string& unit) {
    return unit.empty() ? names : names + " [" + unit + "]";
}
} // namespace

AxisLayout groupAxes(const std::vector<std::pair<std::string, std::string>>& namesAndUnits, AxisMode mode) {
    AxisLayout layout;
    for (std::size_t c = 0; c < namesAndUnits.size(); ++c) {
        const std::string& unit = namesAndUnits[c].second;
        std::size_t axis = 0;
        if (mode == AxisMode::PerUnit)
            while (axis < layout.axes.size() && layout.axes[axis].unit != unit) ++axis;
        if (axis == layout.axes.size()) layout.axes.push_back({unit, {}, axis % 2 == 0, {}});
        layout.axes[axis].channels.push_back(c);
        layout.axisOf.push_back(axis);
    }
    for (ValueAxisGroup& group : layout.axes) {
        bool mixed = false;
        for (std::size_t c : group.channels) mixed = mixed || namesAndUnits[c].second != group.unit;
        std::string names;
        if (mixed) { // a shared axis: each name with its own unit
            for (std::size_t c : group.channels)
                names += (names.empty() ? "" : ", ") + withUnit(namesAndUnits[c].first, namesAndUnits[c].second);
            group.unit.clear();
            group.label = names;
            continue;
        }
        for (std::size_t c : group.channels) names += (names.empty() ? "" : ", ") + namesAndUnits[c].first;
        group.label = withUnit(names, group.unit);
    }
    return layout;
}

} // namespace scope
