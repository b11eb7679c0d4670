// BDS5 program diagnostics through the drive's own front end.
#include "bds5_checker.h"

#include "bds5_interpreter.h"
#include "bds5_lexer.h"
#include "bds5_program.h"

#include "drive_core/catalog/bds5_catalog.h"

#include <algorithm>
#include <cctype>
#include <optional>
#include <set>

namespace drive_core::bds5 {

namespace cat = catalog::bds5;

namespace {

// Errors a line earns by its text alone. The others (drive disabled, zero divide with variables at 0,
// buffers full, ...) depend on the drive's state when the line runs, so the editor stays silent on them.
const std::set<int> kTextErrors = {52, 53, 55, 63, 79, 80, 81, 82, 83, 87, 88, 89, 90, 94, 95, 111, 117};

std::string messageOf(int code) {
    const cat::ErrorInfo* e = cat::findError(code);
    return e ? std::string(e->message) : std::string();
}

Diagnostic diagnose(int line, const std::string& text, const Bds5Error& error) {
    Diagnostic d{line, 0, 0, error.code, error.entry, messageOf(error.code)};
    if (!error.entry.empty()) { // underline the entry the drive quotes, if it can be found
        std::string upper = text;
        for (char& c : upper) c = char(std::toupper(static_cast<unsigned char>(c)));
        const auto at = upper.find(error.entry);
        if (at != std::string::npos) {
            d.column = int(at);
            d.length = int(error.entry.size());
        }
    }
    if (error.code == 83 && error.entry.find(';') != std::string::npos)
        d.message += " (a ; comment needs a space before it)";
    return d;
}

// The switch of an alarm label "A$ I1 ON" must exist, be a switch, and not be REMOTE (ERR 89).
std::optional<Bds5Error> checkAlarmLabel(const LexedLine& l) {
    if (l.entries.size() != 3) return Bds5Error{82, l.entries.front().text, 0};
    const auto ref = cat::findVariable(l.entries[1].text);
    if (!ref || !ref->info->isSwitch) return Bds5Error{83, l.entries[1].text, 0};
    if (l.entries[1].text == "REMOTE") return Bds5Error{89, l.entries[1].text, 0};
    if (l.entries[2].text != "ON" && l.entries[2].text != "OFF") return Bds5Error{83, l.entries[2].text, 0};
    return std::nullopt;
}

} // namespace

std::vector<Diagnostic> checkProgram(const std::vector<std::string>& lines) {
    std::vector<Diagnostic> out;
    Bds5Program program;
    for (const std::string& l : lines) program.append(l);

    // A scratch drive: enabled, so that motion commands check their arguments rather than the drive.
    Bds5State scratch;
    scratch.enabled = true;
    Bds5Interpreter interpreter(scratch);
    // The program may be meant for a drive with v3's EXTDX on or off: X251-X750 exist only while it is on,
    // RECORD/PLAY and TRECORD/TPLAY only while it is off (L9295-9297, L9309). A line that fails is tried
    // again with EXTDX the other way, and flagged only if it fails there too.
    std::optional<Bds5State> other;
    const auto failsEitherWay = [&](const LexedLine& l, int n) {
        if (!other) {
            other.emplace();
            other->enabled = true;
        }
        other->variables.set("EXTDX", scratch.variables.read("EXTDX").value_or(0) ? 0 : 1);
        other->serialBusy = false;
        other->pendingInput.reset();
        std::string printed;
        const Outcome o = Bds5Interpreter(*other).execute(l.entries, ExecContext{Origin::Program, n}, printed);
        other->motion.halt();
        return o.error && kTextErrors.count(o.error->code);
    };
    for (int n = 1; n <= int(lines.size()); ++n) {
        const std::string& text = lines[std::size_t(n - 1)];
        if (int(text.size()) > kMaxLineLength)
            out.push_back({n, kMaxLineLength, 0, 0, {}, "line longer than the drive's 80 characters"});
        auto lexed = lexLine(text);
        if (auto* e = std::get_if<Bds5Error>(&lexed)) {
            out.push_back(diagnose(n, text, *e));
            continue;
        }
        const LexedLine& l = std::get<LexedLine>(lexed);
        // "J 10;BAD COMMENT": the ';' has no blank before it, so the comment is read as entries (L1355-1365).
        // The drive then rejects whatever it makes of them; the editor names the cause.
        const auto glued = std::find_if(l.entries.begin(), l.entries.end(),
                                        [](const Entry& e) { return !e.quoted && e.text.find(';') != std::string::npos; });
        if (glued != l.entries.end()) {
            out.push_back(diagnose(n, text, Bds5Error{83, glued->text, n}));
            continue;
        }
        if (l.entries.empty() || Bds5Program::numericLabel(l)) continue;
        if (const auto dedicated = Bds5Program::dedicatedLabel(l)) {
            const bool alarm = *dedicated == DedicatedLabel::AlarmA || *dedicated == DedicatedLabel::AlarmB ||
                               *dedicated == DedicatedLabel::AlarmC;
            if (alarm)
                if (const auto e = checkAlarmLabel(l)) out.push_back(diagnose(n, text, *e));
            continue;
        }
        if (int(l.entries.size()) > kMaxEntries) {
            out.push_back(diagnose(n, text, Bds5Error{82, l.entries.back().text, n}));
            continue;
        }
        std::string printed;
        scratch.serialBusy = false;
        scratch.pendingInput.reset();
        const Outcome o = interpreter.execute(l.entries, ExecContext{Origin::Program, n}, printed);
        if (o.error && kTextErrors.count(o.error->code) && failsEitherWay(l, n)) {
            out.push_back(diagnose(n, text, *o.error));
            continue;
        }
        const bool jump = o.flow == Flow::Goto || o.flow == Flow::Gosub || (o.flow == Flow::Run && o.target >= 0);
        // Only a constant target is known before the program runs; GOTO X5 is checked when it runs.
        const bool constant = l.entries.size() >= 2 && std::isdigit(static_cast<unsigned char>(l.entries[1].text[0]));
        if (jump && constant && !program.labelLine(o.target))
            out.push_back(diagnose(n, text, Bds5Error{70, l.entries[1].text, n}));
        scratch.motion.halt();
    }
    if (const auto e = program.check()) // labels used twice, labels after ERROR$ (what RUN reports)
        out.push_back(diagnose(e->line, lines[std::size_t(e->line - 1)], *e));
    return out;
}

} // namespace drive_core::bds5
