// unmetExpectations: each check looks for its fact; `plot` then counts trace pixels inside each plot area.
#include "shot_expectations.h"

#include "plot_trace.h"

#include <QRegularExpression>

#include <map>

namespace {

constexpr QSize kMinPlotArea{100, 60}; // smaller, a plot squeezed by its layout shows nothing to read
constexpr int kMinTracePixels = 200;
constexpr int kMinTraceColumns = 40; // a trace runs across the plot; a cursor or marker line is a column or two

struct Fact {
    QString kind;
    QString text;
};

QList<Fact> parse(const QStringList& lines) {
    QList<Fact> facts;
    for (const QString& line : lines) {
        const qsizetype colon = line.indexOf(QLatin1String(": "));
        if (colon > 0) facts.append({line.left(colon), line.mid(colon + 2)});
    }
    return facts;
}

bool any(const QList<Fact>& facts, const std::function<bool(const Fact&)>& holds) {
    return std::any_of(facts.cbegin(), facts.cend(), holds);
}

// "plot: X,Y WxH" in the PNG's pixels.
QList<QRect> plotAreas(const QList<Fact>& facts) {
    static const QRegularExpression area(QStringLiteral("^(\\d+),(\\d+) (\\d+)x(\\d+)$"));
    QList<QRect> areas;
    for (const Fact& fact : facts) {
        const QRegularExpressionMatch m = area.match(fact.text);
        if (fact.kind == QLatin1String("plot") && m.hasMatch())
            areas.append(
                QRect(m.captured(1).toInt(), m.captured(2).toInt(), m.captured(3).toInt(), m.captured(4).toInt()));
    }
    return areas;
}

QStringList unmetPlot(const QList<Fact>& facts, const QImage& image) {
    const QList<QRect> areas = plotAreas(facts);
    if (areas.isEmpty()) return {QStringLiteral("no plot area in its facts")};
    QStringList unmet;
    for (const QRect& area : areas) {
        const QString where =
            QStringLiteral("%1,%2 %3x%4").arg(area.x()).arg(area.y()).arg(area.width()).arg(area.height());
        if (area.width() < kMinPlotArea.width() || area.height() < kMinPlotArea.height()) {
            unmet << QStringLiteral("the plot area %1 is too small to read, expected %2x%3 or more")
                         .arg(where)
                         .arg(kMinPlotArea.width())
                         .arg(kMinPlotArea.height());
            continue;
        }
        const TraceCount trace = traceIn(image, area);
        if (trace.pixels < kMinTracePixels || trace.columns < kMinTraceColumns)
            unmet << QStringLiteral("the plot area %1 shows no trace: %2 trace pixels in %3 columns, "
                                    "expected %4 in %5 or more")
                         .arg(where)
                         .arg(trace.pixels)
                         .arg(trace.columns)
                         .arg(kMinTracePixels)
                         .arg(kMinTraceColumns);
    }
    return unmet;
}

// A fact check: which facts it reads (all when empty), whether the text must equal or contain X, how it is said.
struct FactCheck {
    QLatin1String fact;
    bool exact;
    QString says;
};
const std::map<QString, FactCheck> kFactChecks{
    {QStringLiteral("text"), {QLatin1String(), false, QStringLiteral("fact contains \"%1\"")}},
    {QStringLiteral("dock"), {QLatin1String("dock"), true, QStringLiteral("visible dock \"%1\"")}},
    {QStringLiteral("title"), {QLatin1String("window"), false, QStringLiteral("window title contains \"%1\"")}},
    {QStringLiteral("status"), {QLatin1String("status"), false, QStringLiteral("status message contains \"%1\"")}},
};

} // namespace

QStringList unmetExpectations(const QStringList& checks, const QStringList& lines, const QImage& image) {
    const QList<Fact> facts = parse(lines);
    QStringList unmet;
    for (const QString& check : checks) {
        if (check == QLatin1String("plot")) {
            unmet << unmetPlot(facts, image);
            continue;
        }
        const bool refused = check.startsWith(QLatin1Char('!'));
        const QString key = check.section(QLatin1Char('='), 0, 0).mid(refused ? 1 : 0);
        const QString wanted = check.section(QLatin1Char('='), 1);
        const auto known = kFactChecks.find(key);
        if (known == kFactChecks.cend() || !check.contains(QLatin1Char('='))) {
            unmet << QStringLiteral("unknown check \"%1\"").arg(check);
            continue;
        }
        const FactCheck& kind = known->second;
        const bool found = any(facts, [&](const Fact& f) {
            return (kind.fact.isEmpty() || f.kind == kind.fact) &&
                   (kind.exact ? f.text == wanted : f.text.contains(wanted));
        });
        if (found == refused)
            unmet << (refused ? QStringLiteral("shows what it must not: %1") : QStringLiteral("no %1"))
                         .arg(kind.says.arg(wanted));
    }
    return unmet;
}
