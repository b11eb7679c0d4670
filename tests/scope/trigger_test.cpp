// Triggered captures as a user sees them on a scope: the frame holds the asked pre-trigger samples before
// the trigger sample, rising and falling pick the right crossings, Single stops, Normal re-arms (and skips
// crossings inside a frame), Auto forces frames after its time-out in sample time; the ring under it
// overwrites its oldest samples.
#include "scope/trigger.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

using namespace scope;

namespace {

struct Fed {
    std::vector<TriggerFrame> frames;
    std::vector<std::size_t> completedAt; // the sample index whose feed returned each frame
};

// Feeds samples 0 .. n-1 at time i * dt, channel values from f(i).
template <typename F> Fed feedAll(Trigger& trigger, std::size_t n, double dt, F f) {
    Fed fed;
    for (std::size_t i = 0; i < n; ++i) {
        const std::vector<double> values = f(i);
        if (auto frame = trigger.feed(double(i) * dt, values)) {
            fed.frames.push_back(std::move(*frame));
            fed.completedAt.push_back(i);
        }
    }
    return fed;
}

// 0 for 100 samples, 1 for 100, ...: rising through 0.5 at 100, 300, 500, ...; falling at 200, 400, ...
std::vector<double> square(std::size_t i) {
    return {(i / 100) % 2 == 1 ? 1.0 : 0.0};
}

} // namespace

TEST(SampleRing, OverwritesTheOldestWhenFull) {
    SampleRing ring(4, 2);
    for (int i = 0; i < 6; ++i) ring.push(0.1 * i, std::vector<double>{double(i), -double(i)});
    EXPECT_EQ(ring.size(), 4u);
    EXPECT_TRUE(ring.full());
    EXPECT_EQ(ring.pushed(), 6u);
    for (std::size_t i = 0; i < 4; ++i) { // samples 2 .. 5, oldest first
        EXPECT_DOUBLE_EQ(ring.time(i), 0.1 * double(i + 2));
        EXPECT_DOUBLE_EQ(ring.value(i, 0), double(i + 2));
        EXPECT_DOUBLE_EQ(ring.value(i, 1), -double(i + 2));
    }
    ring.clear();
    EXPECT_EQ(ring.size(), 0u);
    EXPECT_EQ(ring.pushed(), 0u);
}

TEST(Trigger, FrameHasTheAskedPreTriggerSamples) {
    // A step 0 -> 1 at sample 3000; 25 % of 1000: the trigger sample is preceded by 250 and followed by 749.
    TriggerSettings s{.level = 0.5, .frameLength = 1000, .preTrigger_pct = 25, .mode = TriggerMode::Single};
    Trigger trigger(2, s);
    ASSERT_TRUE(trigger.error().empty()) << trigger.error();
    EXPECT_EQ(trigger.preTriggerSamples(), 250u);
    const double dt = 0.001;
    const Fed fed = feedAll(trigger, 5000, dt, [](std::size_t i) {
        return std::vector<double>{i >= 3000 ? 1.0 : 0.0, double(i)};
    });
    ASSERT_EQ(fed.frames.size(), 1u);
    EXPECT_EQ(fed.completedAt[0], 3000u + 749u);
    const TriggerFrame& f = fed.frames[0];
    EXPECT_TRUE(f.triggered);
    EXPECT_EQ(f.triggerSample, 3000u);
    EXPECT_DOUBLE_EQ(f.trigger_s, 3000 * dt);
    EXPECT_EQ(f.triggerIndex, 250u);
    ASSERT_EQ(f.time_s.size(), 1000u);
    ASSERT_EQ(f.values.size(), 2u);
    EXPECT_DOUBLE_EQ(f.time_s[0], 2750 * dt);
    EXPECT_DOUBLE_EQ(f.time_s[250], 3000 * dt);
    EXPECT_DOUBLE_EQ(f.time_s.back(), 3749 * dt);
    EXPECT_EQ(f.values[0][249], 0.0);
    EXPECT_EQ(f.values[0][250], 1.0);
    for (std::size_t i = 0; i < 1000; ++i) ASSERT_EQ(f.values[1][i], double(2750 + i)); // channel 2 rides along
}

