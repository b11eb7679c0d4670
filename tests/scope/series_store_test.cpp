// The series store keeps samples in time order, drops the oldest at capacity, and answers ranges; its
// decimation per pixel column keeps every column's true min and max (against a brute-force scan of random
// data, at ranges that do and do not line up with the min/max pyramid's blocks).
#include "scope/series_store.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

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

namespace {

struct Brute {
    std::size_t first = 0;
    std::size_t last = 0;
    double minimum = 0;
    double maximum = 0;
};

// The columns as the header defines them, by a scan of every sample (each one placed by the edges).
std::vector<Brute> bruteColumns(const std::deque<scope::Sample>& s, double from, double to, std::size_t count) {
    std::vector<Brute> out(count);
    std::vector<double> edges; // edge(1) .. edge(count - 1): column j ends where edge(j + 1) starts
    for (std::size_t j = 1; j < count; ++j) edges.push_back(from + (to - from) * double(j) / double(count));
    std::vector<bool> any(count, false);
    for (std::size_t i = 0; i < s.size(); ++i) {
        const double t = s[i].time_s;
        if (t < from || t > to) continue;
        const auto j = std::size_t(std::upper_bound(edges.begin(), edges.end(), t) - edges.begin());
        if (!any[j]) out[j] = {i, i, s[i].value, s[i].value};
        any[j] = true;
        out[j].last = i + 1;
        out[j].minimum = std::min(out[j].minimum, s[i].value);
        out[j].maximum = std::max(out[j].maximum, s[i].value);
    }
    return out;
}

// Irregular times (as polls arrive) and a random walk with spikes; seeded, so a failure reproduces.
SeriesStore randomStore(std::size_t samples, std::uint32_t seed, std::size_t capacity = 1'000'000) {
    SeriesStore store(capacity);
    const auto c = store.addChannel("VFB", "RPM");
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> dt(0.0001, 0.003);
    std::normal_distribution<double> step(0, 5);
    std::uniform_int_distribution<int> spike(0, 200);
    double t = 0.5;
    double v = 0;
    for (std::size_t i = 0; i < samples; ++i) {
        t += dt(random);
        v += step(random);
        store.append(c, {t, spike(random) == 0 ? v + 500 * step(random) : v});
    }
    return store;
}

void expectColumnsMatch(const SeriesStore& store, double from, double to, std::size_t count) {
    SCOPED_TRACE(testing::Message() << "[" << from << ", " << to << "] in " << count << " columns");
    const auto& samples = store.channel(0).samples;
    const auto got = store.columns(0, from, to, count);
    const auto want = bruteColumns(samples, from, to, count);
    ASSERT_EQ(got.size(), count);
    for (std::size_t j = 0; j < count; ++j) {
        const bool wantEmpty = want[j].first == want[j].last;
        ASSERT_EQ(got[j].empty(), wantEmpty) << "column " << j;
        if (wantEmpty) continue;
        EXPECT_EQ(got[j].first, want[j].first) << "column " << j;
        EXPECT_EQ(got[j].last, want[j].last) << "column " << j;
        EXPECT_EQ(got[j].range.minimum, want[j].minimum) << "column " << j;
        EXPECT_EQ(got[j].range.maximum, want[j].maximum) << "column " << j;
    }
}

} // namespace

