// The visible range of a capture, written as .CSV: only the samples inside the range, with their own times,
// in the same layout as a whole record, so the file loads back where it was cut from. And an XY plot's data.
#include "scope/capture_csv.h"
#include "scope/capture_slice.h"
#include "scope/xy_series.h"

#include <gtest/gtest.h>

#include <algorithm>

using scope::Capture;

namespace {
// 1000 samples at 1 ms: VFB = i, PE = -2 i.
Capture ramp() {
    Capture c;
    c.interval_s = 0.001;
    c.title = "ramp";
    c.channels = {{"VFB", "VEL", {}}, {"PE", "POS", {}}};
    for (int i = 0; i < 1000; ++i) {
        c.channels[0].values.push_back(i);
        c.channels[1].values.push_back(-2.0 * i);
    }
    return c;
}

std::size_t dataRows(const std::string& csv) {
    return std::size_t(std::count(csv.begin(), csv.end(), '\n')) - 2; // RECORD line and titles
}
} // namespace

TEST(CaptureSlice, KeepsTheSamplesInsideTheRangeWithTheirTimes) {
    const Capture slice = scope::sliceCapture(ramp(), 0.100, 0.200);
    ASSERT_EQ(slice.sampleCount(), 101u); // 100 ms to 200 ms inclusive at 1 ms
    EXPECT_DOUBLE_EQ(slice.timeAt(0), 0.100);
    EXPECT_NEAR(slice.timeAt(100), 0.200, 1e-12);
    EXPECT_EQ(slice.channels[0].values.front(), 100);
    EXPECT_EQ(slice.channels[1].values.back(), -400);
}

TEST(CaptureSlice, ARangeBetweenSamplesTakesTheSamplesInsideIt) {
    const Capture slice = scope::sliceCapture(ramp(), 0.0105, 0.0125);
    ASSERT_EQ(slice.sampleCount(), 2u); // 11 and 12 ms
    EXPECT_DOUBLE_EQ(slice.channels[0].values.front(), 11);
    EXPECT_EQ(scope::sliceCapture(ramp(), -1, 0.0005).sampleCount(), 1u); // clamped to the record
    EXPECT_EQ(scope::sliceCapture(ramp(), 5, 6).sampleCount(), 0u);       // past its end
    EXPECT_EQ(scope::sliceCapture(ramp(), -5, 50).sampleCount(), 1000u);
}

TEST(CaptureSlice, AVisibleRangeCsvHasOnlyItsRowsAndLoadsBackWhereItWas) {
    const std::string csv = scope::writeCsv(scope::sliceCapture(ramp(), 0.250, 0.500));
    EXPECT_EQ(dataRows(csv), 251u);
    EXPECT_EQ(csv.rfind("RECORD,251,1,VFB,PE\r\nTime (s),VFB (VEL),PE (POS)\r\n0.25,250,-500\r\n", 0), 0u)
        << csv.substr(0, 80);
    EXPECT_NE(csv.find("\r\n0.5,500,-1000\r\n"), std::string::npos);
    const auto back = scope::readCsv(csv);
    ASSERT_TRUE(back.capture) << back.error;
    EXPECT_EQ(back.capture->sampleCount(), 251u);
    EXPECT_DOUBLE_EQ(back.capture->start_s, 0.25);
    EXPECT_NEAR(back.capture->timeAt(250), 0.5, 1e-12);
    EXPECT_EQ(scope::writeCsv(*back.capture), csv); // the same file again
}

TEST(XySeries, PairsOneChannelWithAnotherSampleBySample) {
    const auto xy = scope::xySeries(ramp(), 0, 1);
    ASSERT_EQ(xy.x.size(), 1000u);
    EXPECT_EQ(xy.y.size(), 1000u);
    EXPECT_EQ(xy.x[10], 10);
    EXPECT_EQ(xy.y[10], -20);
    EXPECT_EQ(xy.xTitle, "VFB [VEL]");
    EXPECT_EQ(xy.yTitle, "PE [POS]");
    EXPECT_TRUE(scope::xySeries(ramp(), 0, 2).x.empty());
}
