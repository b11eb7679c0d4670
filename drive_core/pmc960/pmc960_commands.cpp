// MPL command actions: motion (I J G H N C R), values (A V D OA OB S..., TH/TL/TU), the TG gain chains. Each
// handler receives the characters after the command letters, one at a time (pmc960_interpreter.h).
#include "pmc960_interpreter.h"

#include <cctype>
#include <cmath>

namespace drive_core::pmc960 {

namespace {
char upper(char c) {
    return char(std::toupper(static_cast<unsigned char>(c)));
}
bool isHexDigit(char c) {
    return std::isxdigit(static_cast<unsigned char>(c)) != 0;
}
int hexValue(char c) {
    return std::isdigit(static_cast<unsigned char>(c)) ? c - '0' : upper(c) - 'A' + 10;
}
constexpr std::int64_t kMax31 = 2147483647;
constexpr std::int64_t kMax30 = std::int64_t(1) << 30; // go and normalize positions (5.7)
} // namespace

bool Pmc960Interpreter::writable() {
    if (m_state.reg.writeEnable != 0) return true;
    fail(0xD3);
    return false;
}

bool Pmc960Interpreter::motionAllowed(bool reverse) {
    int code = 0;
    if (m_state.lines.estop)
        code = 0xB3;
    else if (!m_state.motion.enabled())
        code = 0xB6;
    else if (m_state.table.inUse("THL") != 0 && !reverse && (m_state.inputs & 0x80) != 0)
        code = 0xB8; // IN07' = + limit
    else if (m_state.table.inUse("THL") != 0 && reverse && (m_state.inputs & 0x40) != 0)
        code = 0xB9; // IN06' = - limit
    if (code != 0) fail(code);
    return code == 0;
}

void Pmc960Interpreter::stopMotion() {
    if (m_command == "J" && (m_state.reg.profile & 0x01) != 0 && !m_state.motion.atPositiveStop()) // SP bit 0
        m_state.motion.sharpStop();
    else
        m_state.motion.stop(m_state.units().accel_cps2(double(m_state.reg.acceleration)));
}

bool Pmc960Interpreter::startMotion(char command, int sign) {
    const Pmc960Units units = m_state.units();
    Pmc960Registers& reg = m_state.reg;
    Pmc960Motion& motion = m_state.motion;
    const double feedrate = double(reg.feedrate) / 100.0;
    const double accel = units.accel_cps2(double(reg.acceleration));
    if (command == 'J' && numberGiven()) {
        if (number() < 1 || number() > std::int64_t(units.maximumUserVelocity())) return fail(0x94), false;
        if (units.velocityTooSmall(double(number()))) return fail(0x98), false;
        reg.jogSpeed = number();
    }
    if (command == 'I' && numberGiven()) {
        if (number() < 1 || number() > kMax31) return fail(0x91), false;
        if (units.positionOverflows(double(number()), double(kMax31))) return fail(0x99), false;
        reg.distance = number();
    }
    if (command == 'G') {
        const std::int64_t position = numberGiven() ? number() : 0;
        if (position > kMax30) return fail(0x93), false;
        if (units.positionOverflows(double(position), double(kMax30))) return fail(0x99), false;
        reg.goPosition = sign * position;
    }
    if (command == 'H' && numberGiven()) {
        const std::int64_t size = m_state.table.inUse("THA");
        if (size > 0 && number() >= size) return fail(0x9B), false;
        reg.homeLocation = number();
    }
    if (motion.atPositiveStop()) return fail(0xB2), false; // a stop command ends FPS first (L2347)
    if (motion.moving() && !(command == 'J' && motion.jogging())) return fail(0xB2), false;
    bool reverse = sign < 0;
    if (command == 'G') reverse = units.position_counts(double(reg.goPosition)) < motion.commanded_counts();
    if (!motionAllowed(reverse)) return false;
    if (m_state.table.inUse("THS") != 0) { // software limits (SL, L1555-1575): no start into a limit
        const double forward = units.position_counts(double(reg.limitForward));
        const double backward = units.position_counts(double(reg.limitReverse));
        double target = motion.commanded_counts();
        if (command == 'I') target = motion.target_counts() + sign * units.position_counts(double(reg.distance));
        if (command == 'G') target = units.position_counts(double(reg.goPosition));
        if (command == 'J' || command == 'H') target += sign; // the direction is what counts
        const bool beyondForward = target > forward && !reverse;
        const bool beyondReverse = target < backward && reverse;
        if (beyondForward || beyondReverse) {
            if (command == 'J') return true;                 // a jog gets no message (L1561)
            return fail(beyondForward ? 0xB8 : 0xB9), false; // code not given: B8/B9 (digest §11.2 #28)
        }
    }
    // SP, latched as the motion starts (L1612-1631): bit 6 adaptive depth, 3 external decel (I and G).
    const bool fromRest = !motion.moving();
    const bool depth = (reg.profile & 0x40) != 0 && (command == 'I' || command == 'G');
    const bool externalDecel = (reg.profile & 0x08) != 0 && (command == 'I' || command == 'G');
    const double speed = units.velocity_cps(double(reg.velocity)) * feedrate;
    if (depth && externalDecel) return fail(0xB4), false;
    // The depth must exceed the distance to stop from speed plus the following error (L1487-1492).
    if (depth && double(reg.depth) <= speed * speed / (2 * accel) + motion.steadyError_counts(speed))
        return fail(0xB1), false;
    switch (command) {
    case 'I':
    case 'G': {
        const double target = command == 'I'
                                  ? motion.target_counts() + sign * units.position_counts(double(reg.distance))
                                  : units.position_counts(double(reg.goPosition));
        using Action = Pmc960Motion::SensorAction;
        if (externalDecel) { // at speed until SENSOR, then down at the A rate, wherever that ends
            motion.jog(target < motion.commanded_counts() ? -speed : speed, accel);
            motion.onSensor(Action::Decelerate, accel);
        } else {
            motion.go(target, speed, accel);
            if (depth) motion.onSensor(Action::Depth, accel, double(reg.depth)); // SD is in counts
        }
        break;
    }
    case 'J': motion.jog(sign * units.velocity_cps(double(reg.jogSpeed)) * feedrate, accel); break;
    case 'H': {
        // Resolver: the next position ahead whose reading is the location; encoder: the next marker. chosen:
        // an encoder (THA 0) has its marker every 4,096 counts.
        const std::int64_t thaSize = m_state.table.inUse("THA");
        const double size = thaSize > 0 ? double(thaSize) : 4096.0;
        const double here = motion.commanded_counts();
        const double location = thaSize > 0 ? double(reg.homeLocation) : 0.0;
        double target = std::floor(here / size) * size + location;
        if (sign > 0)
            while (target <= here) target += size;
        else
            while (target >= here) target -= size;
        const double homeSpeed = units.velocity_cps(double(m_state.table.inUse("TUH")));
        if ((reg.profile & 0x04) != 0) { // SP bit 2: SENSOR, not the zero reference, stops the home
            motion.jog(sign * homeSpeed, accel);
            motion.onSensor(Pmc960Motion::SensorAction::Stop, accel);
        } else {
            motion.go(target, homeSpeed, accel);
        }
        break;
    }
    default: break;
    }
    // SP bits 5+4: a motion from rest starts on SENSOR. chosen: the zero-reference start (bit 4 = 0) is
    // not modelled (nothing turns a motor at rest in the simulator), so that motion starts at once.
    if (fromRest && (reg.profile & 0x30) == 0x30) motion.holdForSensor();
    motion.armPositiveStop((reg.profile & 0x80) != 0); // SP bit 7: feed to positive stop
    return true;
}

// I J G H N: [<number>] then any of + - * , ; and <cr> (L1165-1363).
void Pmc960Interpreter::motionArgument(char c, bool first) {
    const char cmd = m_command[0];
    Pmc960Motion& motion = m_state.motion;
    if (collectDigit(c, false)) {
        if (cmd == 'J' && m_triggered && motion.jogging()) stopMotion(); // any other character stops (L1270)
        return;
    }
    switch (c) {
    case '+':
    case '-':
        if (cmd == 'N') {
            if (motion.moving()) return fail(0xB2);
            const std::int64_t position = (c == '-' ? -1 : 1) * (numberGiven() ? number() : 0);
            if (std::abs(position) > kMax30) return fail(0x93);
            if (m_state.units().positionOverflows(double(position), double(kMax30))) return fail(0x99);
            const double cancelled = motion.normalize(m_state.units().position_counts(double(position)));
            m_state.reg.normalizeError = std::llround(cancelled);
            return finish(); // N ends at its sign (L1344)
        }
        if (!startMotion(cmd, c == '-' ? -1 : 1)) return;
        // Encoder home (THA 0) is H[<sync>]<direction> with no <cr> (L733, L1222, examples L1246-1250): the
        // direction completes it. Resolver H, I, J and G keep their line open for <cr>.
        if (cmd == 'H' && m_state.table.inUse("THA") == 0) return finish();
        m_triggered = true;
        clearNumber();
        return;
    case '*':
        if (cmd == 'N') {
            if (!first) return fail(0xA2);
            resetCommand();
            m_sink.softwareReset();
            return;
        }
        stopMotion();
        // G* is one of G's display forms (L1169, L1181) and H* is written without the <cr> its neighbours
        // H15+<cr> and H,-<cr> carry (L1214-1216, L1250): both are complete commands, acting and prompting at
        // once. I* and J* are directions inside a line that stays open (#<direction>#, L1255, L1266, and
        // J,-*+*- at L1296), ended by <cr>.
        if (cmd == 'G' || cmd == 'H') return finish();
        m_triggered = true;
        return;
    case ',': beginWait(Pmc960Wait::MotionDone, false); return;
    case ';': beginWait(Pmc960Wait::ConstantSpeed, false); return;
    case '\r':
        if (cmd == 'N') {
            if (!first) return fail(0xA2);
            resetCommand();
            m_sink.autobaud();
            return;
        }
        if (numberGiven()) {
            const std::int64_t n = number();
            switch (cmd) {
            case 'I':
                if (n < 1 || n > kMax31) return fail(0x91);
                if (m_state.units().positionOverflows(double(n), double(kMax31))) return fail(0x99);
                m_state.reg.distance = n;
                break;
            case 'J':
                if (n < 1 || n > std::int64_t(m_state.units().maximumUserVelocity())) return fail(0x94);
                if (m_state.units().velocityTooSmall(double(n))) return fail(0x98);
                m_state.reg.jogSpeed = n;
                break;
            case 'H':
                if (m_state.table.inUse("THA") > 0 && n >= m_state.table.inUse("THA")) return fail(0x9B);
                m_state.reg.homeLocation = n;
                break;
            case 'G': // <cr> is the trigger when no sign came first (digest §11.2 #10)
                if (!m_triggered && !startMotion('G', 1)) return;
                break;
            default: break;
            }
        }
        return finish();
    default:
        if (cmd == 'J' && m_triggered && motion.jogging()) stopMotion();
        return fail(0xA2);
    }
}

// TG#<register>[<value>]#<sign>##<cr> (L1741-1773): TGP++V5--<cr> adds 2 to P and takes 10 from V.
void Pmc960Interpreter::gainsArgument(char c) {
    static constexpr std::string_view kRegisters = "PVTFEBXL";
    const char u = upper(c);
    if (m_command.size() == 3) { // TGP typed as one word: the register is the third letter
        m_register = m_command[2];
        m_command = "TG";
    }
    auto setGain = [this](char reg, std::int64_t value) {
        if (!writable()) return false;
        if (value < 0 || value > 255) return fail(0x90), false;
        if (reg == 'F' && Pmc960Table::feedForwardOverflows(value)) return fail(0x9C), false;
        m_state.table.set(std::string("TG") + reg, value);
        m_state.applyTable();
        return true;
    };
    const bool hexRegister =
        (m_register == 'E' || m_register == 'B') && m_state.format().input() != NumberFormat::Binary;
    const bool isDigit = std::isdigit(static_cast<unsigned char>(c)) || (hexRegister && isHexDigit(c)) ||
                         (m_state.format().input() == NumberFormat::Hex && isHexDigit(c) && m_register != 0 &&
                          kRegisters.find(u) == std::string_view::npos) ||
                         m_binaryBytes > 0 || (c == '\0' && m_state.format().input() == NumberFormat::Binary);
    if (m_register != 0 && isDigit) {
        if (m_gainApplied) {
            clearNumber();
            m_gainApplied = false;
        }
        collectDigit(c, hexRegister);
        return;
    }
    if (kRegisters.find(u) != std::string_view::npos && c != '\0') {
        if (m_register != 0 && numberGiven() && !m_gainApplied && !setGain(m_register, number())) return;
        m_register = u;
        clearNumber();
        m_gainApplied = false;
        return;
    }
    if (m_register == 0) return fail(0xA1);
    if ((c == '?' || c == '!') && !numberGiven() && !m_gainApplied) { // TGP? shows one register
        m_sink.send(display(std::string("TG") + m_register, c));
        return finish();
    }
    if (c == '+' || c == '-') {
        const std::int64_t step = numberGiven() ? number() : 1;
        const std::int64_t now = m_state.table.inUse(std::string("TG") + m_register);
        if (!setGain(m_register, now + (c == '+' ? step : -step))) return;
        m_gainApplied = true;
        return;
    }
    if (c == '\r') {
        if (numberGiven() && !m_gainApplied && !setGain(m_register, number())) return;
        return finish();
    }
    fail(0xA2);
}

// R<tick><count>...<cr> (L1441-1460, L2155-2284). Ticks 1-7 forward, 9-F reverse; the count has 2, 3 or 4
// hex digits. chosen: each segment is queued as a move at count/tick-time with TUB ramps; G/H ticks and
// binary counts are not simulated (#A2).
void Pmc960Interpreter::contourArgument(char c) {
    const Pmc960Units units = m_state.units();
    if (m_contourTick == 0) {
        if (c == '\r') return finish();
        if (c == '0') return; // end of the contour motion: nothing more is queued
        if (!isHexDigit(c) || c == '8') return fail(0xA2);
        const int v = hexValue(c);
        const int n = v > 8 ? v - 8 : v;
        m_contourTick = v > 8 ? -n : n;
        m_contourDigits = n == 1 ? 2 : n <= 3 ? 3 : 4;
        return;
    }
    if (c == '\r') return finish(); // a <cr> before all digits ends the count and the line
    if (!isHexDigit(c)) {
        m_state.motion.stop(units.maximumAccel_cps2());
        return fail(0xA2);
    }
    m_digits += c;
    if (int(m_digits.size()) < m_contourDigits) return;
    std::int64_t count = 0;
    for (const char d : m_digits) count = count * 16 + hexValue(d);
    const int n = std::abs(m_contourTick);
    const std::int64_t maximum = n == 1 ? 255 : std::int64_t(256) << (n - 1);
    if (count > maximum) { // #A4, though 7.22 lists it as reserved (digest §11.2 #8)
        m_state.motion.stop(units.maximumAccel_cps2());
        return fail(0xA4);
    }
    const double rangeScale = units.topSpeed_cps() <= 48000 ? 4.0 : units.topSpeed_cps() > 192000 ? 0.5 : 1.0;
    const double tick_s = 256.0 / 192000.0 * std::pow(2.0, n - 1) * rangeScale;
    const double direction = m_contourTick < 0 ? -1 : 1;
    const double target = m_state.motion.target_counts() + direction * double(count);
    const bool fromRest = !m_state.motion.moving();
    if (count > 0 && !m_state.motion.go(target, double(count) / tick_s, units.maximumAccel_cps2())) return fail(0xD8);
    // Sensor start (L2255): a segment entered from command level waits for SENSOR. chosen: a sensor start
    // requested within a running profile (hold the last speed until SENSOR) is not modelled.
    if (count > 0 && fromRest && (m_state.reg.profile & 0x30) == 0x30) m_state.motion.holdForSensor();
    m_contourTick = 0;
    clearNumber();
    if (m_source == Source::Sci) beginWait(Pmc960Wait::ContourReady, false);
}

} // namespace drive_core::pmc960
