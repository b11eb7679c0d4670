// Bds5Interpreter, motion side: the motion commands and their arguments in user units, handed to
// Bds5Motion (the profile generator's face), and TUNE. The rest of the language is in bds5_interpreter.cpp.
#include "bds5_interpreter.h"
#include "bds5_tune.h"

#include "bds5_expression.h"
#include "drive_core/catalog/bds5_catalog.h"

#include <cmath>

namespace drive_core::bds5 {

namespace cat = catalog::bds5;

namespace {
std::string joined(std::span<const Entry> entries) {
    std::string s;
    for (const Entry& e : entries) s += (s.empty() ? "" : " ") + e.text;
    return s;
}
} // namespace

std::optional<std::int64_t> Bds5Interpreter::basicValue(const Entry& entry, cat::UnitClass unit,
                                                        std::optional<Bds5Error>& error) const {
    const ExpressionResult r = evaluate(entry.text, [this](auto n) { return readValue(n); });
    if (r.error) {
        error = Bds5Error{r.error, entry.text, 0};
        return std::nullopt;
    }
    const auto basic = m_state.variables.toBasic(unit, r.value);
    if (!basic) error = Bds5Error{96, entry.text, 0};
    return basic;
}

// J v | MA p [v] | MI d [v] | JT p v | JF p v | MRD p v [CW|CCW] | MCA p [v [v]] | MCI d [v [v]] | MCD ms |
// MCGO | CONTINUE [ms] | W n | NORM p [CAM] | ZPE (L2277-3158, L4513-4549, L9430-9460, App. C).
Outcome Bds5Interpreter::motionCommand(std::span<const Entry> entries, const ExecContext& context) {
    const std::string& word = entries.front().text;
    const auto args = entries.subspan(1);
    struct Arity {
        const char* word;
        std::size_t least, most;
    };
    static constexpr Arity kArity[] = {{"J", 1, 1},   {"MA", 1, 2},   {"MI", 1, 2},  {"JT", 2, 2},      {"JF", 2, 2},
                                       {"MRD", 2, 3}, {"MCA", 1, 3},  {"MCI", 1, 3}, {"MCD", 1, 1},     {"MCGO", 0, 0},
                                       {"W", 1, 1},   {"NORM", 1, 2}, {"ZPE", 0, 0}, {"CONTINUE", 0, 1}};
    for (const Arity& a : kArity)
        if (word == a.word && (args.size() < a.least || args.size() > a.most))
            return {Bds5Error{82, joined(entries), 0}};
    std::optional<Bds5Error> error;
    const auto fail = [&](int e) { return Outcome{Bds5Error{e, joined(entries), 0}}; };
    if (word == "ZPE") { // PCMD := PFB (EXTLOOP: PEXT), the motor stays where it is (L2484-2494, L3131)
        const bool extloop = m_state.variables.read("EXTLOOP").value_or(0) != 0;
        const std::int64_t to =
            extloop ? std::int64_t(m_state.variables.read("PEXT").value_or(0)) : m_state.servo.feedback_counts();
        if (const int e = m_state.motion.zeroPositionError(double(to))) return {Bds5Error{e, joined(entries), 0}};
        m_state.variables.set("PCMD", std::int32_t(to));
        m_state.variables.set("PE", 0);
        return {};
    }
    if (word == "MCGO" || word == "CONTINUE") {
        if (word == "CONTINUE" && !args.empty()) { // averaging time 1..1000 ms (L6620-6631)
            const ExpressionResult r = evaluate(args[0].text, [this](auto n) { return readValue(n); });
            if (r.error) return {Bds5Error{r.error, args[0].text, 0}};
            if (r.value < 1 || r.value > 1000) return {Bds5Error{83, args[0].text, 0}};
        }
        const int e = word == "CONTINUE" ? m_state.motion.keepMoving(m_state.enabled)
                                         : m_state.motion.macroGo(m_state.variables, m_state.enabled);
        if (e == 30 && context.origin == Origin::Program) return {std::nullopt, Flow::WaitMotion};
        if (e) return fail(e);
        return {};
    }
    if (word == "MCD") {
        const ExpressionResult r = evaluate(args[0].text, [this](auto n) { return readValue(n); });
        if (r.error) return {Bds5Error{r.error, args[0].text, 0}};
        if (const int e = m_state.motion.macroDwell(r.value)) return fail(e);
        return {};
    }
    if (word == "JT" || word == "JF" || word == "MRD" || word == "MCA" || word == "MCI") {
        const auto first = basicValue(args[0], cat::UnitClass::Position, error);
        if (!first) return {error};
        std::optional<std::int64_t> v1;
        std::optional<std::int64_t> v2;
        int direction = 0;
        if (args.size() >= 2) {
            v1 = basicValue(args[1], cat::UnitClass::Velocity, error);
            if (!v1) return {error};
        }
        if (args.size() == 3 && word == "MRD") {
            if (args[2].text != "CW" && args[2].text != "CCW") return {Bds5Error{83, args[2].text, 0}};
            direction = args[2].text == "CW" ? 1 : -1;
        } else if (args.size() == 3) {
            v2 = basicValue(args[2], cat::UnitClass::Velocity, error);
            if (!v2) return {error};
        }
        int e = 0;
        if (word == "JT" || word == "JF")
            e = m_state.motion.jogTo(m_state.variables, m_state.enabled, *first, *v1, word == "JT");
        else if (word == "MRD")
            e = m_state.motion.moveRd(m_state.variables, m_state.enabled, *first, *v1, direction);
        else
            e = m_state.motion.macroSection(m_state.variables, *first, word == "MCA", v1, v2);
        if (e) return fail(e);
        return {};
    }
    if (word == "W") {
        const ExpressionResult r = evaluate(args[0].text, [this](auto n) { return readValue(n); });
        if (r.error) return {Bds5Error{r.error, args[0].text, 0}};
        if (r.value < 0 || r.value > 30) return {Bds5Error{83, args[0].text, 0}};
        return {std::nullopt, Flow::WaitSegment, r.value};
    }
    const auto unit = word == "J" ? cat::UnitClass::Velocity : cat::UnitClass::Position;
    const auto first = basicValue(args[0], unit, error);
    if (!first) return {error};
    if (word == "NORM" && args.size() == 2) { // NORM <master counts> CAM: camming on, PFB := PCAM (v3)
        if (args[1].text != "CAM") return {Bds5Error{83, args[1].text, 0}};
        if (const int e = m_state.motion.normalizeCam(m_state.variables, m_state.enabled, *first))
            return {Bds5Error{e, joined(entries), 0}};
        const auto pcam = std::llround(m_state.motion.servoTarget_counts());
        m_state.servo.normalize(pcam);
        m_state.variables.set("PFB", std::int32_t(pcam));
        m_state.variables.set("PCAM", std::int32_t(pcam));
        m_state.variables.set("PCMD", std::int32_t(*first % 32768));
        m_state.variables.set("CAM", 1);
        m_state.variables.set("PE", 0);
        return {};
    }
    if (word == "NORM") {
        if (m_state.variables.read("GEAR").value_or(0)) return {Bds5Error{56, joined(entries), 0}};
        if (const int e = m_state.motion.normalize(*first)) return {Bds5Error{e, joined(entries), 0}};
        m_state.servo.normalize(*first);
        m_state.variables.set("PFB", std::int32_t(*first));
        if (m_state.variables.read("EXTLOOP").value_or(0)) m_state.variables.set("PEXT", std::int32_t(*first));
        m_state.variables.set("PCMD", std::int32_t(*first));
        return {};
    }
    if (word == "J") {
        if (const int e = m_state.motion.jog(m_state.variables, m_state.enabled, *first))
            return {Bds5Error{e, joined(entries), 0}};
        return {};
    }
    std::optional<std::int64_t> velocity;
    if (args.size() == 2) {
        velocity = basicValue(args[1], cat::UnitClass::Velocity, error);
        if (!velocity) return {error};
    }
    const int e = m_state.motion.move(m_state.variables, m_state.enabled, *first, velocity, word == "MI");
    // A full buffer idles a program before the command (L4637-4641); typed, it is ERR 30 (L7242).
    if (e == 30 && context.origin == Origin::Program) return {std::nullopt, Flow::WaitMotion};
    if (e) return {Bds5Error{e, joined(entries), 0}};
    return {};
}

// RECORD <n> <ms> <v1> [v2 v3 v4] | PLAY (L6370-6397, L7011-7037). With v3's EXTDX on, PC-SCOPE (RECORD and
// PLAY) is unavailable (L9295-9297); the manual names no error: ERR 63 NOT AT THIS LEVEL (DECISIONS.md 11).
Outcome Bds5Interpreter::record(std::span<const Entry> entries, std::string& out) {
    const auto args = entries.subspan(1);
    if (entries.front().text == "PLAY") {
        if (!args.empty()) return {Bds5Error{82, args.front().text, 0}};
        if (m_state.variables.read("EXTDX").value_or(0)) return {Bds5Error{63, "PLAY", 0}};
        const auto listing = m_state.recorder.play();
        if (!listing) return {Bds5Error{65, "PLAY", 0}}; // RECORD NOT READY
        out += *listing;
        return {};
    }
    if (args.size() < 3 || args.size() > 6) return {Bds5Error{82, joined(entries), 0}};
    if (m_state.variables.read("EXTDX").value_or(0)) return {Bds5Error{63, joined(entries), 0}}; // v3: no RECORD
    const auto reader = [this](auto n) { return readValue(n); };
    const ExpressionResult n = evaluate(args[0].text, reader);
    if (n.error) return {Bds5Error{n.error, args[0].text, 0}};
    const ExpressionResult t = evaluate(args[1].text, reader);
    if (t.error) return {Bds5Error{t.error, args[1].text, 0}};
    std::vector<std::string> names;
    for (const Entry& e : args.subspan(2)) names.push_back(e.text);
    std::string bad;
    if (const int e = m_state.recorder.start(n.value, t.value, names, m_state.variables, bad))
        return {Bds5Error{e, bad.empty() ? joined(entries) : bad, 0}};
    return {};
}

// RAND <seed> | RAND Xn <e1> <e2> (v3, L9310): seed 0-31000; a number between the bounds, |e1-e2| <= 31000.
// The generator is not in the seed; chosen: a 32-bit linear congruential generator (deterministic).
Outcome Bds5Interpreter::random(std::span<const Entry> entries) {
    const auto args = entries.subspan(1);
    const auto reader = [this](auto n) { return readValue(n); };
    if (args.size() == 1) {
        const ExpressionResult seed = evaluate(args[0].text, reader);
        if (seed.error) return {Bds5Error{seed.error, args[0].text, 0}};
        if (seed.value < 0 || seed.value > 31000) return {Bds5Error{83, args[0].text, 0}};
        m_state.randomState = std::uint32_t(seed.value) * 2654435761u + 1;
        return {};
    }
    if (args.size() != 3) return {Bds5Error{82, joined(entries), 0}};
    // "<user reg>=1-250" (L9310), even with EXTDX on: X251-X750 cannot take a random number (DECISIONS.md 14).
    const auto target = cat::findVariable(args[0].text);
    if (!target || target->info->name != "X" || target->index > target->info->lastIndex)
        return {Bds5Error{83, args[0].text, 0}};
    const ExpressionResult a = evaluate(args[1].text, reader);
    if (a.error) return {Bds5Error{a.error, args[1].text, 0}};
    const ExpressionResult b = evaluate(args[2].text, reader);
    if (b.error) return {Bds5Error{b.error, args[2].text, 0}};
    const std::int64_t lo = std::min(a.value, b.value);
    const std::int64_t hi = std::max(a.value, b.value);
    if (hi - lo > 31000) return {Bds5Error{83, args[2].text, 0}};
    m_state.randomState = m_state.randomState * 1664525u + 1013904223u;
    const std::int64_t value = lo + std::int64_t((m_state.randomState >> 8) % std::uint32_t(hi - lo + 1));
    m_state.variables.set(*target, std::int32_t(value));
    return {};
}

// TRECORD START|STOP|CONTINUE and TPLAY [NEWEST n | OLDEST n | n | l1 l2] (v3, L9317-9319): lines
// "#<n> LINE <program line> <task prefix> <command>", numbered oldest first (chosen where the OCR is unclear).
Outcome Bds5Interpreter::realTimeTrace(std::span<const Entry> entries, std::string& out) {
    const auto args = entries.subspan(1);
    if (m_state.variables.read("EXTDX").value_or(0)) return {Bds5Error{63, joined(entries), 0}};
    if (entries.front().text == "TRECORD") {
        if (args.size() != 1) return {Bds5Error{82, joined(entries), 0}};
        const std::string& what = args[0].text;
        if (what == "START")
            m_state.traceBuffer.clear();
        else if (what != "STOP" && what != "CONTINUE")
            return {Bds5Error{83, what, 0}};
        m_state.traceRecording = what != "STOP";
        return {};
    }
    const int size = int(m_state.traceBuffer.size());
    int first = 1;
    int last = size;
    std::vector<std::int32_t> numbers;
    const std::size_t numberAt = args.size() == 2 && (args[0].text == "NEWEST" || args[0].text == "OLDEST") ? 1 : 0;
    for (std::size_t i = numberAt; i < args.size(); ++i) {
        const auto v = parseConstant(args[i].text);
        if (!v || *v < 0) return {Bds5Error{83, args[i].text, 0}};
        numbers.push_back(*v);
    }
    if (args.size() > 2) return {Bds5Error{82, joined(entries), 0}};
    if (numberAt == 1 && args[0].text == "NEWEST")
        first = std::max(1, size - numbers[0] + 1);
    else if (numberAt == 1)
        last = std::min(size, int(numbers[0]));
    else if (numbers.size() == 1)
        first = last = numbers[0];
    else if (numbers.size() == 2) {
        first = numbers[0];
        last = std::min(size, int(numbers[1]));
    }
    for (int n = std::max(first, 1); n <= last && n <= size; ++n) {
        const auto& e = m_state.traceBuffer[std::size_t(n - 1)];
        out += "#" + std::to_string(n) + " LINE " + std::to_string(e.line) + " " + e.prefix + " " + e.text + "\r\n";
    }
    return {};
}

// TUNE bw stab (L6264-6286, L7084-7096): enables the drive for the shake even if it is disabled; the
// motor ends where the shake left it, so the command is re-based on it (PE 0).
Outcome Bds5Interpreter::tune(std::span<const Entry> entries) {
    const auto args = entries.subspan(1);
    if (args.size() != 2) return {Bds5Error{82, joined(entries), 0}};
    std::int64_t values[2] = {};
    for (std::size_t i = 0; i < 2; ++i) {
        const ExpressionResult r = evaluate(args[i].text, [this](auto n) { return readValue(n); });
        if (r.error) return {Bds5Error{r.error, args[i].text, 0}};
        values[i] = r.value;
    }
    if (!Bds5Tune::validBandwidth(int(values[0]))) return {Bds5Error{83, args[0].text, 0}};
    if (Bds5Tune::damping(int(values[1])) == 0) return {Bds5Error{83, args[1].text, 0}};
    if (m_state.motion.moving()) return {Bds5Error{57, joined(entries), 0}};
    const bool remote = m_state.variables.read("REMOTE").value_or(1) != 0;
    const int e = Bds5Tune::run(m_state.servo, m_state.variables, int(values[0]), int(values[1]), remote);
    m_state.motion.zeroPositionError(double(m_state.servo.feedback_counts()));
    if (e) return {Bds5Error{e, joined(entries), 0}};
    return {};
}

} // namespace drive_core::bds5
