// WatchSource: the parts every family's source shares.
#include "watch_source.h"

namespace app {

std::optional<WatchSource::Choice> WatchSource::choice(const QString& name) const {
    for (const Choice& c : choices())
        if (c.name.compare(name, Qt::CaseInsensitive) == 0) return c;
    return std::nullopt;
}

std::optional<double> WatchSource::number(const QString& word) {
    if (word.compare(QLatin1String("ON"), Qt::CaseInsensitive) == 0) return 1;
    if (word.compare(QLatin1String("OFF"), Qt::CaseInsensitive) == 0) return 0;
    bool ok = false;
    const double v = word.trimmed().toDouble(&ok);
    return ok ? std::optional<double>(v) : std::nullopt;
}

} // namespace app