TEST(Trigger, RisingAndFallingPickTheirCrossings) {
    // sin(2 pi (i + 0.5) / 100) on channel 2: falls through 0 between samples 49 and 50, rises between 99
    // and 100.
    const auto wave = [](std::size_t i) {
        return std::vector<double>{0.0, std::sin(2 * std::numbers::pi * (double(i) + 0.5) / 100)};
    };
    const auto firstTrigger = [&](TriggerSlope slope) {
        Trigger t(2, {.channel = 1,
                      .slope = slope,
                      .level = 0,
                      .frameLength = 100,
                      .preTrigger_pct = 10,
                      .mode = TriggerMode::Single});
        const Fed fed = feedAll(t, 400, 0.001, wave);
        EXPECT_EQ(fed.frames.size(), 1u);
        EXPECT_EQ(t.state(), Trigger::State::Stopped);
        return fed.frames.empty() ? std::uint64_t(0) : fed.frames[0].triggerSample;
    };
    EXPECT_EQ(firstTrigger(TriggerSlope::Rising), 100u);
    EXPECT_EQ(firstTrigger(TriggerSlope::Falling), 50u);
    EXPECT_EQ(firstTrigger(TriggerSlope::Either), 50u);
}

TEST(Trigger, EdgeFiresOnAStepWhateverTheLevel) {
    // 100 with a +-0.5 ripple, stepping to 105 at sample 400: a rising edge of at least 2.
    const auto signal = [](std::size_t i) {
        return std::vector<double>{(i >= 400 ? 105.0 : 100.0) + (i % 2 ? 0.5 : -0.5)};
    };
    Trigger rising(1, {.kind = TriggerKind::Edge, .minStep = 2, .frameLength = 200, .mode = TriggerMode::Single});
    const Fed up = feedAll(rising, 1000, 0.001, signal);
    ASSERT_EQ(up.frames.size(), 1u);
    EXPECT_EQ(up.frames[0].triggerSample, 400u);
    Trigger falling(1, {.kind = TriggerKind::Edge,
                        .slope = TriggerSlope::Falling,
                        .minStep = 2,
                        .frameLength = 200,
                        .mode = TriggerMode::Single});
    EXPECT_TRUE(feedAll(falling, 1000, 0.001, signal).frames.empty());
}

TEST(Trigger, HysteresisIgnoresRippleAroundTheLevel) {
    // 0.49, 0.51, ... around the 0.5 level for 300 samples, then down to 0 and up to 1 at 350.
    const auto signal = [](std::size_t i) {
        return std::vector<double>{i < 300 ? (i % 2 ? 0.51 : 0.49) : i < 350 ? 0.0 : 1.0};
    };
    Trigger t(1, {.level = 0.5, .hysteresis = 0.1, .frameLength = 100, .mode = TriggerMode::Single});
    const Fed fed = feedAll(t, 600, 0.001, signal);
    ASSERT_EQ(fed.frames.size(), 1u);
    EXPECT_EQ(fed.frames[0].triggerSample, 350u);
}

TEST(Trigger, SingleStopsAfterOneFrameUntilArmedAgain) {
    Trigger t(1, {.level = 0.5, .frameLength = 100, .preTrigger_pct = 50, .mode = TriggerMode::Single});
    const Fed fed = feedAll(t, 2000, 0.001, square);
    ASSERT_EQ(fed.frames.size(), 1u);
    EXPECT_EQ(fed.frames[0].triggerSample, 100u);
    EXPECT_EQ(t.state(), Trigger::State::Stopped);
    EXPECT_FALSE(t.feed(2.0, std::vector<double>{0.0}));
    t.arm(); // sample numbering starts again
    EXPECT_EQ(t.state(), Trigger::State::Filling);
    Fed again;
    for (std::size_t i = 0; i < 400; ++i)
        if (auto f = t.feed(3.0 + double(i) * 0.001, square(i))) again.frames.push_back(*f);
    ASSERT_EQ(again.frames.size(), 1u);
    EXPECT_EQ(again.frames[0].triggerSample, 100u);
}

