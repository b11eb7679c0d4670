// The median of a benchmark's repeated stretches: this machine's speed wanders (a shared host), and one
// stretch of a fraction of a second can come out a third faster or slower than the next. The median is the
// figure a bench prints as its result; every stretch is printed too.
#pragma once

#include <algorithm>
#include <vector>

// measure(k) runs stretch k (0 ... runs - 1) and returns its figure.
template <typename Measure>
double medianOf(int runs, Measure measure) {
    std::vector<double> figures;
    for (int k = 0; k < runs; ++k) figures.push_back(measure(k));
    std::sort(figures.begin(), figures.end());
    return figures[figures.size() / 2];
}
