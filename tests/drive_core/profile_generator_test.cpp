// The shared profile generator: exact landings, buffering, segments, jogs and stops.
#include "drive_core/motion/profile_generator.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace drive_core::motion;

namespace {
MoveRequest move(double target, double v, double a, double d) {
    return {MoveKind::Position, target, v, a, d};
}
void run(ProfileGenerator& g, double seconds, double dt = 0.001) {
    for (double t = 0; t < seconds; t += dt) g.step(dt);
}
} // namespace

TEST(ProfileGenerator, EveryMoveLandsExactlyOnItsEndPosition) {
    std::mt19937 random(20261122); // fixed seed: the same 500 moves every run
    std::uniform_real_distribution<double> target(-1e6, 1e6), speed(10, 2e5), rate(100, 1e7), step(1e-4, 5e-3);
    for (int i = 0; i < 500; ++i) {
        ProfileGenerator g;
        const double from = std::round(target(random));
        g.setPosition(from);
        const double to = std::round(target(random));
        ASSERT_TRUE(g.push(move(to, speed(random), rate(random), rate(random))));
        const double dt = step(random);
        for (int n = 0; n < 10'000'000 && g.moving(); ++n) g.step(dt);
        ASSERT_FALSE(g.moving());
        EXPECT_EQ(g.position(), to) << "move " << i << " from " << from;
        EXPECT_EQ(g.velocity(), 0);
    }
}

TEST(ProfileGenerator, TrapezoidHasThreeSegmentsAtTheRightTimes) {
    // 4000 counts at 10000 c/s with 100000 c/s²: 0.1 s ramps covering 500 counts each, 0.3 s traverse.
    const auto s = ProfileGenerator::plan(0, move(4000, 10000, 1e5, 1e5));
    ASSERT_EQ(s.size(), 3u);
    EXPECT_NEAR(s[0].duration_s, 0.1, 1e-12);
    EXPECT_NEAR(s[1].duration_s, 0.3, 1e-12);
    EXPECT_NEAR(s[2].duration_s, 0.1, 1e-12);
    ProfileGenerator g;
    g.push(move(4000, 10000, 1e5, 1e5));
    run(g, 0.05);
    EXPECT_EQ(g.segment(), 1);
    run(g, 0.1);
    EXPECT_EQ(g.segment(), 2);
    EXPECT_NEAR(g.velocity(), 10000, 1e-6);
    run(g, 0.3);
    EXPECT_EQ(g.segment(), 3);
}

TEST(ProfileGenerator, ShortMoveIsTriangularWithAShortTraverse) {
    const auto s = ProfileGenerator::plan(0, move(100, 1e6, 1e5, 1e5));
    ASSERT_EQ(s.size(), 3u);
    EXPECT_LT(s[1].duration_s, 0.005);
    const double peak = s[0].duration_s * 1e5;
    const double covered = peak * s[0].duration_s / 2 + peak * s[1].duration_s + peak * s[2].duration_s / 2;
    EXPECT_NEAR(covered, 100, 1e-9);
}

TEST(ProfileGenerator, OneExecutingAndOnePending) {
    ProfileGenerator g;
    const auto first = g.push(move(1000, 5000, 1e5, 1e5));
    const auto second = g.push(move(2000, 5000, 1e5, 1e5));
    ASSERT_TRUE(first && second);
    EXPECT_TRUE(g.full());
    EXPECT_FALSE(g.push(move(3000, 5000, 1e5, 1e5))) << "a third move must wait";
    EXPECT_EQ(g.finalPosition(), 2000);
    EXPECT_FALSE(g.reached(*second, 1));
    run(g, 0.3);
    EXPECT_EQ(g.activeId(), *second);
    EXPECT_TRUE(g.reached(*first, 3));
    run(g, 1);
    EXPECT_EQ(g.position(), 2000);
    EXPECT_TRUE(g.reached(*second, 0));
}

TEST(ProfileGenerator, JogRampsToSpeedAndReversesAtTheSmallerRate) {
    ProfileGenerator g;
    g.jog({MoveKind::Jog, 0, 1000, 1e4, 5e3});
    run(g, 0.1 + 1e-9);
    EXPECT_NEAR(g.velocity(), 1000, 1e-6);
    EXPECT_EQ(g.segment(), 2);
    g.jog({MoveKind::Jog, 0, -1000, 1e4, 5e3});
    run(g, 0.2);
    EXPECT_NEAR(g.velocity(), 0, 1e-6) << "2000 c/s of change at 5000 c/s² takes 0.4 s";
    run(g, 0.2 + 1e-9);
    EXPECT_NEAR(g.velocity(), -1000, 1e-6);
}

TEST(ProfileGenerator, StopDeceleratesAndCancelsEverything) {
    ProfileGenerator g;
    g.push(move(100000, 10000, 1e5, 1e5));
    g.push(move(0, 10000, 1e5, 1e5));
    run(g, 0.2);
    g.stop(1e6);
    run(g, 0.02);
    EXPECT_FALSE(g.moving());
    EXPECT_EQ(g.velocity(), 0);
    EXPECT_LT(g.position(), 100000);
}
