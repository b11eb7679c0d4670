// Executes one lexed BDS5 instruction against the drive's state. It never parses characters (the
// lexer and expression evaluator do) and never touches the UART (the drive frames the output).
#pragma once

#include "bds5_error.h"
#include "bds5_lexer.h"
#include "bds5_variable_store.h"

#include <deque>
#include <optional>
#include <string>

namespace drive_core::bds5 {

// State the interpreter reads and changes; owned by Bds5Drive.
struct Bds5State {
    Bds5VariableStore variables;
    std::deque<int> errorHistory; // ERR HIST, newest first, at most 20 entries (L6110-6148)
    bool enabled = false;         // drive enabled (EN) / inhibited (DIS, K)
};

constexpr std::size_t kErrorHistorySize = 20;

// Appends an error number to the history (newest first, 20 entries).
void logError(Bds5State& state, int code);

class Bds5Interpreter {
public:
    explicit Bds5Interpreter(Bds5State& state) : m_state(state) {}

    // Runs an interactive instruction. Output text (already with CR LF line ends) is appended to out.
    // Returns the error the drive reports, if any.
    std::optional<Bds5Error> execute(const LexedLine& line, std::string& out);

private:
    std::optional<Bds5Error> print(const LexedLine& line, std::size_t first, bool terminate, std::string& out);
    std::optional<Bds5Error> assign(const LexedLine& line);
    std::optional<Bds5Error> errCommand(const LexedLine& line, std::string& out);

    Bds5State& m_state;
};

} // namespace drive_core::bds5
