// The series store keeps samples in time order, drops the oldest at capacity, and answers ranges.
#include "scope/series_store.h"

#include <gtest/gtest.h>

using scope::SeriesStore;

TEST(SeriesStore, ChannelsAreFoundByNameAndKeepTheirUnit) {
    SeriesStore store;
    const auto vfb = store.addChannel("VFB", "RPM");
    EXPECT_EQ(store.addChannel("VFB", "RPM"), vfb);
    EXPECT_EQ(store.find("VFB"), vfb);
    EXPECT_FALSE(store.find("ICMD"));
    EXPECT_EQ(store.channel(vfb).unit, "RPM");
}

TEST(SeriesStore, RefusesSamplesOutOfTimeOrder) {
    SeriesStore store;
    const auto c = store.addChannel("PE", "counts");
    EXPECT_TRUE(store.append(c, {0.001, 5}));
    EXPECT_TRUE(store.append(c, {0.002, 7}));
    EXPECT_FALSE(store.append(c, {0.0015, 9}));
    EXPECT_EQ(store.channel(c).samples.size(), 2u);
}

TEST(SeriesStore, DropsTheOldestAtCapacity) {
    SeriesStore store(3);
    const auto c = store.addChannel("X", "");
    for (int i = 0; i < 5; ++i) store.append(c, {double(i), double(i * 10)});
    ASSERT_EQ(store.channel(c).samples.size(), 3u);
    EXPECT_EQ(store.channel(c).samples.front().value, 20);
}

TEST(SeriesStore, ValueRangeOfAWindow) {
    SeriesStore store;
    const auto c = store.addChannel("VFB", "RPM");
    const double values[] = {0, 100, -50, 300, 20};
    for (int i = 0; i < 5; ++i) store.append(c, {double(i), values[i]});
    const auto r = store.valueRange(c, 1, 2);
    ASSERT_TRUE(r);
    EXPECT_EQ(r->minimum, -50);
    EXPECT_EQ(r->maximum, 100);
    EXPECT_FALSE(store.valueRange(c, 10, 20));
}

TEST(SeriesStore, DropBeforeKeepsTheRollingWindow) {
    scope::SeriesStore store;
    const std::size_t pfb = store.addChannel("PFB", "POS");
    for (int i = 0; i < 10; ++i) store.append(pfb, {double(i), double(10 * i)});
    store.dropBefore(6.5);
    ASSERT_EQ(store.channel(pfb).samples.size(), 3u);
    EXPECT_EQ(store.channel(pfb).samples.front().value, 70);
}
