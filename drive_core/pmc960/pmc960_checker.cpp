// PMC-960 program diagnostics through the controller's own interpreter. Decisions (DECISIONS.md, "Program
// checker"): each line is read alone by a factory-fresh scratch controller in decimal input; a character
// the controller refuses is reported at its column.
#include "pmc960_checker.h"

#include "pmc960_interpreter.h"

#include "drive_core/catalog/pmc960_catalog.h"

#include <algorithm>
#include <cstdio>
#include <optional>
#include <set>

namespace drive_core::pmc960 {

namespace cat = catalog::pmc960;

namespace {

// Errors a line earns by its text alone (7.22, L2286-2384): syntax (A1 A2 A4 A5 AA, L2332-2342), ranges
// fixed by the manual (90-93 95 97, L2316-2323), labels and loop counters (C5 C6 C8, L2362-2365). The others
// depend on the controller's state when the line runs: motion and cam (80-8B, B1-B9, D8), the table (9A 9B
// 9C D3 D4; 98 99 with engineering units), the machine lines (Ex). #94 depends on the velocity range (L2320)
// and is kept only when the widest range refuses the speed too; #C2 is checked over the whole program.
const std::set<int> kTextErrors = {0x90, 0x91, 0x92, 0x93, 0x95, 0x97, 0xA1, 0xA2, 0xA4, 0xA5, 0xAA, 0xC5, 0xC6, 0xC8};
constexpr int kValueRange = 0x90;
constexpr int kAccelerationRange = 0x92;
constexpr int kVelocityRange = 0x94;
constexpr int kInvalidDesignator = 0xA2;
constexpr int kInvalidAddress = 0xA5;
constexpr int kBufferFull = 0xC1;
constexpr int kLabelUndefined = 0xC2;
// The scratch program's own label: a control character no editor stores (L1412), so no line can name it.
constexpr char kScratchLabel = '\x01';
constexpr std::int64_t kPastAnyDwell_us = 70'000'000; // D takes at most 65,535 ms (L1125)

std::string messageOf(int code) {
    const cat::ErrorInfo* e = cat::findError(code);
    return e ? std::string(e->message) : std::string();
}

// A line as the controller stores it: its characters and the editor column each came from.
struct StoredLine {
    int line = 0;
    std::string text;
    std::vector<int> columns;
    int end = 0; // the column of its <cr>: after the last stored character

    int columnOf(std::size_t at) const { return at < columns.size() ? columns[at] : end; }
};

struct Refusal {
    int code = 0;
    std::size_t at = 0;  // index into the stored line; its size() is the <cr>
    std::string command; // the command being read when the character came
};

struct LabelUse {
    char label = 0;
    std::size_t at = 0;
};

// The table a scratch controller reads with. Factory: decimal input (THC 00, L1836-1843), a resolver (THA
// 4096), 192 kHz. The others are tables a user may have, for the refusals that depend on them.
enum class ScratchTable {
    Factory,
    // Engineering units with TUS 0:0001 and TUV 65535: the largest user speed any table allows (48 kHz
    // range / 0.0001 Hz per unit), so a #94 here is a speed no table accepts.
    WidestVelocityRange,
    // THA 0: H ends at its direction (7.9.2, L1222), where a resolver's H waits for <cr> (7.9.1, L1197).
    Encoder,
};

// A controller fresh from its table, write-enabled (SW1) with the drive enabled (SM2), so T and motion
// commands check their values instead of refusing for #D3 or #B6. The motion is brought to rest before
// every character and every wait is satisfied at once: what the line asks of the motion is the
// controller's state at run time, not the text's.
class ScratchController final : public Pmc960Sink {
public:
    explicit ScratchController(ScratchTable table) : m_interpreter(m_state, *this) {
        m_state.reg.writeEnable = 1;
        if (table == ScratchTable::WidestVelocityRange) {
            m_state.table.set("THC", 0x10);
            m_state.table.set("TUS", 1);
            m_state.table.set("TUV", 65535);
        }
        if (table == ScratchTable::Encoder) m_state.table.set("THA", 0);
    }

    struct Reading {
        std::optional<Refusal> refusal;
        std::vector<LabelUse> labels; // labels B, F and L name, which the program must define
    };