TEST(Trigger, NormalReArmsAfterEachFrame) {
    // Rising at 100 + 200 k; a frame of 100 (50 before, 49 after) ends at 149 + 200 k, before the next.
    Trigger t(1, {.level = 0.5, .frameLength = 100, .preTrigger_pct = 50, .mode = TriggerMode::Normal});
    const Fed fed = feedAll(t, 2000, 0.001, square);
    ASSERT_EQ(fed.frames.size(), 10u); // triggers 100 .. 1900: the last frame ends at 1949 < 2000
    for (std::size_t k = 0; k < fed.frames.size(); ++k) {
        EXPECT_EQ(fed.frames[k].triggerSample, 100 + 200 * k);
        EXPECT_EQ(fed.completedAt[k], 149 + 200 * k);
        EXPECT_TRUE(fed.frames[k].triggered);
    }
    EXPECT_NE(t.state(), Trigger::State::Stopped);
}

TEST(Trigger, NormalIgnoresCrossingsInsideAFrame) {
    // A frame of 300 from the trigger at 100 runs to 349, over the crossing at 300; that crossing is not
    // taken late at the re-arm (the signal is high there), so the next trigger is 500.
    Trigger t(1, {.level = 0.5, .frameLength = 300, .preTrigger_pct = 50 / 3.0, .mode = TriggerMode::Normal});
    EXPECT_EQ(t.preTriggerSamples(), 50u);
    const Fed fed = feedAll(t, 1000, 0.001, square);
    ASSERT_EQ(fed.frames.size(), 2u);
    EXPECT_EQ(fed.frames[0].triggerSample, 100u);
    EXPECT_EQ(fed.frames[1].triggerSample, 500u);
}

TEST(Trigger, AutoForcesFramesAfterItsTimeOutInSampleTime) {
    // A flat signal never triggers. dt = 1/1024 s and a time-out of 100 dt (exact in binary): armed at
    // sample 0, forced at 100; the frame (25 before, 74 after) ends at 174; re-armed at 175, forced at 275...
    const double dt = 1.0 / 1024;
    Trigger t(
        1,
        {.level = 0.5, .frameLength = 100, .preTrigger_pct = 25, .mode = TriggerMode::Auto, .autoTimeout_s = 100 * dt});
    const Fed fed = feedAll(t, 600, dt, [](std::size_t) { return std::vector<double>{0.0}; });
    ASSERT_EQ(fed.frames.size(), 3u);
    for (std::size_t k = 0; k < 3; ++k) {
        EXPECT_FALSE(fed.frames[k].triggered);
        EXPECT_EQ(fed.frames[k].triggerSample, 100 + 175 * k);
        EXPECT_EQ(fed.frames[k].triggerIndex, 25u);
        EXPECT_EQ(fed.frames[k].time_s.size(), 100u);
    }
    // The time-out counts sample time: samples 1 s apart with a 5 s time-out force at the fifth sample on.
    Trigger slow(1,
                 {.level = 0.5, .frameLength = 2, .preTrigger_pct = 0, .mode = TriggerMode::Auto, .autoTimeout_s = 5});
    const Fed seconds = feedAll(slow, 8, 1.0, [](std::size_t) { return std::vector<double>{0.0}; });
    ASSERT_FALSE(seconds.frames.empty());
    EXPECT_EQ(seconds.frames[0].triggerSample, 5u);
}

TEST(Trigger, AutoTakesARealTriggerBeforeItsTimeOut) {
    Trigger t(
        1, {.level = 0.5, .frameLength = 100, .preTrigger_pct = 25, .mode = TriggerMode::Auto, .autoTimeout_s = 1.0});
    const Fed fed = feedAll(t, 300, 0.001, [](std::size_t i) { return std::vector<double>{i >= 60 ? 1.0 : 0.0}; });
    ASSERT_FALSE(fed.frames.empty());
    EXPECT_TRUE(fed.frames[0].triggered);
    EXPECT_EQ(fed.frames[0].triggerSample, 60u);
}

