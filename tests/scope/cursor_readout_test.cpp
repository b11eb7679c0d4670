// The cursor readout reads a capture at fixed intervals and a store's live samples at their own times, both
// interpolated between samples and clamped to the first and last.
#include "scope/cursor_readout.h"

#include <gtest/gtest.h>

using scope::Capture;
using scope::SeriesStore;

TEST(CursorReadout, ReadsACaptureBetweenItsSamples) {
    Capture capture;
    capture.interval_s = 0.010;
    capture.channels = {{"VCMD", "VEL", {0, 1000, 1000, 1000}}};
    const auto r = scope::readCursors(capture, 0.005, 0.030);
    ASSERT_EQ(r.rows.size(), 1u);
    EXPECT_DOUBLE_EQ(r.rows[0].atFirst, 500);
    EXPECT_DOUBLE_EQ(r.rows[0].atSecond, 1000);
    EXPECT_NE(r.text().find("VCMD 500 \u2192 1000"), std::string::npos);
}

TEST(CursorReadout, ReadsLiveSamplesAtTheirOwnTimes) {
    SeriesStore store;
    const auto pfb = store.addChannel("PFB", "POS");
    store.append(pfb, {1.0, 0});
    store.append(pfb, {1.5, 100}); // polls are not evenly spaced
    store.append(pfb, {3.5, 500});
    const auto r = scope::readCursors(store, 1.25, 2.5);
    ASSERT_EQ(r.rows.size(), 1u);
    EXPECT_EQ(r.rows[0].name, "PFB");
    EXPECT_EQ(r.rows[0].unit, "POS");
    EXPECT_DOUBLE_EQ(r.rows[0].atFirst, 50);
    EXPECT_DOUBLE_EQ(r.rows[0].atSecond, 300);
    EXPECT_DOUBLE_EQ(r.rows[0].delta, 250);
}

TEST(CursorReadout, LiveCursorsOutsideTheSamplesReadTheNearestEnd) {
    SeriesStore store;
    const auto c = store.addChannel("VFB", "VEL");
    EXPECT_DOUBLE_EQ(scope::valueAt(store.channel(c), 1.0), 0); // nothing yet
    store.append(c, {2.0, 40});
    store.append(c, {3.0, 60});
    EXPECT_DOUBLE_EQ(scope::valueAt(store.channel(c), 0.0), 40);
    EXPECT_DOUBLE_EQ(scope::valueAt(store.channel(c), 9.0), 60);
}