    // Executes line as a program line, one character at a time.
    Reading read(const std::string& line) {
        Reading reading;
        m_state.program.edit() = std::string{'@', kScratchLabel, '\r'} + line + '\r';
        m_interpreter.start(kScratchLabel);
        m_interpreter.run(3); // the scratch label line
        std::size_t at = 0;
        while (m_interpreter.running() && at <= line.size()) {
            if (m_interpreter.wait() != Pmc960Wait::None) {
                settle();
                continue;
            }
            rest();
            const std::string command = m_interpreter.command();
            const bool labelDue = (command == "B" || command == "F" || command == "L") && m_interpreter.label() == 0;
            m_raised = 0;
            if (m_interpreter.run(1) == 0) break;
            if (m_raised != 0) {
                reading.refusal = Refusal{m_raised, at, command};
                break;
            }
            // B| names the label TLB holds when the branch runs (L1081), not one the text gives.
            const bool vector = command == "B" && at < line.size() && line[at] == '|';
            if (labelDue && m_interpreter.label() != 0 && !vector)
                reading.labels.push_back({m_interpreter.label(), at});
            ++at;
        }
        return reading;
    }

private:
    void send(std::string_view) override {}
    void raise(int code) override {
        m_raised = code;
        m_interpreter.abort(); // as the controller: the command and the program end (L2288)
    }
    void commandDone() override {}
    void enterEditor(std::size_t) override {}
    void listProgram(bool) override {}
    void stream(std::string, int) override {}
    void softwareReset() override { m_interpreter.abort(); } // N*: nothing after it runs
    void autobaud() override {}

    void rest() {
        m_state.motion.reset();
        m_state.motion.setMode(2);
    }

    void settle() {
        const Pmc960Wait wait = m_interpreter.wait();
        // U waits at its <cr> (L2128-2138), single step at a label: the line has been read.
        if (wait == Pmc960Wait::Until || wait == Pmc960Wait::SingleStep) return m_interpreter.abort();
        if (wait == Pmc960Wait::Dwell) m_now_us += kPastAnyDwell_us;
        rest(); // , ; ^ and R wait on the motion: at rest they are satisfied
        m_interpreter.poll(m_now_us);
        if (m_interpreter.wait() != Pmc960Wait::None) m_interpreter.abort();
    }

