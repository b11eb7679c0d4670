// The BDS5 serial port's link layer, before the line discipline: autobaud at power-up (L5292-5318),
// multidrop addressing with '\' + ID, '\' alone and '\*' broadcast (L5416-5469, L10013-10038), and the
// serial watchdog (WATCH/WTIME, L5328-5342).
#pragma once

#include "drive_core/drive.h"

#include <optional>
#include <string>

namespace drive_core::bds5 {

class Bds5Port {
public:
    // Power-up: axisId set for multidrop (ADDR 48-57 or 65-90), autobaud when the drive must measure the
    // host's rate first. A multidrop drive powers up asleep.
    void powerUp(std::optional<char> axisId, bool autobaud, Microseconds now);
    // ADDR changed while running: "immediately puts the drive in multidrop mode" (L5424), asleep until
    // '\' + the new ID wakes it (L5449-5451); ADDR 0 makes it single-drop and awake. No change, no effect.
    void setAxis(std::optional<char> axisId);

    enum class Verdict {
        Process,      // give the byte to the line discipline
        Drop,         // swallowed by the link layer
        Woken,        // '\' + our ID: the drive answers with CR LF and its prompt
        AutobaudDone, // the first CR measured the rate: sign on now
    };
    Verdict accept(char c, Microseconds now);

    bool autobauding() const { return m_autobaud; }
    // Every byte but CR goes to the line discipline unchanged (single-drop, not autobauding): the drive
    // may take a run of typed characters at once.
    bool passesText() const { return !m_autobaud && !m_axis; }
    // Whether what the drive sends reaches the wire: not while asleep or addressed by broadcast.
    bool transmits() const { return !m_asleep && !m_broadcast && !m_autobaud; }
    std::optional<char> axisId() const { return m_axis; }
    // The prompt as this drive shows it: single-drop "-->" "==>" "s-->" "e->" ..., multidrop "A->" "A=>"
    // "As>" "Ae>" ... (the ID first, the mode character slid right, '>' last; L10015).
    std::string prompt(const std::string& singleDrop) const;

    // True once each time WTIME ms pass with WATCH on and no CR received (ERR 105).
    bool watchdogExpired(Microseconds now, bool watchOn, int wtimeMs);

private:
    std::optional<char> m_axis;
    bool m_asleep = false;
    bool m_broadcast = false;
    bool m_autobaud = false;
    bool m_afterBackslash = false;
    Microseconds m_lastCr{0};
};

} // namespace drive_core::bds5
