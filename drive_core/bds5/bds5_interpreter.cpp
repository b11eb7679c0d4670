// BDS5 instruction execution. The full language grows here (issue 3); motion arrives with issue 4.
#include "bds5_interpreter.h"

#include "bds5_dump.h"
#include "bds5_expression.h"
#include "bds5_printer.h"
#include "drive_core/catalog/bds5_catalog.h"
#include "drive_core/physics/motor_parameters.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <unordered_map>

namespace drive_core::bds5 {

namespace cat = catalog::bds5;

void logError(Bds5State& state, int code) {
    static const auto lsterr = cat::findVariable("LSTERR"); // LSTERR: the last error (digest §4.14)
    if (code != 199 && lsterr) state.variables.set(*lsterr, code);
    state.errorHistory.push_front(code);
    while (state.errorHistory.size() > kErrorHistorySize) state.errorHistory.pop_back();
}

void switchExtendedRegisters(Bds5State& state) {
    const cat::VariableInfo* x = cat::findVariable("X1")->info;
    for (int i = x->lastIndex + 1; i <= cat::highestIndex(*x); ++i) state.variables.set(cat::VariableRef{x, i}, 0);
    state.recorder.clear();
    state.traceBuffer.clear();
    state.traceRecording = false;
}

namespace {

// "VFB[5.3]" -> expression "VFB", format "5.3"; nullopt when the brackets are malformed.
std::optional<std::pair<std::string_view, std::string_view>> splitFormat(std::string_view item) {
    const std::size_t open = item.find('[');
    if (open == std::string_view::npos) return std::pair{item, std::string_view{}};
    if (item.back() != ']' || open == 0) return std::nullopt;
    return std::pair{item.substr(0, open), item.substr(open + 1, item.size() - open - 2)};
}

// A command typed where the catalog says it does not belong: ERR 52 from the terminal, ERR 63 from
// monitor mode (the COM1 transcripts, L9805, L9861), ERR 53 from the program.
int legalityError(std::string_view word, Origin origin) {
    const cat::CommandInfo* command = cat::findCommand(word);
    if (!command) return 0;
    const unsigned needed = origin == Origin::Terminal  ? cat::kInteractive
                            : origin == Origin::Monitor ? cat::kMonitor
                                                        : cat::kProgram;
    if (command->modes & needed) return 0;
    return origin == Origin::Terminal ? 52 : origin == Origin::Monitor ? 63 : 53;
}

std::string joined(std::span<const Entry> entries) {
    std::string s;
    for (const Entry& e : entries) s += (s.empty() ? "" : " ") + e.text;
    return s;
}

// The instruction words dispatch() acts on, looked up once an instruction: comparing the word with each
// name in turn was a fifth of the input fuzzer's time (issue 20). Any other word assigns or is ERR 80.
// Packed by hand: clang-format would put every entry on its own line.
// clang-format off
enum class Word {
    Other, QuickIf, Til, If, Elif, Else, Endif, Ret, End, B, S, K, List, Ed, Goto, Gosub, Run, Load, Rd, D, H,
    P, PS, R, RS, PA, PAS, Input, Err, Dump, En, Dis, Record, Tune, Rand, Trace, Motor, Motion, ClearX
};

Word wordOf(std::string_view word) {
    static const std::unordered_map<std::string_view, Word> kWords{
        {"?", Word::QuickIf}, {"TIL", Word::Til}, {"IF", Word::If}, {"ELIF", Word::Elif},
        {"ELSE", Word::Else}, {"ENDIF", Word::Endif}, {"RET", Word::Ret}, {"END", Word::End},
        {"B", Word::B}, {"S", Word::S}, {"K", Word::K}, {"<BDS", Word::List},
        {"ED", Word::Ed}, {"GOTO", Word::Goto}, {"GOSUB", Word::Gosub}, {"RUN", Word::Run},
        {">BDS", Word::Load}, {"RD", Word::Rd}, {"D", Word::D}, {"H", Word::H},
        {"P", Word::P}, {"PS", Word::PS}, {"R", Word::R}, {"RS", Word::RS},
        {"PA", Word::PA}, {"PAS", Word::PAS}, {"INPUT", Word::Input}, {"ERR", Word::Err},
        {"DUMP", Word::Dump}, {"EN", Word::En}, {"DIS", Word::Dis}, {"RECORD", Word::Record},
        {"PLAY", Word::Record}, {"TUNE", Word::Tune}, {"RAND", Word::Rand}, {"TRECORD", Word::Trace},
        {"TPLAY", Word::Trace}, {"MOTOR", Word::Motor}, {"CLEARX", Word::ClearX},
        // the motion commands (bds5_interpreter_motion.cpp)
        {"J", Word::Motion}, {"MA", Word::Motion}, {"MI", Word::Motion}, {"W", Word::Motion},
        {"NORM", Word::Motion}, {"ZPE", Word::Motion}, {"JT", Word::Motion}, {"JF", Word::Motion},
        {"MRD", Word::Motion}, {"CONTINUE", Word::Motion}, {"MCA", Word::Motion}, {"MCI", Word::Motion},
        {"MCD", Word::Motion}, {"MCGO", Word::Motion}};
    // clang-format on
    const auto it = kWords.find(word);
    return it == kWords.end() ? Word::Other : it->second;
}

} // namespace

std::optional<std::int32_t> Bds5Interpreter::readValue(std::string_view name) const {
    if (name == "CHECKSUM") return m_state.program.checksum(); // P CHECKSUM after a load (L9953)
    return m_state.variables.read(name);
}

Outcome Bds5Interpreter::execute(std::span<const Entry> entries, const ExecContext& context, std::string& out) {
    Outcome outcome = dispatch(entries, context, out);
    if (outcome.error && context.origin == Origin::Program) outcome.error->line = context.line;
    return outcome;
}

Outcome Bds5Interpreter::dispatch(std::span<const Entry> entries, const ExecContext& context, std::string& out) {
    if (entries.empty()) return {};
    if (int(entries.size()) > kMaxEntries) return {Bds5Error{82, entries.back().text, 0}};
    const std::string& word = entries.front().text;
    const auto args = entries.subspan(1);

    if (const int error = legalityError(word, context.origin)) return {Bds5Error{error, joined(entries), 0}};
    const Word w = wordOf(word);
    // A print in a program idles until the previous one has left and no INPUT waits (L4637, L4797-4814);
    // this catches the prints inside ? and TIL, whose lines the executor cannot see as prints.
    const bool printing = w == Word::P || w == Word::PS || w == Word::R || w == Word::RS || w == Word::PA ||
                          w == Word::PAS || w == Word::Input ||
                          (w == Word::Err && !(args.size() == 1 && args[0].text == "CLR"));
    if (printing && context.origin == Origin::Program) {
        if ((m_state.serialBusy || m_state.pendingInput) && context.nested) return {std::nullopt, Flow::WaitPrinter};
        m_state.serialBusy = true;
    }
    switch (w) {
    case Word::QuickIf: return quickIf(entries, context, out);
    case Word::Til: return til(entries, context, out);
    case Word::If:
    case Word::Elif: {
        if (args.size() != 3) return {Bds5Error{82, joined(entries), 0}};
        std::optional<Bds5Error> error;
        const auto c = condition(args, error);
        if (!c) return {error};
        return {std::nullopt, w == Word::If ? Flow::If : Flow::Elif, 0, *c};
    }
    case Word::Else:
    case Word::Endif:
    case Word::Ret:
    case Word::End:
    case Word::B:
    case Word::S:
    case Word::K:
    case Word::List:
    case Word::Ed:
        if (!args.empty()) return {Bds5Error{82, args.front().text, 0}};
        if (w == Word::K) {
            m_state.enabled = false;
            m_state.motion.halt();
        }
        if (w == Word::S) m_state.motion.stop(m_state.variables); // decelerate at AMAX (L2212-2231)
        return {std::nullopt, w == Word::Else    ? Flow::Else
                              : w == Word::Endif ? Flow::Endif
                              : w == Word::Ret   ? Flow::Return
                              : w == Word::End   ? Flow::End
                              : w == Word::B     ? Flow::Break
                              : w == Word::S     ? Flow::Stop
                              : w == Word::K     ? Flow::Kill
                              : w == Word::Ed    ? Flow::Edit
                                                 : Flow::List};
    case Word::Goto: return jump(Flow::Goto, entries);
    case Word::Gosub: return jump(Flow::Gosub, entries);
    case Word::Run:
        if (args.empty()) return {std::nullopt, Flow::Run, -1};
        return jump(Flow::Run, entries);
    case Word::Load:
        if (args.size() > 1) return {Bds5Error{82, args[1].text, 0}};
        return {std::nullopt, Flow::Load, 0, false, args.empty() ? std::string() : args.front().text};
    case Word::Rd: // RD <ms>: a dwell timed by the external input (L5823-5839, L6999-7009)
    case Word::D: {
        if (args.size() != 1) return {Bds5Error{82, joined(entries), 0}};
        const ExpressionResult r = evaluate(args.front().text, [this](auto n) { return readValue(n); });
        if (r.error) return {Bds5Error{r.error, args.front().text, 0}};
        if (r.value < 0) return {Bds5Error{83, args.front().text, 0}};
        return {std::nullopt, w == Word::Rd ? Flow::RegulatedDwell : Flow::Dwell, r.value};
    }
    case Word::H: { // H <switch> ON|OFF — any switch but REMOTE and XS11-XS50 (L4450-4477)
        if (args.size() != 2) return {Bds5Error{82, joined(entries), 0}};
        const auto ref = cat::findVariable(args[0].text);
        if (!ref || !ref->info->isSwitch) return {Bds5Error{83, args[0].text, 0}};
        if (args[0].text == "REMOTE" || (ref->info->name == "XS" && ref->index > 10))
            return {Bds5Error{89, args[0].text, 0}};
        const auto state = parseConstant(args[1].text);
        if (!state || (*state != 0 && *state != 1)) return {Bds5Error{83, args[1].text, 0}};
        return {std::nullopt, Flow::Hold, 0, *state == 1, args[0].text};
    }
    // P/PS end with CR LF, R/RS with CR only (refresh a line), v3 PA/PAS with nothing (L4191-4378, L9305).
    case Word::P:
    case Word::PS: return {print(entries, "\r\n", w == Word::PS, out)};
    case Word::R:
    case Word::RS: return {print(entries, "\r", w == Word::RS, out)};
    case Word::PA:
    case Word::PAS: return {print(entries, "", w == Word::PAS, out)};
    case Word::Input: return input(entries, out);
    case Word::Err: return {errCommand(entries, out)};
    case Word::Dump: return dump(entries, out);
    case Word::En:
    case Word::Dis:
        if (!args.empty()) return {Bds5Error{82, args.front().text, 0}};
        if (w == Word::En && m_state.variables.read("REMOTE").value_or(1) == 0) // needs REMOTE (L7183)
            return {Bds5Error{10, "EN", 0}};
        m_state.enabled = w == Word::En;
        if (m_state.enabled) { // EN clears the FAULT latch and the macro memory (L2111-2115, L2522)
            m_state.variables.set("FAULT", 0);
            m_state.motion.resetMacro();
        } else
            m_state.motion.halt();
        return {};
    case Word::Record: return record(entries, out);
    case Word::Tune: return tune(entries);
    case Word::Rand: return random(entries);
    case Word::Trace: return realTimeTrace(entries, out);
    case Word::Motor: { // the present motor drive combination (L6923-6927); the layout is chosen
        if (!args.empty()) return {Bds5Error{82, args.front().text, 0}};
        const physics::ReferenceMotor* motor = physics::findReferenceMotor(m_state.motorName);
        out += "MOTOR: " + m_state.motorName;
        if (motor) out += " (" + std::string(motor->description) + ")";
        out += ", 12-BIT R/D, VMAX " + std::to_string(readValue("VMAX").value_or(0)) + " RPM\r\n";
        return {};
    }
    case Word::Motion: return motionCommand(entries, context);
    case Word::ClearX: // v3: zero "all user registers and user flags", X1-X750 and XS1-XS50 (L9308)
        // X251-X750 are zeroed whether EXTDX is on or not: while it is off they do not exist and hold 0.
        for (const char* family : {"X1", "XS1"}) {
            const cat::VariableInfo* v = cat::findVariable(family)->info;
            for (int i = v->firstIndex; i <= cat::highestIndex(*v); ++i)
                m_state.variables.set(cat::VariableRef{v, i}, 0);
        }
        return {};
    case Word::Other: break;
    }
    // X(Xn) = expr with blanks around '=' (L9548, the cam test's "X(X1) = (X1-100)*100") is an assignment too.
    if (word.find('=') != std::string::npos || word.starts_with("X(") || cat::findVariable(word))
        return {assign(entries)};
    // Known commands whose behaviour is not simulated yet answer as an unknown instruction would.
    return {Bds5Error{80, word, 0}};
}

// DUMP [VERSION|TL]: interactive, drive disabled (ERR 51) (L5396-5414).
Outcome Bds5Interpreter::dump(std::span<const Entry> entries, std::string& out) {
    const auto args = entries.subspan(1);
    if (args.size() > 1) return {Bds5Error{82, args[1].text, 0}};
    const std::string what = args.empty() ? std::string() : args.front().text;
    if (what == "VERSION") {
        out += dumpVersion();
        return {};
    }
    if (!what.empty() && what != "TL") return {Bds5Error{83, what, 0}};
    if (m_state.enabled) return {Bds5Error{51, joined(entries), 0}};
    out += what == "TL" ? dumpLoopGains(m_state) : dumpAll(m_state);
    return {};
}

// ? cond [TRUE-instr] [: FALSE-instr] — either instruction may be omitted but not both (L3836-3900).
Outcome Bds5Interpreter::quickIf(std::span<const Entry> entries, const ExecContext& context, std::string& out) {
    if (entries.size() < 5) return {Bds5Error{82, joined(entries), 0}};
    std::optional<Bds5Error> error;
    const auto c = condition(entries.subspan(1, 3), error);
    if (!c) return {error};
    auto rest = entries.subspan(4);
    std::size_t colon = 0;
    while (colon < rest.size() && rest[colon].text != ":") ++colon;
    auto whenTrue = rest.subspan(0, colon);
    auto whenFalse = colon < rest.size() ? rest.subspan(colon + 1) : std::span<const Entry>{};
    if (whenTrue.empty() && whenFalse.empty()) return {Bds5Error{82, joined(entries), 0}};
    for (const auto& part : {whenTrue, whenFalse})
        if (!part.empty() && part.front().text == "TIL") return {Bds5Error{117, part.front().text, 0}};
    const auto chosen = *c ? whenTrue : whenFalse;
    if (chosen.empty()) return {};
    ExecContext inner = context;
    inner.nested = true;
    return dispatch(chosen, inner, out);
}

// TIL cond [instr] — while cond is false, run instr (if any) and come back to this line (L3902-3936).
Outcome Bds5Interpreter::til(std::span<const Entry> entries, const ExecContext& context, std::string& out) {
    if (entries.size() < 4) return {Bds5Error{82, joined(entries), 0}};
    std::optional<Bds5Error> error;
    const auto c = condition(entries.subspan(1, 3), error);
    if (!c) return {error};
    if (*c) return {};
    const auto instruction = entries.subspan(4);
    if (!instruction.empty()) {
        if (instruction.front().text == "TIL" || instruction.front().text == "?")
            return {Bds5Error{117, instruction.front().text, 0}};
        ExecContext nested = context;
        nested.nested = true;
        Outcome inner = dispatch(instruction, nested, out);
        if (inner.error || inner.flow != Flow::Next) return inner;
    }
    return {std::nullopt, Flow::Repeat};
}

// GOTO|GOSUB|RUN <label> | <Xn> — the target label number; the executor checks that it exists.
Outcome Bds5Interpreter::jump(Flow flow, std::span<const Entry> entries) {
    if (entries.size() != 2) return {Bds5Error{82, joined(entries), 0}};
    // The manual writes targets both as "GOTO 3" and "GOTO 3$" (L3771-3811): accept the '$'.
    std::string_view target = entries[1].text;
    if (target.size() > 1 && target.back() == '$') target.remove_suffix(1);
    const ExpressionResult r = evaluate(target, [this](auto n) { return readValue(n); });
    if (r.error) return {Bds5Error{r.error, entries[1].text, 0}};
    if (r.value < 0 || r.value > kMaxLabel) return {Bds5Error{83, entries[1].text, 0}};
    return {std::nullopt, flow, r.value};
}

std::optional<bool> Bds5Interpreter::condition(std::span<const Entry> entries, std::optional<Bds5Error>& error) const {
    if (entries.size() < 3) {
        error = Bds5Error{82, entries.empty() ? std::string() : entries.front().text, 0};
        return std::nullopt;
    }
    const std::string& op = entries[1].text;
    if (op != "GT" && op != "GE" && op != "LT" && op != "LE" && op != "EQ" && op != "NE") {
        error = Bds5Error{83, op, 0};
        return std::nullopt;
    }
    const auto reader = [this](auto n) { return readValue(n); };
    const ExpressionResult a = evaluate(entries[0].text, reader);
    if (a.error) {
        error = Bds5Error{a.error, entries[0].text, 0};
        return std::nullopt;
    }
    const ExpressionResult b = evaluate(entries[2].text, reader);
    if (b.error) {
        error = Bds5Error{b.error, entries[2].text, 0};
        return std::nullopt;
    }
    if (op == "GT") return a.value > b.value;
    if (op == "GE") return a.value >= b.value;
    if (op == "LT") return a.value < b.value;
    if (op == "LE") return a.value <= b.value;
    if (op == "EQ") return a.value == b.value;
    return a.value != b.value;
}

// The status word of PS/RS/PAS (Table 4.4 L4347-4356; v3 CAMMING when GEAR and CAM are on, L9468). Its
// place is not in the seed; chosen: after one space. When several words fit the seed gives no order;
// chosen: FAULT, then the enable chain (OFF, READY), then the mode the command comes from (CAMMING, GEAR)
// before the motion under way (JOG, PROFILE); ACTIVE is "active, but no motion".
std::string Bds5Interpreter::statusWord() const {
    if (m_state.variables.read("FAULT").value_or(0)) return "FAULT";
    if (!m_state.enabled) return "OFF";
    if (!m_state.variables.read("REMOTE").value_or(1)) return "READY";
    const bool gear = m_state.variables.read("GEAR").value_or(0) != 0;
    if (gear && m_state.motion.camming()) return "CAMMING";
    if (gear) return "GEAR";
    if (m_state.motion.jogging()) return "JOG";
    if (m_state.motion.moving()) return "PROFILE";
    return "ACTIVE";
}

// P item item ... — texts verbatim, expressions formatted, no separators added (L4191-4358).
std::optional<Bds5Error> Bds5Interpreter::print(std::span<const Entry> entries, std::string_view terminator,
                                                bool status, std::string& out) {
    if (entries.size() < 2 && !status) return Bds5Error{82, entries.front().text, 0};
    std::string text;
    for (const Entry& item : entries.subspan(1)) {
        if (item.quoted) {
            text += expandControlCharacters(std::string_view(item.text).substr(1, item.text.size() - 2));
            continue;
        }
        const auto parts = splitFormat(item.text);
        if (!parts) return Bds5Error{79, item.text, 0};
        const ExpressionResult r = evaluate(parts->first, [this](auto n) { return readValue(n); });
        if (r.error) return Bds5Error{r.error, item.text, 0};
        const auto formatted = formatValue(r.value, parts->second);
        if (!formatted) return Bds5Error{79, item.text, 0};
        text += *formatted;
    }
    if (status) text += (text.empty() ? "" : " ") + statusWord();
    out += text;
    out += terminator;
    return std::nullopt;
}

// INPUT "text" VAR[d] [min max] — program only; limits both or neither, clipped to the variable's own;
// [d] scales the typed number by 10^d; [.d] is ERR 79 (L4380-4436, L6785-6802).
Outcome Bds5Interpreter::input(std::span<const Entry> entries, std::string& out) {
    if (entries.size() != 3 && entries.size() != 5) return {Bds5Error{82, joined(entries), 0}};
    if (!entries[1].quoted) return {Bds5Error{83, entries[1].text, 0}};
    InputRequest request;
    std::string target = entries[2].text;
    if (const auto open = target.find('['); open != std::string::npos) {
        const std::string digits = target.substr(open + 1, target.size() - open - 2);
        if (target.back() != ']' || digits.empty() || digits.size() > 1 || !std::isdigit((unsigned char)digits[0]))
            return {Bds5Error{79, target, 0}};
        request.decimals = digits[0] - '0';
        target.resize(open);
    }
    const auto ref = cat::findVariable(target);
    if (!ref || !m_state.variables.exists(*ref)) return {Bds5Error{80, target, 0}};
    if (ref->info->write == cat::WriteCondition::Never) return {Bds5Error{81, target, 0}};
    if (ref->info->write == cat::WriteCondition::Factory) return {Bds5Error{111, target, 0}};
    request.variable = target;
    request.minimum = cat::minimumOf(*ref->info);
    request.maximum = cat::maximumOf(*ref->info);
    if (entries.size() == 5) {
        const auto reader = [this](auto n) { return readValue(n); };
        const ExpressionResult lo = evaluate(entries[3].text, reader);
        if (lo.error) return {Bds5Error{lo.error, entries[3].text, 0}};
        const ExpressionResult hi = evaluate(entries[4].text, reader);
        if (hi.error) return {Bds5Error{hi.error, entries[4].text, 0}};
        request.minimum = std::max<std::int64_t>(request.minimum, lo.value);
        request.maximum = std::min<std::int64_t>(request.maximum, hi.value);
    }
    request.text = expandControlCharacters(std::string_view(entries[1].text).substr(1, entries[1].text.size() - 2));
    out += request.text;
    Outcome o{std::nullopt, Flow::Input};
    o.input = std::move(request);
    return o;
}

// assignment := VAR '=' expr | VAR expr | VAR '=' expr (with blanks around '=')
std::optional<Bds5Error> Bds5Interpreter::assign(std::span<const Entry> entries) {
    std::string name;
    std::string expression;
    const std::string& first = entries.front().text;
    const std::size_t eq = first.find('=');
    std::size_t next = 1;
    if (eq != std::string::npos) {
        name = first.substr(0, eq);
        expression = first.substr(eq + 1);
    } else {
        name = first;
        if (next < entries.size() && entries[next].text == "=") ++next;
    }
    if (expression.empty()) {
        if (next >= entries.size()) return Bds5Error{82, first, 0};
        expression = entries[next].text.starts_with("=") ? entries[next].text.substr(1) : entries[next].text;
        ++next;
    }
    if (next != entries.size()) return Bds5Error{82, entries[next].text, 0};
    if (name.starts_with("X(") && name.back() == ')') { // X(Xn) = expr (L9548)
        const ExpressionResult index =
            evaluate(name.substr(2, name.size() - 3), [this](auto n) { return readValue(n); });
        if (index.error) return Bds5Error{index.error, name, 0};
        // Pointing at no user variable is ERR 85 (L7390-7394): X251-X750 count only while EXTDX is on.
        if (index.value < 1 || !m_state.variables.exists("X" + std::to_string(index.value)))
            return Bds5Error{85, name, 0};
        name = "X" + std::to_string(index.value);
    }
    if (!m_state.variables.exists(name)) return Bds5Error{80, name, 0};
    const ExpressionResult r = evaluate(expression, [this](auto n) { return readValue(n); });
    if (r.error) return Bds5Error{r.error, expression, 0};
    if (name == "GATEMODE" && r.value == 1 && m_state.motion.moving()) // not while motion is commanded (L5957)
        return Bds5Error{57, name, 0};
    // PNUM, PDEN and PROTARY cannot change with ROTARY on (L5258); the manual names no error, ERR 59 NOT
    // w/ROTARY is the one that says why.
    if ((name == "PNUM" || name == "PDEN" || name == "PROTARY") && m_state.variables.read("ROTARY").value_or(0) != 0)
        return Bds5Error{59, name, 0};
    if (name == "ROTARY" && r.value == 1) { // PFB must already lie in 0..PROTARY (ERR 61, L7322)
        const auto pfb = m_state.variables.read("PFB").value_or(0);
        if (pfb < 0 || pfb > m_state.variables.read("PROTARY").value_or(0)) return Bds5Error{61, name, 0};
    }
    if (name == "PFB") { // PFB=p is NORM p (L2449-2483)
        std::optional<Bds5Error> error;
        const auto basic = m_state.variables.toBasic(cat::UnitClass::Position, r.value);
        if (!basic) return Bds5Error{96, expression, 0};
        if (const int e = m_state.motion.normalize(*basic)) return Bds5Error{e, name, 0};
        m_state.servo.normalize(*basic);
        m_state.variables.set("PFB", std::int32_t(*basic));
        m_state.variables.set("PCMD", std::int32_t(*basic));
        return std::nullopt;
    }
    const auto extended = name == "EXTDX" ? m_state.variables.read(name) : std::nullopt;
    if (const int error = m_state.variables.write(name, r.value, m_state.enabled))
        return Bds5Error{error, error == 83 ? expression : name, 0};
    if (extended && r.value != *extended) switchExtendedRegisters(m_state);
    if (name == "CAPDIR") m_state.variables.set("CAP", 0);                // writing CAPDIR turns CAP off (L2627)
    if (name == "GEAR" && r.value == 1) m_state.variables.set("VOFF", 0); // VOFF is reset by GEAR ON (L3031)
    return std::nullopt;
}

// ERR <n> | ERR HIST | ERR CLR (L6110-6148, L6711-6727)
std::optional<Bds5Error> Bds5Interpreter::errCommand(std::span<const Entry> entries, std::string& out) {
    if (entries.size() != 2) return Bds5Error{82, entries.front().text, 0};
    const std::string& arg = entries[1].text;
    if (arg == "CLR") {
        m_state.errorHistory.clear();
        return std::nullopt;
    }
    if (arg == "HIST") {
        // The seed does not print the history format; chosen: one "ERR n MESSAGE" line per entry.
        for (const int code : m_state.errorHistory) {
            const cat::ErrorInfo* info = cat::findError(code);
            out += "ERR " + std::to_string(code) + " " + std::string(info ? info->message : "UNKNOWN") + "\r\n";
        }
        return std::nullopt;
    }
    const ExpressionResult r = evaluate(arg, [this](auto n) { return readValue(n); });
    if (r.error) return Bds5Error{r.error, arg, 0};
    if (r.value < 1 || r.value > 999) return Bds5Error{83, arg, 0};
    const cat::ErrorInfo* info = cat::findError(r.value);
    out += info ? "ERR " + std::to_string(r.value) + " " + std::string(info->message) + "\r\n"
                : std::string("ERROR NOT FOUND\r\n");
    return std::nullopt;
}

std::string formatError(const Bds5Error& error) {
    std::string text;
    appendError(text, error);
    return text;
}

// Appends in place: every flooded line the fuzzer types is answered with one of these (issue 20).
void appendError(std::string& out, const Bds5Error& error) {
    const cat::ErrorInfo* info = cat::findError(error.code);
    const std::string_view message = info ? info->message : "UNKNOWN";
    constexpr std::size_t kMessageColumn = 40; // the message starts at character 40 (L6036-6060)
    const std::size_t start = out.size();
    out.reserve(start + kMessageColumn + error.entry.size() + message.size() + 16);
    const auto appendNumber = [&out](int n) {
        char digits[16];
        const auto [end, ec] = std::to_chars(digits, digits + sizeof digits, n);
        out.append(digits, end);
    };
    out += "ERR ";
    appendNumber(error.code);
    if (error.line > 0) {
        out += " LINE ";
        appendNumber(error.line);
    }
    if (error.entry.empty() && error.line == 0) { // asynchronous fault
        out += ' ';
        out += message;
        return;
    }
    out += " '";
    out += error.entry;
    out += '\'';
    const std::size_t head = out.size() - start;
    out.append(head < kMessageColumn ? kMessageColumn - head : 1, ' ');
    out += message;
}

} // namespace drive_core::bds5