    Pmc960State m_state;
    Pmc960Interpreter m_interpreter;
    int m_raised = 0;
    std::int64_t m_now_us = 0;
};

// The decimal digits the controller read just before the refused character.
std::string digitsBefore(const std::string& line, std::size_t at) {
    std::size_t from = std::min(at, line.size());
    while (from > 0 && line[from - 1] >= '0' && line[from - 1] <= '9') --from;
    return line.substr(from, std::min(at, line.size()) - from);
}

// Whether another table refuses the line at the same character with the same code.
bool refusedWith(ScratchTable table, const Refusal& r, const std::string& line) {
    const auto again = ScratchController(table).read(line).refusal;
    return again && again->code == r.code && again->at == r.at;
}

bool textError(const Refusal& r, const std::string& line) {
    // A0: the external (slave) range takes a rate of 0-65,534 (5.7, L900), the internal ones 1-65,535
    // (L885-895); only a rate past 65,535 is out of every range.
    if (r.code == kAccelerationRange) {
        const std::string digits = digitsBefore(line, r.at);
        return digits.empty() || digits.find_first_not_of('0') != std::string::npos;
    }
    // THI's ID: 21H-5AH in THI's damaged text (L1918), any printable but space in A5's (L2336; digest
    // §11.2 #19). Only a missing ID is refused by both.
    if (r.code == kInvalidAddress) return r.at >= line.size();
    if (r.code == kVelocityRange) return refusedWith(ScratchTable::WidestVelocityRange, r, line);
    if (!kTextErrors.count(r.code)) return false;
    const char c = r.at < line.size() ? line[r.at] : '\r';
    // TG<register><value>+ adds to the register's present value (L1741-1773): its range is the table's.
    if (r.code == kValueRange && r.command.rfind("TG", 0) == 0 && (c == '+' || c == '-')) return false;
    // Contour ticks G and H (L2202) are not simulated (pmc960_commands.cpp) and 8 is in 7.16's 0-9, A-H
    // though not in 7.21's table (digest §11.2 #35): the interpreter's refusal is not the controller's.
    if (r.code == kInvalidDesignator && r.command == "R" && std::string_view("8GgHh").find(c) != std::string_view::npos)
        return false;
    return true;
}

bool reported(const Refusal& r, const std::string& line) {
    if (!textError(r, line)) return false;
    if (r.command == "H") return refusedWith(ScratchTable::Encoder, r, line); // what follows H's direction
    return true;
}

std::vector<std::string_view> editorLines(std::string_view text) {
    std::vector<std::string_view> lines;
    std::size_t start = 0;
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (text[i] != '\r' && text[i] != '\n') continue;
        lines.push_back(text.substr(start, i - start));
        if (text[i] == '\r' && i + 1 < text.size() && text[i + 1] == '\n') ++i;
        start = i + 1;
    }
    if (start < text.size()) lines.push_back(text.substr(start));
    return lines;
}

// What the download sends (serialport/pmc960_download.cpp) and the program-mode editor keeps: spaces and
// tabs are dropped, an empty line is not sent; the editor stores printing ASCII and rings the BELL for
// anything else (L1412); '}' in column 1 erases the buffer from there to the end and leaves (L930, the
// OCR's ')' read as '}').
std::vector<StoredLine> storedLines(std::string_view text, std::vector<Diagnostic>& out) {
    std::vector<StoredLine> stored;
    const std::vector<std::string_view> lines = editorLines(text);
    for (int n = 1; n <= int(lines.size()); ++n) {
        const std::string_view raw = lines[std::size_t(n - 1)];
        StoredLine s{n, {}, {}, 0};
        bool sent = false;
        for (int column = 0; column < int(raw.size()); ++column) {
            const auto c = static_cast<unsigned char>(raw[std::size_t(column)]);
            if (c == ' ' || c == '\t') continue;
            sent = true;
            s.end = column + 1;
            if (c < 0x21 || c > 0x7E) {
                char byte[8];
                std::snprintf(byte, sizeof byte, "%02X", unsigned(c));
                out.push_back({n, column, 0,
                               std::string("not stored: the program editor takes printing ASCII characters only "
                                           "and rings the bell for byte ") +
                                   byte + "H"});
                continue;
            }
            s.text += char(c);
            s.columns.push_back(column);
        }
        if (!sent) continue;
        if (!s.text.empty() && s.text.front() == '}') {
            out.push_back({n, s.columns.front(), 0,
                           "'}' at the start of a line erases the program buffer from there to the end and leaves "
                           "the editor"});
            continue;
        }
        stored.push_back(std::move(s));
    }
    return stored;
}

// #C1 where the first byte past the buffer's 1,940 (L982, digest §1) would go: the editor refuses it (L2358).
std::optional<Diagnostic> capacity(const std::vector<StoredLine>& lines) {
    std::size_t total = 0;
    for (const StoredLine& l : lines) total += l.text.size() + 1;
    if (total <= Pmc960Program::kCapacity) return std::nullopt;
    std::size_t bytes = 0;
    for (const StoredLine& l : lines) {
        if (bytes + l.text.size() + 1 > Pmc960Program::kCapacity) {
            const std::size_t first = Pmc960Program::kCapacity - bytes; // the first byte that does not fit
            return Diagnostic{l.line, l.columnOf(first), kBufferFull,
                              messageOf(kBufferFull) + ": the program takes " + std::to_string(total) + " of its " +
                                  std::to_string(Pmc960Program::kCapacity) + " bytes"};
        }
        bytes += l.text.size() + 1;
    }
    return std::nullopt;
}

} // namespace

std::vector<Diagnostic> checkProgram(std::string_view text) {
    std::vector<Diagnostic> out;
    const std::vector<StoredLine> lines = storedLines(text, out);
    if (const auto full = capacity(lines)) out.push_back(*full);

    // Label search finds "@<label>" at the start of a stored line (L1026-1057, pmc960_program.h).
    std::set<char> defined;
    for (const StoredLine& l : lines)
        if (l.text.size() >= 2 && l.text[0] == '@') defined.insert(l.text[1]);

    for (const StoredLine& l : lines) {
        const ScratchController::Reading reading = ScratchController(ScratchTable::Factory).read(l.text);
        if (reading.refusal && reported(*reading.refusal, l.text)) {
            out.push_back(
                {l.line, l.columnOf(reading.refusal->at), reading.refusal->code, messageOf(reading.refusal->code)});
            continue;
        }
        // B, F and L search for their label when they jump (L1075-1091, L1151-1163, L1300-1340) and give #C2
        // if no line defines it (L2359). Reported whatever the condition or count: the jump is what the line
        // is for.
        for (const LabelUse& use : reading.labels)
            if (!defined.count(use.label))
                out.push_back({l.line, l.columnOf(use.at), kLabelUndefined,
                               messageOf(kLabelUndefined) + ": no line starts with @" + std::string(1, use.label)});
    }
    std::stable_sort(out.begin(), out.end(), [](const Diagnostic& a, const Diagnostic& b) {
        return a.line != b.line ? a.line < b.line : a.column < b.column;
    });
    return out;
}

} // namespace drive_core::pmc960
