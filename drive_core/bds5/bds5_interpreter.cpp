// BDS5 instruction execution (interactive subset; the full language grows here, see issue 3).
#include "bds5_interpreter.h"

#include "bds5_expression.h"
#include "bds5_printer.h"
#include "drive_core/catalog/bds5_catalog.h"

namespace drive_core::bds5 {

namespace cat = catalog::bds5;

void logError(Bds5State& state, int code) {
    state.errorHistory.push_front(code);
    while (state.errorHistory.size() > kErrorHistorySize) state.errorHistory.pop_back();
}

namespace {

ExpressionResult evaluateIn(const Bds5State& state, std::string_view text) {
    return evaluate(text, [&state](std::string_view name) { return state.variables.read(name); });
}

// "VFB[5.3]" -> expression "VFB", format "5.3"; nullopt when the brackets are malformed.
std::optional<std::pair<std::string_view, std::string_view>> splitFormat(std::string_view item) {
    const std::size_t open = item.find('[');
    if (open == std::string_view::npos) return std::pair{item, std::string_view{}};
    if (item.back() != ']' || open == 0) return std::nullopt;
    return std::pair{item.substr(0, open), item.substr(open + 1, item.size() - open - 2)};
}

} // namespace

std::optional<Bds5Error> Bds5Interpreter::execute(const LexedLine& line, std::string& out) {
    if (line.entries.empty()) return std::nullopt;
    if (int(line.entries.size()) > kMaxEntries) return Bds5Error{82, line.entries.back().text, 0};
    const Entry& first = line.entries.front();
    const std::string& word = first.text;

    if (word == "P") return print(line, 1, true, out);
    if (word == "PA") return print(line, 1, false, out);
    if (word == "ERR") return errCommand(line, out);
    if (word == "EN") {
        m_state.enabled = true;
        return std::nullopt;
    }
    if (word == "DIS" || word == "K") {
        m_state.enabled = false;
        return std::nullopt;
    }
    // Assignment: VAR=expr, VAR expr, VAR = expr (L1437-1448).
    if (word.find('=') != std::string::npos || cat::findVariable(word)) return assign(line);
    // Known commands whose behaviour is not simulated yet answer as an unknown instruction would.
    return Bds5Error{80, word, 0};
}

// P item item ... — texts verbatim, expressions formatted, no separators added (L4191-4358).
std::optional<Bds5Error> Bds5Interpreter::print(const LexedLine& line, std::size_t first, bool terminate,
                                                std::string& out) {
    if (line.entries.size() <= first) return Bds5Error{82, line.entries.front().text, 0};
    std::string text;
    for (std::size_t i = first; i < line.entries.size(); ++i) {
        const Entry& item = line.entries[i];
        if (item.quoted) {
            text += expandControlCharacters(std::string_view(item.text).substr(1, item.text.size() - 2));
            continue;
        }
        const auto parts = splitFormat(item.text);
        if (!parts) return Bds5Error{79, item.text, 0};
        const ExpressionResult r = evaluateIn(m_state, parts->first);
        if (r.error) return Bds5Error{r.error, item.text, 0};
        const auto formatted = formatValue(r.value, parts->second);
        if (!formatted) return Bds5Error{79, item.text, 0};
        text += *formatted;
    }
    out += text;
    if (terminate) out += "\r\n";
    return std::nullopt;
}

// assignment := VAR '=' expr | VAR expr | VAR '=' | VAR '=' expr (with blanks around '=')
std::optional<Bds5Error> Bds5Interpreter::assign(const LexedLine& line) {
    std::string name;
    std::string expression;
    const std::string& first = line.entries.front().text;
    const std::size_t eq = first.find('=');
    std::size_t next = 1;
    if (eq != std::string::npos) {
        name = first.substr(0, eq);
        expression = first.substr(eq + 1);
    } else {
        name = first;
        if (next < line.entries.size() && line.entries[next].text == "=") ++next;
    }
    if (expression.empty()) {
        if (next >= line.entries.size()) return Bds5Error{82, first, 0};
        if (line.entries[next].text.starts_with("=")) expression = line.entries[next].text.substr(1);
        else expression = line.entries[next].text;
        ++next;
    }
    if (next != line.entries.size()) return Bds5Error{82, line.entries[next].text, 0};
    if (!cat::findVariable(name)) return Bds5Error{80, name, 0};
    const ExpressionResult r = evaluateIn(m_state, expression);
    if (r.error) return Bds5Error{r.error, expression, 0};
    if (const int error = m_state.variables.write(name, r.value, m_state.enabled))
        return Bds5Error{error, error == 83 ? expression : name, 0};
    return std::nullopt;
}

// ERR <n> | ERR HIST | ERR CLR (L6110-6148, L6711-6727)
std::optional<Bds5Error> Bds5Interpreter::errCommand(const LexedLine& line, std::string& out) {
    if (line.entries.size() != 2) return Bds5Error{82, line.entries.front().text, 0};
    const std::string& arg = line.entries[1].text;
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
    const ExpressionResult r = evaluateIn(m_state, arg);
    if (r.error) return Bds5Error{r.error, arg, 0};
    if (r.value < 1 || r.value > 999) return Bds5Error{83, arg, 0};
    const cat::ErrorInfo* info = cat::findError(r.value);
    out += info ? "ERR " + std::to_string(r.value) + " " + std::string(info->message) + "\r\n"
                : std::string("ERROR NOT FOUND\r\n");
    return std::nullopt;
}

std::string formatError(const Bds5Error& error) {
    const cat::ErrorInfo* info = cat::findError(error.code);
    const std::string message = info ? std::string(info->message) : "UNKNOWN";
    std::string head = "ERR " + std::to_string(error.code);
    if (error.line > 0) head += " LINE " + std::to_string(error.line);
    if (error.entry.empty() && error.line == 0) return head + " " + message; // asynchronous fault
    head += " '" + error.entry + "'";
    constexpr std::size_t kMessageColumn = 40; // the message starts at character 40 (L6036-6060)
    head.append(head.size() < kMessageColumn ? kMessageColumn - head.size() : 1, ' ');
    return head + message;
}

} // namespace drive_core::bds5
