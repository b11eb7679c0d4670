// MathChannelList: evaluates the user's math channels, in order, on each capture.
#include "math_channel_list.h"

#include <QObject>

namespace app {

bool MathChannelList::remove(const QString& name) {
    const auto before = m_specs.size();
    std::erase_if(m_specs, [&name](const scope::MathChannelSpec& s) { return QString::fromStdString(s.name) == name; });
    return m_specs.size() != before;
}

bool MathChannelList::contains(const QString& name) const {
    for (const scope::MathChannelSpec& s : m_specs)
        if (QString::fromStdString(s.name) == name) return true;
    return false;
}

MathChannelList::Applied MathChannelList::apply(const scope::Capture& raw, std::size_t maxChannels) const {
    Applied out{raw, {}};
    for (const scope::MathChannelSpec& spec : m_specs) {
        const QString name = QString::fromStdString(spec.name);
        if (out.capture.channels.size() >= maxChannels) {
            out.skipped << QObject::tr("%1: the plot shows at most %2 channels").arg(name).arg(maxChannels);
            continue;
        }
        scope::CaptureMath r = scope::evaluate(out.capture, spec);
        if (!r.ok()) {
            out.skipped << QStringLiteral("%1: %2").arg(name, QString::fromStdString(r.error));
            continue;
        }
        out.capture.channels.push_back(std::move(r.channel));
    }
    return out;
}

} // namespace app
