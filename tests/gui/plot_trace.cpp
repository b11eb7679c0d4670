// traceIn: colour arithmetic over one rectangle of a screenshot.
#include "plot_trace.h"

#include <QHash>

#include <algorithm>
#include <cstdlib>

namespace {

constexpr int kMinSaturation = 60; // max(r,g,b) - min(r,g,b): grey, black and white stay below it
constexpr int kMinContrast = 60;   // the largest channel difference from the background

int saturation(QRgb c) {
    const int r = qRed(c), g = qGreen(c), b = qBlue(c);
    return std::max({r, g, b}) - std::min({r, g, b});
}

int contrast(QRgb a, QRgb b) {
    return std::max({std::abs(qRed(a) - qRed(b)), std::abs(qGreen(a) - qGreen(b)), std::abs(qBlue(a) - qBlue(b))});
}

QRgb mostCommon(const QImage& image, const QRect& area) {
    QHash<QRgb, int> counts;
    for (int y = area.top(); y <= area.bottom(); ++y) {
        const auto* line = reinterpret_cast<const QRgb*>(image.constScanLine(y));
        for (int x = area.left(); x <= area.right(); ++x) ++counts[line[x] | 0xff000000u];
    }
    QRgb best = 0;
    int most = -1;
    for (auto it = counts.cbegin(); it != counts.cend(); ++it)
        if (it.value() > most) best = it.key(), most = it.value();
    return best;
}

} // namespace

TraceCount traceIn(const QImage& image, const QRect& wanted) {
    const QRect area = wanted.intersected(image.rect());
    TraceCount count;
    if (area.isEmpty()) return count;
    const QRgb background = mostCommon(image, area);
    for (int x = area.left(); x <= area.right(); ++x) {
        int inColumn = 0;
        for (int y = area.top(); y <= area.bottom(); ++y) {
            const QRgb c = reinterpret_cast<const QRgb*>(image.constScanLine(y))[x];
            inColumn += saturation(c) >= kMinSaturation && contrast(c, background) >= kMinContrast;
        }
        count.pixels += inColumn;
        count.columns += inColumn > 0;
    }
    return count;
}
