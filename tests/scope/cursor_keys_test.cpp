// The A/B cursors from the keyboard: C places them in view, Space picks the one that moves, Shift+arrows
// step it a sample, Ctrl+Shift+arrows a tenth of the view, and no key takes a cursor out of view.
#include "scope/cursor_keys.h"

#include <gtest/gtest.h>

using scope::applyCursorKey;
using scope::CursorKey;
using scope::CursorPair;
using scope::CursorView;

TEST(CursorKeys, PlaceSetsBothCursorsInsideTheView) {
    const CursorPair c = applyCursorKey({}, CursorKey::Place, {0.2, 0.6, 0.001});
    EXPECT_DOUBLE_EQ(c.a_s, 0.3);
    EXPECT_DOUBLE_EQ(c.b_s, 0.5);
    EXPECT_EQ(c.active, 0);
}

TEST(CursorKeys, StepsMoveOnlyTheActiveCursorBySamples) {
    const CursorView view{0, 1, 0.001};
    CursorPair c{0.25, 0.75, 0};
    c = applyCursorKey(c, CursorKey::StepForward, view);
    c = applyCursorKey(c, CursorKey::StepForward, view);
    EXPECT_NEAR(c.a_s, 0.252, 1e-12);
    EXPECT_DOUBLE_EQ(c.b_s, 0.75);
    c = applyCursorKey(c, CursorKey::SwitchActive, view);
    EXPECT_EQ(c.active, 1);
    c = applyCursorKey(c, CursorKey::JumpBack, view);
    EXPECT_NEAR(c.b_s, 0.65, 1e-12);
    EXPECT_NEAR(c.a_s, 0.252, 1e-12);
}

TEST(CursorKeys, LiveDataStepAFiveHundredthOfTheView) {
    CursorPair c{1.0, 2.0, 1};
    c = applyCursorKey(c, CursorKey::StepBack, {0, 5, 0});
    EXPECT_NEAR(c.b_s, 2.0 - 5.0 / 500, 1e-12);
}

TEST(CursorKeys, ACursorStopsAtTheEdgeOfTheView) {
    CursorPair c{0.95, 0.5, 0};
    for (int i = 0; i < 5; ++i) c = applyCursorKey(c, CursorKey::JumpForward, {0, 1, 0.001});
    EXPECT_DOUBLE_EQ(c.a_s, 1.0);
    for (int i = 0; i < 30; ++i) c = applyCursorKey(c, CursorKey::JumpBack, {0, 1, 0.001});
    EXPECT_DOUBLE_EQ(c.a_s, 0.0);
}
