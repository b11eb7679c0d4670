// The zoom-level column cache: grid columns hold their true min and max (against a brute-force scan of random
// data), and what a cache reuses while panning and zooming is exactly what a fresh one would compute.
#include "scope/column_cache.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

using scope::ColumnCache;
using scope::Sample;
using scope::SeriesStore;

namespace {

// Irregular times and a random walk with spikes; seeded, so a failure reproduces.
void appendRandom(SeriesStore& store, std::size_t samples, std::uint32_t seed) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> dt(0.0002, 0.002);
    std::normal_distribution<double> step(0, 3);
    double t = store.channel(0).samples.empty() ? 0.25 : store.channel(0).samples.back().time_s;
    double v = 0;
    for (std::size_t i = 0; i < samples; ++i) {
        t += dt(random);
        v += step(random);
        store.append(0, {t, random() % 300 == 0 ? v + 100 * step(random) : v});
    }
}

// The grid column a time falls in, by the definition: m * width <= t < (m + 1) * width, each edge one product.
std::int64_t gridIndex(double t, double width) {
    auto m = std::int64_t(std::floor(t / width));
    while (double(m) * width > t) --m;
    while (double(m + 1) * width <= t) ++m;
    return m;
}

} // namespace

TEST(GridColumns, EachHoldsItsTrueMinAndMax) {
    SeriesStore store;
    store.addChannel("VFB", "RPM");
    appendRandom(store, 50'000, 17);
    const auto& s = store.channel(0).samples;
    std::mt19937 random(5);
    for (int k = 0; k < 10; ++k) {
        const double width = std::exp2(std::uniform_real_distribution<double>(-12, 0)(random));
        const auto first = gridIndex(s[random() % s.size()].time_s, width) - 3;
        std::vector<scope::Column> columns(1 + random() % 700);
        store.gridColumns(0, width, first, columns);
        std::vector<std::size_t> count(columns.size(), 0); // brute force: every sample to its column
        std::vector<double> lo(columns.size(), INFINITY);
        std::vector<double> hi(columns.size(), -INFINITY);
        for (const Sample& x : s) {
            const std::int64_t j = gridIndex(x.time_s, width) - first;
            if (j < 0 || j >= std::int64_t(columns.size())) continue;
            ++count[std::size_t(j)];
            lo[std::size_t(j)] = std::min(lo[std::size_t(j)], x.value);
            hi[std::size_t(j)] = std::max(hi[std::size_t(j)], x.value);
        }
        for (std::size_t j = 0; j < columns.size(); ++j) {
            ASSERT_EQ(columns[j].last - columns[j].first, count[j]) << "width " << width << ", column " << j;
            if (count[j] == 0) continue;
            EXPECT_EQ(columns[j].range.minimum, lo[j]) << "width " << width << ", column " << j;
            EXPECT_EQ(columns[j].range.maximum, hi[j]) << "width " << width << ", column " << j;
        }
    }
}

TEST(ColumnCache, LevelsAreQuarterOctavesNoWiderThanAPixel) {
    for (const double span : {1e-3, 0.77, 1.0, 1000.0, 123456.0}) {
        const double width = ColumnCache::levelWidth(span, 1280);
        EXPECT_LE(width, span / 1280);
        EXPECT_GT(width, span / 1280 / std::exp2(0.25));
        const double quarterOctaves = 4 * std::log2(width);
        EXPECT_NEAR(quarterOctaves, std::round(quarterOctaves), 1e-9);
    }
    EXPECT_EQ(ColumnCache::levelWidth(0, 1280), 0);
}

// What the user sees must not depend on the path the view took: after any pans and zooms, a cache answers
// exactly (bit for bit) what a fresh one does, and each grid column shows its true min and max.
TEST(ColumnCache, PanningAndZoomingGiveWhatAFreshCacheGives) {
    SeriesStore store;
    store.addChannel("VFB", "RPM");
    appendRandom(store, 200'000, 23);
    const auto& s = store.channel(0).samples;
    ColumnCache kept;
    std::vector<Sample> got;
    std::vector<Sample> want;
    std::mt19937 random(29);
    double from = s.front().time_s;
    double span = s.back().time_s - s.front().time_s;
    constexpr std::size_t kPixels = 900;
    for (int k = 0; k < 60; ++k) {
        switch (random() % 4) {
        case 0: span *= 0.85; break;
        case 1: span /= 0.85; break;
        default: from += span * std::uniform_real_distribution<double>(-0.2, 0.2)(random); break;
        }
        SCOPED_TRACE(testing::Message() << "step " << k << ": [" << from << ", " << from + span << "]");
        const bool dense = kept.points(store, 0, from, from + span, kPixels, got);
        ColumnCache fresh;
        EXPECT_EQ(fresh.points(store, 0, from, from + span, kPixels, want), dense);
        ASSERT_EQ(got.size(), want.size());
        for (std::size_t i = 0; i < got.size(); ++i) {
            EXPECT_EQ(got[i].time_s, want[i].time_s) << i;
            EXPECT_EQ(got[i].value, want[i].value) << i;
        }
        if (!dense) continue;
        const double width = ColumnCache::levelWidth(span, kPixels);
        std::vector<scope::Column> columns(std::size_t(gridIndex(from + span, width) - gridIndex(from, width) + 1));
        store.gridColumns(0, width, gridIndex(from, width), columns);
        for (const scope::Column& c : columns) {
            if (c.empty()) continue;
            const auto shown = [&](double v) {
                return std::any_of(got.begin(), got.end(), [&](const Sample& p) {
                    return p.value == v && p.time_s >= s[c.first].time_s && p.time_s <= s[c.last - 1].time_s;
                });
            };
            EXPECT_TRUE(shown(c.range.minimum)) << "a column's minimum is not drawn";
            EXPECT_TRUE(shown(c.range.maximum)) << "a column's maximum is not drawn";
        }
    }
}

// New samples (a live trace) change the store's revision: nothing computed before is reused.
TEST(ColumnCache, NewSamplesAreNotHiddenByWhatWasKept) {
    SeriesStore store;
    store.addChannel("PFB", "POS");
    appendRandom(store, 100'000, 31);
    ColumnCache kept;
    std::vector<Sample> got;
    std::vector<Sample> want;
    const double from = store.channel(0).samples.front().time_s;
    const double to = store.channel(0).samples.back().time_s + 30; // room for what comes
    ASSERT_TRUE(kept.points(store, 0, from, to, 640, got));
    appendRandom(store, 20'000, 37);
    kept.points(store, 0, from, to, 640, got);
    ColumnCache().points(store, 0, from, to, 640, want);
    ASSERT_EQ(got.size(), want.size());
    EXPECT_TRUE(std::equal(got.begin(), got.end(), want.begin(), [](const Sample& a, const Sample& b) {
        return a.time_s == b.time_s && a.value == b.value;
    }));
    // A copy of the store is another store: its revision never matches what the cache holds.
    const SeriesStore copy = store;
    EXPECT_NE(copy.revision(), store.revision());
}

// Zoomed in to at most two samples a pixel, the cache hands over the samples themselves, as decimate does.
TEST(ColumnCache, SparseRangesAreTheSamples) {
    SeriesStore store;
    store.addChannel("VFB", "RPM");
    appendRandom(store, 10'000, 41);
    const auto& s = store.channel(0).samples;
    std::vector<Sample> got;
    ColumnCache cache;
    EXPECT_FALSE(cache.points(store, 0, s[100].time_s, s[1100].time_s, 800, got));
    ASSERT_EQ(got.size(), 1003u); // the 1001 samples and a neighbour each side
    EXPECT_EQ(got.front().time_s, s[99].time_s);
    EXPECT_EQ(got.back().value, s[1101].value);
}
