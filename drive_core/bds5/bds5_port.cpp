// BDS5 serial link layer.
#include "bds5_port.h"

namespace drive_core::bds5 {

void Bds5Port::powerUp(std::optional<char> axisId, bool autobaud, Microseconds now) {
    m_axis = axisId;
    m_asleep = axisId.has_value(); // power-up in multidrop = asleep (L5424-5449)
    m_broadcast = false;
    m_autobaud = autobaud;
    m_afterBackslash = false;
    m_lastCr = now;
}

void Bds5Port::setAxis(std::optional<char> axisId) {
    if (axisId == m_axis) return;
    m_axis = axisId;
    m_broadcast = m_afterBackslash = false;
    // A new ID puts the drive in multidrop mode asleep: it "then waits for the \A" before it answers
    // (L5449-5451), so ADDR=66 gets no prompt until "\B". ADDR 0 is single-drop, always awake.
    m_asleep = axisId.has_value();
}

Bds5Port::Verdict Bds5Port::accept(char c, Microseconds now) {
    if (c == '\r') m_lastCr = now; // only CRs feed the watchdog, valid or not (L5332)
    if (m_autobaud) {
        // The seed: the host sends several CRs and the drive measures them. A simulation has no bit
        // timing to measure, so the first CR completes autobaud at the configured rate (chosen).
        if (c != '\r') return Verdict::Drop;
        m_autobaud = false;
        return Verdict::AutobaudDone;
    }
    if (!m_axis) return Verdict::Process;
    if (m_afterBackslash) { // '\' + ID wakes that axis; any other character after '\' sleeps every axis
        m_afterBackslash = false;
        // '\*' is the Axis Broadcast All (L10017-10019): every axis executes, none transmits (L5467-5469).
        // A '*' anywhere else is the character it is (6*7 multiplies).
        if (c == '*') {
            m_broadcast = true;
            m_asleep = false;
            return Verdict::Drop;
        }
        if (c == '\\') { // "\\": the first puts every axis to sleep, the second starts a new attention
            m_asleep = true;
            m_broadcast = false;
            m_afterBackslash = true;
            return Verdict::Drop;
        }
        const bool mine = c == *m_axis;
        m_asleep = !mine;
        m_broadcast = false;
        return mine ? Verdict::Woken : Verdict::Drop;
    }
    if (c == '\\') {
        m_afterBackslash = true;
        return Verdict::Drop;
    }
    return m_asleep ? Verdict::Drop : Verdict::Process;
}

std::string Bds5Port::prompt(const std::string& singleDrop) const {
    if (!m_axis || singleDrop.empty()) return singleDrop;
    char mode = singleDrop[0]; // '-' interactive, '=' monitor, 's' single-step, 'e' 'l' 'i' 'f' 'c'
    return std::string(1, *m_axis) + mode + '>';
}

bool Bds5Port::watchdogExpired(Microseconds now, bool watchOn, int wtimeMs) {
    if (!watchOn || wtimeMs <= 0) {
        m_lastCr = now;
        return false;
    }
    if (now - m_lastCr < std::chrono::milliseconds(wtimeMs)) return false;
    m_lastCr = now; // fires once a period of silence, not every millisecond after
    return true;
}

} // namespace drive_core::bds5
