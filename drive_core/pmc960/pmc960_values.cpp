// MPL value commands: A V D OA OB, the S registers and the TH/TL/TU table entries — a number (or a label)
// and <cr>, checked against the catalog's range with the manual's error code.
#include "pmc960_interpreter.h"

#include <cctype>
#include <cmath>

namespace drive_core::pmc960 {

namespace {
bool isHexDigit(char c) {
    return std::isxdigit(static_cast<unsigned char>(c)) != 0;
}
bool oneOf(const std::string& k, std::initializer_list<std::string_view> names) {
    for (const auto n : names)
        if (k == n) return true;
    return false;
}
} // namespace

bool Pmc960Interpreter::applyValue(const std::string& k, std::int64_t v) {
    Pmc960Registers& reg = m_state.reg;
    auto inRange = [this](std::int64_t value, std::int64_t lo, std::int64_t hi, int code) {
        if (value >= lo && value <= hi) return true;
        fail(code);
        return false;
    };
    if (k == "A") {
        if (!inRange(v, 1, 65535, 0x92)) return false;
        reg.acceleration = v;
    } else if (k == "V") {
        if (!inRange(v, 1, std::int64_t(m_state.units().maximumUserVelocity()), 0x94)) return false;
        if (m_state.units().velocityTooSmall(double(v))) return fail(0x98), false;
        reg.velocity = v;
    } else if (k == "SD") {
        if (!inRange(v, 3, 65535, 0x90)) return false;
        reg.depth = v;
    } else if (k == "SF") { // rounded up to a power of 2, at most 32,767 (digest §11.2 #18)
        if (!inRange(v, 1, 32767, 0x90)) return false;
        reg.followingTrip = v;
        std::int64_t trip = 1;
        while (trip < v) trip <<= 1;
        m_state.motion.setTripPoint(double(std::min<std::int64_t>(trip, 32767)));
    } else if (k == "SM") {
        if (!inRange(v, 0, 3, 0x90)) return false;
        if (v != 0 && !m_state.lines.driveReady) return fail(0xE2), false;
        m_state.motion.setMode(int(v));
    } else if (k == "SP") {
        if (!inRange(v, 0, 0xFF, 0x90)) return false;
        reg.profile = v;
    } else if (k == "ST") {
        if (!inRange(v, 0, 1000, 0x90)) return false;
        reg.torque = v;
    } else if (k == "SV") {
        if (!inRange(v, 1, 100, 0x90)) return false;
        reg.feedrate = v;
    } else if (k == "SW") {
        if (!inRange(v, 0, 1, 0x95)) return false;
        reg.writeEnable = v;
    } else if (k[0] == 'T') {
        if (!writable()) return false;
        if (k == "THA") {
            if (v != 0 && !inRange(v, 4096, 65535, 0x90)) return false;
        } else if (k == "THB") {
            if (!inRange(v, 0, 8, 0x90)) return false;
        } else if (k == "THC" || k == "THR") {
            if (!inRange(v, 0, 0xFF, 0x90)) return false;
        } else if (oneOf(k, {"THL", "THM", "THP", "THS"})) {
            if (!inRange(v, 0, 1, 0x95)) return false;
        } else if (oneOf(k, {"TUB", "TUH", "TUV"})) {
            if (!inRange(v, 1, 65535, 0x90)) return false;
            if (k == "TUV" && double(m_state.table.inUse("TUS")) / 10000.0 * double(v) >= 384000)
                return fail(0xD4), false;
        } else if (k == "TUS") {
            if (double(v) / 10000.0 * double(m_state.table.inUse("TUV")) >= 384000) return fail(0xD4), false;
        }
        m_state.table.set(k, v);
        m_state.applyTable();
    }
    return true;
}

void Pmc960Interpreter::valueArgument(char c, bool first) {
    const std::string k = m_command;
    Pmc960Registers& reg = m_state.reg;
    if (oneOf(k, {"SB", "SE", "SN", "SS", "TF"})) return fail(0xA2); // display only
    if (k == "SI") {                                                 // SI[<bank>]<display> (L1519-1530)
        if (first && isHexDigit(c)) {
            if (m_state.table.inUse("THM") == 0) return fail(0x9A);
            m_label = c;
            return;
        }
        if (m_label != 0 && (c == '?' || c == '!' || c == '&')) {
            m_sink.send(display("SI", c)); // no muxed hardware on the bench: the bank reads as IN15'..IN00'
            return finish();
        }
        return fail(0xA2);
    }
    if (k == "SL") { // SL<F|R><position>[<sign>]<cr> (L1532-1575)
        if (first) {
            const char u = char(std::toupper(static_cast<unsigned char>(c)));
            if (u != 'F' && u != 'R') return fail(0xA2);
            m_label = u;
            return;
        }
        if (m_sign == 0 && collectDigit(c, false)) return;
        if ((c == '+' || c == '-') && m_sign == 0) {
            m_sign = c == '+' ? 1 : -1;
            return;
        }
        if (c != '\r' || !numberGiven()) return fail(0xA2);
        if (number() > 2147483647) return fail(0x93);
        (m_label == 'F' ? reg.limitForward : reg.limitReverse) = (m_sign < 0 ? -1 : 1) * number();
        return finish();
    }
    if (k == "OA") { // OA<value><sign><cr>, 0-2047 = 0-10 V (7.14.1, digest §11.2 #12)
        if (m_sign == 0 && collectDigit(c, false)) return;
        if ((c == '+' || c == '-') && m_sign == 0 && numberGiven()) {
            m_sign = c == '+' ? 1 : -1;
            return;
        }
        if (c != '\r' || !numberGiven()) return fail(0xA2);
        if (number() > 2047) return fail(0x90);
        reg.analogOut = (m_sign < 0 ? -1 : 1) * number();
        return finish();
    }
    if (k == "OB") { // OB<hex>[:<mask>]<cr>: outputs = (outputs & ~mask) | (hex & mask) (L1383-1396)
        if (isHexDigit(c)) {
            std::string& digits = m_colon ? m_fraction : m_digits;
            if (digits.size() >= 4) return fail(0xA2);
            digits += c;
            return;
        }
        if (c == ':' && !m_colon && !m_digits.empty()) {
            m_colon = true;
            return;
        }
        if (c != '\r' || m_digits.empty()) return fail(0xA2);
        const auto value = std::stoll(m_digits, nullptr, 16);
        const auto mask = m_colon && !m_fraction.empty() ? std::stoll(m_fraction, nullptr, 16) : 0xFFFF;
        reg.outputs = (reg.outputs & ~mask) | (value & mask);
        return finish();
    }
    if (k == "THI" || k == "TLB" || k == "TLP" || k == "TLV") {
        if (first) {
            if (k == "THI" && (c < 0x21 || c > 0x5A)) return fail(0xA5); // 21H-5AH (digest §11.2 #19)
            if (k != "THI" && !Pmc960Program::validLabel(c)) return fail(0xC5);
            m_label = c;
            return;
        }
        if (c != '\r') return fail(0xA2);
        if (!writable()) return;
        m_state.table.set(k, m_label);
        return finish();
    }
    if (k == "TUA" || k == "TUP" || k == "TUS") { // <int>[:<frac>], ASCII even in binary input (L1866)
        if (std::isdigit(static_cast<unsigned char>(c))) {
            (m_colon ? m_fraction : m_digits) += c;
            return;
        }
        if (c == ':') {
            if (m_colon) return fail(0xAA);
            m_colon = true;
            return;
        }
        if (c != '\r' || (m_digits.empty() && m_fraction.empty())) return fail(0xA2);
        const std::int64_t whole = m_digits.empty() ? 0 : std::stoll(m_digits.substr(0, 12));
        if (whole >= 65536) return fail(0x97);
        std::string fraction = (m_fraction + "0000").substr(0, 4);
        const std::int64_t value = whole * 10000 + std::stoll(fraction);
        if (value == 0) return fail(0x97);
        if (!applyValue(k, value)) return;
        return finish();
    }
    if (k == "D") { // D[<time>][<sync>]<cr> on the 4 ms clock (L1119-1134)
        if (!m_synced && collectDigit(c, false)) return;
        if (c == ',' || c == ';') {
            m_synced = true;
            return beginWait(c == ',' ? Pmc960Wait::MotionDone : Pmc960Wait::ConstantSpeed, false);
        }
        if (c != '\r') return fail(0xA2);
        const std::int64_t ms = numberGiven() ? number() : 0;
        if (ms > 65535) return fail(0x90);
        if (ms == 0) return finish();
        const std::int64_t ticks = (ms + 3) / 4;
        m_waitUntil_us = (m_now_us / 4000 + ticks + 1) * 4000; // delay in [4 ceil(t/4), 4 ceil(t/4) + 4) ms
        return beginWait(Pmc960Wait::Dwell, true);
    }
    // Hex even in decimal input, but binary in binary input like every number except THC's (L1870).
    const bool binaryIn = m_state.format().input() == NumberFormat::Binary;
    const bool hexAlways = oneOf(k, {"SP", "THC", "THR", "THL", "THM", "THP", "THS"}) && (!binaryIn || k == "THC");
    if (collectDigit(c, hexAlways)) return;
    if (c != '\r' || !numberGiven()) return fail(0xA2);
    if (applyValue(k, number())) finish();
}

} // namespace drive_core::pmc960
