// Channels onto value axes: one axis per unit (sides alternating, labels naming the channels and the unit),
// or one shared axis for all.
#include "scope/axis_groups.h"

#include <gtest/gtest.h>

using scope::AxisMode;
using scope::groupAxes;

namespace {
const std::vector<std::pair<std::string, std::string>> kTuning = {
    {"VCMD", "VEL"}, {"VFB", "VEL"}, {"ICMD", "%"}, {"PFB", "POS"}};
}

TEST(AxisGroups, ChannelsOfOneUnitShareAnAxisAndEachUnitHasItsOwn) {
    const auto layout = groupAxes(kTuning, AxisMode::PerUnit);
    ASSERT_EQ(layout.axes.size(), 3u);
    EXPECT_EQ(layout.axisOf, (std::vector<std::size_t>{0, 0, 1, 2}));
    EXPECT_EQ(layout.axes[0].label, "VCMD, VFB [VEL]");
    EXPECT_EQ(layout.axes[1].label, "ICMD [%]");
    EXPECT_EQ(layout.axes[2].label, "PFB [POS]");
    EXPECT_TRUE(layout.axes[0].left);
    EXPECT_FALSE(layout.axes[1].left); // the second axis on the right
    EXPECT_TRUE(layout.axes[2].left);
}

TEST(AxisGroups, ASharedAxisNamesEveryChannelWithItsUnit) {
    const auto layout = groupAxes(kTuning, AxisMode::Shared);
    ASSERT_EQ(layout.axes.size(), 1u);
    EXPECT_EQ(layout.axisOf, (std::vector<std::size_t>{0, 0, 0, 0}));
    EXPECT_EQ(layout.axes[0].label, "VCMD [VEL], VFB [VEL], ICMD [%], PFB [POS]");
    // One unit throughout: the axis says it once.
    EXPECT_EQ(groupAxes({{"VCMD", "VEL"}, {"VFB", "VEL"}}, AxisMode::Shared).axes[0].label, "VCMD, VFB [VEL]");
}

TEST(AxisGroups, ChannelsWithoutAUnitShareAnAxisNamedByThem) {
    const auto layout = groupAxes({{"X1", ""}, {"X2", ""}}, AxisMode::PerUnit);
    ASSERT_EQ(layout.axes.size(), 1u);
    EXPECT_EQ(layout.axes[0].label, "X1, X2");
    EXPECT_TRUE(groupAxes({}, AxisMode::PerUnit).axes.empty());
}
