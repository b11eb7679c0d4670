// The cursor readout reads a capture at fixed intervals and a store's live samples at their own times, both
// interpolated between samples and clamped to the first and last.
#include "scope/cursor_readout.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

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

// A 50 Hz sine's period, read between two of its peaks (t = 5 ms and 25 ms, closed form): 1/Δt = 50 Hz, and
// both cursors read the peak, so Δy is 0.
TEST(CursorReadout, APeriodBetweenTwoPeaksReadsAsItsFrequency) {
    Capture capture;
    capture.interval_s = 0.0001; // 10 kHz sampling
    std::vector<double> velocity;
    for (int i = 0; i < 600; ++i) velocity.push_back(1000 * std::sin(2 * M_PI * 50 * i * capture.interval_s));
    capture.channels = {{"VFB", "VEL", velocity}};
    const auto r = scope::readCursors(capture, 0.005, 0.025);
    EXPECT_NEAR(r.delta_s, 0.020, 1e-12);
    EXPECT_NEAR(r.frequency_hz(), 50.0, 1e-9);
    EXPECT_NEAR(r.rows[0].atFirst, 1000, 1e-9);
    EXPECT_NEAR(r.rows[0].atSecond, 1000, 1e-9);
    const std::string text = r.text();
    EXPECT_NE(text.find("A 5.00 ms   B 25.00 ms   \u0394t 20.00 ms   1/\u0394t 50.0 Hz"), std::string::npos) << text;
    EXPECT_NE(text.find("VFB 1000 \u2192 1000  \u0394y 0 VEL"), std::string::npos) << text;
}

// B before A reads a negative Δt but the same frequency; the cursors on one spot have none.
TEST(CursorReadout, FrequencyIsOfTheDistanceBetweenTheCursors) {
    Capture capture;
    capture.channels = {{"ICMD", "%", {0, 10, 20, 30}}};
    const auto reversed = scope::readCursors(capture, 0.0025, 0.0020);
    EXPECT_NEAR(reversed.frequency_hz(), 2000, 1e-6);
    EXPECT_NE(reversed.text().find("\u0394t -500.0 \u00b5s   1/\u0394t 2.00 kHz"), std::string::npos)
        << reversed.text();
    const auto same = scope::readCursors(capture, 0.001, 0.001);
    EXPECT_EQ(same.frequency_hz(), 0);
    EXPECT_NE(same.text().find("1/\u0394t \u2014"), std::string::npos) << same.text();
}

TEST(CursorReadout, TimesAndFrequenciesKeepTheirUnitsReadable) {
    EXPECT_EQ(scope::formatSeconds(0.020), "20.00 ms");
    EXPECT_EQ(scope::formatSeconds(1.25), "1.2500 s");
    EXPECT_EQ(scope::formatSeconds(0.00025), "250.0 \u00b5s");
    EXPECT_EQ(scope::formatHertz(50), "50.0 Hz");
    EXPECT_EQ(scope::formatHertz(2500), "2.50 kHz");
    EXPECT_EQ(scope::formatHertz(0.5), "0.500 Hz");
}

// Channels beyond four go on a further line, so the readout never runs off the plot's width.
TEST(CursorReadout, FiveChannelsTakeTwoLinesUnderTheTimes) {
    Capture capture;
    for (const char* name : {"A1", "A2", "A3", "A4", "A5"}) capture.channels.push_back({name, "", {1, 2}});
    const std::string text = scope::readCursors(capture, 0, 0.001).text();
    EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 2) << text;
    EXPECT_NE(text.find("\nA5 1 \u2192 2"), std::string::npos) << text;
}

// A slice of a record starts later (Capture::start_s): the cursors read it at its own times.
TEST(CursorReadout, ACaptureThatStartsLaterIsReadAtItsOwnTimes) {
    Capture capture;
    capture.interval_s = 0.010;
    capture.start_s = 0.100;
    capture.channels = {{"PFB", "POS", {0, 100, 200}}};
    EXPECT_NEAR(scope::valueAt(capture, 0, 0.105), 50, 1e-9);
    EXPECT_DOUBLE_EQ(scope::valueAt(capture, 0, 0.0), 0); // before the slice: its first sample
}

// Interpolating a zero crossing a hair off the sample leaves -1e-11: the readout says 0, not "-0".
TEST(CursorReadout, ATinyNegativeReadsAsZero) {
    Capture capture;
    capture.channels = {{"ICMD", "%", {0, -1}}};
    const std::string text = scope::readCursors(capture, 0, 1e-14).text();
    EXPECT_NE(text.find("ICMD 0 \u2192 0  \u0394y 0 %"), std::string::npos) << text;
}
