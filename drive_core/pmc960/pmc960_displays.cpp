// What the display characters print (5.3.1, 5.3.4, 7.18): ? entered value, ! current value, & value at the
// last error. chosen (digest §11.2 #23): the value follows the echoed command directly, negative numbers
// with a leading '-'; T displays in decimal start with CR LF and label each item "<letter>-<value>"
// like TF's "48-<gain48>" (L1732); hex and binary output drop labels and separators (L1719).
#include "pmc960_interpreter.h"

#include <cmath>

namespace drive_core::pmc960 {

namespace {

std::string fixedPoint(std::int64_t value) { // x 10000 -> "68:27"
    std::string text = std::to_string(value / 10000);
    std::string fraction = std::to_string(10000 + value % 10000).substr(1);
    while (!fraction.empty() && fraction.back() == '0') fraction.pop_back();
    return fraction.empty() ? text : text + ":" + fraction;
}

} // namespace

std::string Pmc960Interpreter::display(std::string_view command, char kind) const {
    const Pmc960Format fmt = m_state.format();
    const Pmc960Units units = m_state.units();
    const Pmc960Registers& reg = m_state.reg;
    const Pmc960Motion& motion = m_state.motion;
    const bool stored = kind == '?';
    auto num = [&fmt](double value, int bits) { return fmt.number(std::llround(value), bits); };
    auto lastLabel = [&fmt](char label, int count) {
        if (fmt.output() == NumberFormat::Binary) return std::string(1, label) + fmt.number(count, 16);
        return std::string(1, label) + " " + fmt.number(count, 16); // no space in binary output (L1472)
    };
    const std::string k(command);

    if (kind == '&') {
        const Pmc960Snapshot& s = m_state.snapshot;
        if (k == "V") return num(double(s.velocity), 16);
        if (k == "G") return num(double(s.position), 32);
        if (k == "SS") return fmt.hex(s.motionBits, 2);
        if (k == "SI") return fmt.hex(s.inputs, 4);
        if (k == "SB") return lastLabel(s.lastLabel, s.commandCount);
        if (k == "OB") return fmt.hex(s.outputs, 4);
        if (k == "SM") return num(s.mode, 8);
        if (k == "SE") return fmt.hex(s.error, 2);
        return {};
    }
    if (kind != '?' && kind != '!') return {};

    if (k == "A")
        return num(stored ? double(reg.acceleration) : units.userAccel(std::abs(motion.acceleration_cps2())), 16);
    if (k == "V") return num(stored ? double(reg.velocity) : units.userVelocity(std::abs(motion.velocity_cps())), 16);
    if (k == "J")
        return num(stored ? double(reg.jogSpeed) : units.userVelocity(std::abs(motion.referenceVelocity_cps())), 16);
    if (k == "I") return num(stored ? double(reg.distance) : units.userPosition(motion.remaining_counts()), 32);
    if (k == "G") return num(stored ? double(reg.goPosition) : units.userPosition(motion.actual_counts()), 32);
    if (k == "H") {
        const std::int64_t size = m_state.table.inUse("THA");
        if (stored) return num(double(reg.homeLocation), 16);
        if (size == 0) return num(units.userVelocity(std::abs(motion.referenceVelocity_cps())), 16);
        const double reading = std::fmod(std::fmod(motion.actual_counts(), double(size)) + double(size), double(size));
        return num(std::floor(reading), 16);
    }
    if (k == "SF") return num(stored ? double(reg.followingTrip) : motion.followingError_counts(), 16);
    if (k == "SD") return num(double(reg.depth), 16);
    if (k == "ST") return num(double(reg.torque), 16);
    if (k == "SV") return num(double(reg.feedrate), 8);
    if (k == "SW") return num(double(reg.writeEnable), 8);
    if (k == "SN") return num(double(reg.normalizeError), 16);
    if (k == "SM") return num(motion.mode(), 8);
    if (k == "SE") return fmt.hex(reg.lastError, 2);
    if (k == "SS") return fmt.hex(m_state.motionBits(), 2);
    if (k == "SI") return fmt.hex(m_state.inputs, 4);
    if (k == "SP") return fmt.hex(reg.profile, 2);
    if (k == "SB") return lastLabel(reg.lastLabel, reg.commandCount);
    if (k == "OA") return num(double(reg.analogOut), 16);
    if (k == "OB") return fmt.hex(reg.outputs, 4);
    if (k == "SL") {
        if (fmt.output() != NumberFormat::Decimal)
            return num(double(reg.limitForward), 32) + num(double(reg.limitReverse), 32);
        return "F" + num(double(reg.limitForward), 32) + " R" + num(double(reg.limitReverse), 32);
    }

    // T displays.
    const bool decimal = fmt.output() == NumberFormat::Decimal;
    const Pmc960Table& table = m_state.table;
    auto value = [&](const std::string& name) { return stored ? table.stored(name) : table.inUse(name); };
    auto item = [&](std::string& out, std::string_view label, const std::string& text) {
        if (!decimal) {
            out += text;
            return;
        }
        if (!out.empty()) out += ' ';
        out += std::string(label) + "-" + text;
    };
    auto group = [&](std::string_view prefix, std::string_view only = {}) {
        std::string out;
        const std::string_view letters = !only.empty()    ? only
                                         : prefix == "TG" ? "PVTFEBXL"
                                         : prefix == "TH" ? "ABCILMPRS"
                                         : prefix == "TL" ? "BPV"
                                                          : "ABHPSV";
        for (const char letter : letters) {
            const std::string name = std::string(prefix) + letter;
            const std::int64_t v = value(name);
            std::string text;
            if (name == "TGE" || name == "TGB" || name == "THC" || name == "THR")
                text = fmt.hex(v, 2);
            else if (name == "THI" || prefix == "TL")
                text = v == 0 ? (decimal ? std::string() : std::string(1, '\0')) : std::string(1, char(v));
            else if (name == "TUA" || name == "TUP" || name == "TUS")
                text = decimal ? fixedPoint(v) : fmt.number(v, 32);
            else
                text = fmt.number(v, name == "THA" || prefix == "TU" ? 16 : 8);
            item(out, std::string_view(&letter, 1), text);
        }
        return out;
    };
    const std::string lead = decimal ? "\r\n" : "";
    if (k == "TF") {
        const auto ff = table.feedForward();
        std::string out;
        item(out, "48", fmt.number(ff.gain48, 8));
        item(out, "192", fmt.number(ff.gain192, 8));
        item(out, "384", fmt.number(ff.gain384, 8));
        item(out, "Ext", fmt.number(ff.gainExt, 8));
        return lead + out;
    }
    if (k == "TG" || k == "TH" || k == "TL" || k == "TU") return lead + group(k);
    if (k.size() == 3 && k[0] == 'T') return lead + group(k.substr(0, 2), std::string_view(k).substr(2));
    if (k == "T") {
        if (!decimal) return group("TG") + group("TH") + group("TL") + group("TU");
        return lead + group("TG") + lead + group("TH") + lead + group("TL") + lead + group("TU");
    }
    return {};
}

} // namespace drive_core::pmc960