TEST(SeriesStoreDecimation, EveryColumnKeepsItsTrueMinAndMax) {
    const SeriesStore store = randomStore(60'000, 20240611);
    const auto& s = store.channel(0).samples;
    const double first = s.front().time_s;
    const double last = s.back().time_s;
    expectColumnsMatch(store, first, last, 1280);                                     // the whole record
    expectColumnsMatch(store, first, last, 1);                                        // one column: the whole range
    expectColumnsMatch(store, first - 3, last + 3, 777);                              // wider than the data
    expectColumnsMatch(store, s[1234].time_s, s[41'017].time_s, 1000);                // ends exactly on samples
    expectColumnsMatch(store, s[17].time_s + 1e-5, s[17 + 16 * 64].time_s - 1e-5, 3); // across few blocks
    std::mt19937 random(7);
    for (int k = 0; k < 12; ++k) { // zoomed in and out, never lined up with the pyramid's blocks
        std::uniform_real_distribution<double> at(first - 1, last + 1);
        double a = at(random);
        double b = at(random);
        if (a > b) std::swap(a, b);
        expectColumnsMatch(store, a, b, std::size_t(1) + random() % 1500);
    }
    expectColumnsMatch(store, last + 1, last + 2, 100); // after the data: all empty
    expectColumnsMatch(store, first, first, 10);        // zero span: the last column holds t == from
}

// The rolling window drops samples (and pyramid blocks) from the front: what is left still decimates right.
TEST(SeriesStoreDecimation, KeepsMinAndMaxAfterTheOldestDrop) {
    SeriesStore store = randomStore(50'000, 99, 9'001); // capacity: 40,999 samples dropped one by one
    ASSERT_EQ(store.channel(0).samples.size(), 9'001u);
    store.dropBefore(store.channel(0).samples[333].time_s); // and a rolling window's cut
    const auto& s = store.channel(0).samples;
    expectColumnsMatch(store, s.front().time_s, s.back().time_s, 1280);
    expectColumnsMatch(store, s.front().time_s, s.back().time_s, 3); // columns across every pyramid level
    expectColumnsMatch(store, s[5].time_s + 1e-6, s[8000].time_s, 313);
    std::mt19937 random(11);
    for (int k = 0; k < 16; ++k) {
        const std::size_t a = random() % s.size();
        const std::size_t b = a + random() % (s.size() - a);
        expectColumnsMatch(store, s[a].time_s, s[b].time_s, std::size_t(1) + random() % (k % 2 ? 900 : 20));
    }
}

TEST(SeriesStoreDecimation, ValueRangeIsTheBruteForceOne) {
    const SeriesStore store = randomStore(30'000, 5);
    const auto& s = store.channel(0).samples;
    std::mt19937 random(3);
    for (int k = 0; k < 50; ++k) {
        const std::size_t a = random() % s.size();
        const std::size_t b = a + random() % (s.size() - a);
        const auto r = store.valueRange(0, s[a].time_s, s[b].time_s);
        ASSERT_TRUE(r);
        const auto [lo, hi] = std::minmax_element(s.begin() + std::ptrdiff_t(a), s.begin() + std::ptrdiff_t(b + 1),
                                                  [](const auto& x, const auto& y) { return x.value < y.value; });
        EXPECT_EQ(r->minimum, lo->value);
        EXPECT_EQ(r->maximum, hi->value);
    }
}

// What the plot is handed: per column the min and max it would show raw, the neighbours just outside the
// range so the line reaches the edges, time-ordered, and at most two points a column.
TEST(SeriesStoreDecimation, DecimatedPointsDrawEachColumnsMinAndMax) {
    const SeriesStore store = randomStore(200'000, 42);
    const auto& s = store.channel(0).samples;
    std::vector<scope::Sample> points;
    const std::size_t count = 1280;
    for (const auto& [a, b] :
         {std::pair<std::size_t, std::size_t>{0, s.size() - 1}, {1001, 150'003}, {70'000, 74'000}}) {
        const double from = s[a].time_s + 1e-7;
        const double to = s[b].time_s - 1e-7;
        EXPECT_TRUE(store.decimate(0, from, to, count, points));
        ASSERT_LE(points.size(), 2 * count + 2);
        EXPECT_TRUE(std::is_sorted(points.begin(), points.end(),
                                   [](const auto& x, const auto& y) { return x.time_s < y.time_s; }));
        EXPECT_EQ(points.front().time_s, s[a].time_s); // the sample before the range
        EXPECT_EQ(points.back().time_s, s[b].time_s);  // and the one after it
        const auto want = bruteColumns(s, from, to, count);
        const auto shown = bruteColumns(std::deque<scope::Sample>(points.begin(), points.end()), from, to, count);
        for (std::size_t j = 0; j < count; ++j) {
            ASSERT_EQ(want[j].first == want[j].last, shown[j].first == shown[j].last) << "column " << j;
            if (want[j].first == want[j].last) continue;
            EXPECT_EQ(shown[j].minimum, want[j].minimum) << "column " << j;
            EXPECT_EQ(shown[j].maximum, want[j].maximum) << "column " << j;
        }
    }
    // Zoomed in to fewer samples than two a column: the samples themselves, with a neighbour each side.
    EXPECT_FALSE(store.decimate(0, s[500].time_s, s[900].time_s, count, points));
    ASSERT_EQ(points.size(), 403u);
    for (std::size_t i = 0; i < points.size(); ++i) {
        EXPECT_EQ(points[i].time_s, s[499 + i].time_s);
        EXPECT_EQ(points[i].value, s[499 + i].value);
    }
}

// NaN (a .CSV may hold "nan") is a gap in the line, never a column's min or max, even as its first sample.
TEST(SeriesStoreDecimation, NanIsAGapNotAnExtreme) {
    SeriesStore store;
    const auto c = store.addChannel("X", "");
    for (int i = 0; i < 100; ++i) store.append(c, {double(i), i % 10 == 0 ? std::nan("") : double(i % 7)});
    const auto r = store.valueRange(c, 0, 99);
    ASSERT_TRUE(r);
    EXPECT_EQ(r->minimum, 0);
    EXPECT_EQ(r->maximum, 6);
    for (const scope::Column& column : store.columns(c, 0, 99, 3)) {
        EXPECT_EQ(column.range.minimum, 0);
        EXPECT_EQ(column.range.maximum, 6);
    }
}