TEST(Trigger, NoTriggerBeforeThePreTriggerSamplesAreIn) {
    // A crossing at sample 10 with 250 pre-trigger samples asked: too early, so the frame stays whole and the
    // trigger is the next crossing (at 600).
    Trigger t(1, {.level = 0.5, .frameLength = 1000, .preTrigger_pct = 25, .mode = TriggerMode::Single});
    const Fed fed = feedAll(t, 2000, 0.001, [](std::size_t i) {
        return std::vector<double>{(i >= 10 && i < 500) || i >= 600 ? 1.0 : 0.0};
    });
    ASSERT_EQ(fed.frames.size(), 1u);
    EXPECT_EQ(fed.frames[0].triggerSample, 600u);
}

TEST(Trigger, AllPreTriggerEndsTheFrameAtTheTriggerSample) {
    Trigger t(1, {.level = 0.5, .frameLength = 10, .preTrigger_pct = 100, .mode = TriggerMode::Single});
    EXPECT_EQ(t.preTriggerSamples(), 9u);
    const Fed fed = feedAll(t, 300, 0.001, square);
    ASSERT_EQ(fed.frames.size(), 1u);
    EXPECT_EQ(fed.completedAt[0], 100u);
    EXPECT_EQ(fed.frames[0].triggerIndex, 9u);
    EXPECT_DOUBLE_EQ(fed.frames[0].time_s.back(), 0.1);
}

TEST(Trigger, BlocksGiveTheSameFramesAsSingleSamples) {
    const TriggerSettings s{.level = 0.5, .frameLength = 100, .preTrigger_pct = 30, .mode = TriggerMode::Normal};
    Trigger one(2, s), block(2, s);
    const Fed expected = feedAll(one, 1500, 0.001, [](std::size_t i) {
        return std::vector<double>{square(i)[0], double(i)};
    });
    std::vector<double> times, interleaved;
    for (std::size_t i = 0; i < 1500; ++i) {
        times.push_back(double(i) * 0.001);
        interleaved.push_back(square(i)[0]);
        interleaved.push_back(double(i));
    }
    std::vector<TriggerFrame> got;
    for (std::size_t at = 0; at < 1500; at += 64) { // blocks of 64, the last one short
        const std::size_t n = std::min<std::size_t>(64, 1500 - at);
        for (auto& f : block.feed(std::span(times).subspan(at, n), std::span(interleaved).subspan(2 * at, 2 * n)))
            got.push_back(std::move(f));
    }
    ASSERT_EQ(got.size(), expected.frames.size());
    for (std::size_t k = 0; k < got.size(); ++k) {
        EXPECT_EQ(got[k].triggerSample, expected.frames[k].triggerSample);
        EXPECT_EQ(got[k].values, expected.frames[k].values);
    }
}

TEST(Trigger, RefusesTimesThatGoBackAndBadSettings) {
    Trigger t(1, {.level = 0.5, .frameLength = 10});
    t.feed(1.0, std::vector<double>{0.0});
    t.feed(0.5, std::vector<double>{0.0});
    EXPECT_EQ(t.refusedSamples(), 1u);
    EXPECT_EQ(t.ring().size(), 1u);

    Trigger bad(2, {.channel = 2});
    EXPECT_FALSE(bad.error().empty());
    EXPECT_EQ(bad.state(), Trigger::State::Stopped);
    EXPECT_FALSE(bad.feed(0, std::vector<double>{1, 2}));
    EXPECT_FALSE(Trigger::validate({.frameLength = 1}, 1).empty());
    EXPECT_FALSE(Trigger::validate({.kind = TriggerKind::Edge, .minStep = 0}, 1).empty());
    EXPECT_FALSE(Trigger::validate({.mode = TriggerMode::Auto, .autoTimeout_s = 0}, 1).empty());
    EXPECT_TRUE(Trigger::validate({}, 1).empty());
}
