// MathChannelList: the Scope dock's math channels as the user defined them (an operation and operand names),
// applied to every capture the dock shows, so a math channel stays, recomputed, when the next capture of the
// same channels arrives. Widget-free; GUI thread only.
// - Each is evaluated in turn on the capture with the earlier ones added: one may use another.
// - One whose operands a capture lacks is kept but not shown (skipped, with why); it comes back with the
//   next capture that has them. So is one beyond the plot's channel limit.
#pragma once

#include "scope/capture.h"
#include "scope/math_channel.h"

#include <QString>
#include <QStringList>

#include <cstddef>
#include <vector>

namespace app {

class MathChannelList {
public:
    struct Applied {
        scope::Capture capture; // the capture's channels, then the math channels shown
        QStringList skipped;    // "d/dt(VFB): no channel VFB in this capture", one a channel not shown
    };

    // spec.name must be set (MathChannelDialog sets it to the name it showed the user).
    void add(const scope::MathChannelSpec& spec) { m_specs.push_back(spec); }
    bool remove(const QString& name);
    void clear() { m_specs.clear(); }
    bool contains(const QString& name) const;
    const std::vector<scope::MathChannelSpec>& specs() const { return m_specs; }
    bool isEmpty() const { return m_specs.empty(); }

    // raw with the math channels appended, at most maxChannels channels in all.
    Applied apply(const scope::Capture& raw, std::size_t maxChannels) const;

private:
    std::vector<scope::MathChannelSpec> m_specs;
};

} // namespace app
