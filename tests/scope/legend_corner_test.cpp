// The legend's corner: it leaves a corner where a trace runs under it for one where less does, and otherwise
// stays where it is.
#include "scope/legend_corner.h"

#include <gtest/gtest.h>

#include <cmath>

using scope::bestLegendCorner;
using scope::LegendCorner;
using scope::legendBox;
using scope::PixelBox;
using scope::PixelPoint;
using scope::segmentsThrough;

namespace {

const PixelBox kArea{0, 0, 300, 200};
constexpr double kWidth = 80;
constexpr double kHeight = 30;
constexpr double kMargin = 5;

// A step near the left edge that rises to the top and comes back down halfway: the PMC-960 tuning view's tach.
// Two samples make its rising edge, neither of them under a top-left legend.
const std::vector<std::vector<PixelPoint>> kEarlyStep{
    {{0, 190}, {10, 190}, {12, 10}, {150, 10}, {152, 190}, {300, 190}}};

} // namespace

TEST(LegendCorner, BoxesSitInTheirCornersInsideTheMargin) {
    const PixelBox tl = legendBox(kArea, kWidth, kHeight, kMargin, LegendCorner::TopLeft);
    EXPECT_DOUBLE_EQ(tl.left, 5);
    EXPECT_DOUBLE_EQ(tl.top, 5);
    const PixelBox br = legendBox(kArea, kWidth, kHeight, kMargin, LegendCorner::BottomRight);
    EXPECT_DOUBLE_EQ(br.left, 215);
    EXPECT_DOUBLE_EQ(br.top, 165);
    EXPECT_DOUBLE_EQ(br.width, kWidth);
    EXPECT_DOUBLE_EQ(br.height, kHeight);
}

TEST(LegendCorner, ARisingEdgeBetweenTwoSamplesCountsAsHidden) {
    // its rising edge and the start of its plateau
    EXPECT_EQ(segmentsThrough(kEarlyStep, legendBox(kArea, kWidth, kHeight, kMargin, LegendCorner::TopLeft)), 2);
    EXPECT_EQ(segmentsThrough(kEarlyStep, legendBox(kArea, kWidth, kHeight, kMargin, LegendCorner::TopRight)), 0);
    // the base line at y 190 runs through both bottom boxes (165 to 195)
    EXPECT_EQ(segmentsThrough(kEarlyStep, legendBox(kArea, kWidth, kHeight, kMargin, LegendCorner::BottomLeft)), 2);
    EXPECT_EQ(segmentsThrough(kEarlyStep, legendBox(kArea, kWidth, kHeight, kMargin, LegendCorner::BottomRight)), 1);
}

TEST(LegendCorner, ALineBesideTheBoxIsNotUnderIt) {
    const PixelBox box{10, 10, 20, 20};
    EXPECT_EQ(segmentsThrough({{{0, 5}, {100, 5}}}, box), 0);   // above, parallel to its top
    EXPECT_EQ(segmentsThrough({{{40, 0}, {40, 100}}}, box), 0); // to its right
    EXPECT_EQ(segmentsThrough({{{0, 70}, {70, 0}}}, box), 0);   // past its bottom-right corner
    EXPECT_EQ(segmentsThrough({{{0, 40}, {40, 0}}}, box), 1);   // across it
    EXPECT_EQ(segmentsThrough({{{15, 15}}}, box), 1);           // a lone sample inside
    const double gap = std::nan("");
    EXPECT_EQ(segmentsThrough({{{0, 20}, {gap, gap}, {40, 20}}}, box), 0); // a gap where it would cross
}

TEST(LegendCorner, TheLegendLeavesTheRisingEdgeForTheEmptyTopRight) {
    EXPECT_EQ(bestLegendCorner(kEarlyStep, kArea, kWidth, kHeight, kMargin, LegendCorner::TopLeft),
              LegendCorner::TopRight);
}

TEST(LegendCorner, AClearCornerKeepsTheLegend) {
    // top left is clear of a step that starts late: the legend stays, though top right would be clear too
    const std::vector<std::vector<PixelPoint>> late{{{0, 190}, {120, 190}, {122, 10}, {200, 10}, {202, 190}}};
    EXPECT_EQ(bestLegendCorner(late, kArea, kWidth, kHeight, kMargin, LegendCorner::TopLeft), LegendCorner::TopLeft);
    EXPECT_EQ(bestLegendCorner(kEarlyStep, kArea, kWidth, kHeight, kMargin, LegendCorner::TopRight),
              LegendCorner::TopRight);
}

TEST(LegendCorner, ItMovesOnlyForLessAndTakesTheFirstOfEqualCorners) {
    // a frame 10 pixels in hides two segments in every corner: no corner is better, the legend stays
    const std::vector<std::vector<PixelPoint>> frame{{{10, 10}, {290, 10}, {290, 190}, {10, 190}, {10, 10}}};
    for (const LegendCorner c : {LegendCorner::TopLeft, LegendCorner::BottomRight})
        EXPECT_EQ(bestLegendCorner(frame, kArea, kWidth, kHeight, kMargin, c), c);
    // the early step from the bottom left (two segments there): top right (none) wins
    EXPECT_EQ(bestLegendCorner(kEarlyStep, kArea, kWidth, kHeight, kMargin, LegendCorner::BottomLeft),
              LegendCorner::TopRight);
    // a flat line through the middle of the top boxes: the bottom right is first of the two clear corners
    const std::vector<std::vector<PixelPoint>> high{{{0, 20}, {300, 20}}};
    EXPECT_EQ(bestLegendCorner(high, kArea, kWidth, kHeight, kMargin, LegendCorner::TopLeft),
              LegendCorner::BottomRight);
}
