// BDS5 expression evaluator: a small recursive-descent parser that evaluates as it goes.
#include "bds5_expression.h"

#include <cctype>
#include <charconv>
#include <string>

namespace drive_core::bds5 {

namespace {

constexpr std::int64_t kMax = INT32_MAX;
constexpr std::int64_t kMin = INT32_MIN;

bool isDigit(char c) {
    return std::isdigit(static_cast<unsigned char>(c)) != 0;
}
bool isAlnum(char c) {
    return std::isalnum(static_cast<unsigned char>(c)) != 0;
}

struct Failure {
    int error;
};

class Evaluator {
public:
    Evaluator(std::string_view text, const VariableReader& read) : m_text(text), m_read(read) {}

    std::int32_t run() {
        const std::int64_t v = sum();
        if (m_pos != m_text.size()) throw Failure{m_text[m_pos] == ')' ? 95 : 83};
        return std::int32_t(v);
    }

private:
    // sum := product { ('+' | '-' | '!') product }
    std::int64_t sum() {
        std::int64_t left = product();
        while (m_pos < m_text.size()) {
            const char op = m_text[m_pos];
            if (op != '+' && op != '-' && op != '!') break;
            ++m_pos;
            const std::int64_t right = product();
            left = op == '+' ? checked(left + right) : op == '-' ? checked(left - right) : (left | right);
        }
        return left;
    }

    // product := factor { ('*' | '/' | '&') factor }
    std::int64_t product() {
        std::int64_t left = factor();
        while (m_pos < m_text.size()) {
            const char op = m_text[m_pos];
            if (op != '*' && op != '/' && op != '&') break;
            ++m_pos;
            const std::int64_t right = factor();
            if (op == '*')
                left = checked(left * right);
            else if (op == '&')
                left = left & right;
            else
                left = divideRounded(left, right);
        }
        return left;
    }

    // factor := ['-'] ( constant | variable | 'X(' sum ')' | '(' sum ')' )
    std::int64_t factor() {
        if (m_pos >= m_text.size()) throw Failure{83};
        if (m_text[m_pos] == '-') {
            ++m_pos;
            return checked(-factor());
        }
        if (m_text[m_pos] == '(') return parenthesised();
        if (m_text[m_pos] == ')') throw Failure{95};
        const std::size_t start = m_pos;
        while (m_pos < m_text.size() && isAlnum(m_text[m_pos])) ++m_pos;
        const std::string_view word = m_text.substr(start, m_pos - start);
        if (word.empty()) throw Failure{83};
        if (isDigit(word.front())) {
            const auto constant = parseConstant(word);
            if (!constant) throw Failure{83};
            return *constant;
        }
        if (word == "X" && m_pos < m_text.size() && m_text[m_pos] == '(') { // indirect X(Xn)
            const std::int64_t index = parenthesised();
            // A user variable that does not exist is ERR 85 (L7390-7394): past X250, or past X750 with
            // EXTDX on (v3) — the reader knows which the drive has now.
            if (index < 1) throw Failure{85};
            const auto v = m_read("X" + std::to_string(index));
            if (!v) throw Failure{85};
            return *v;
        }
        if (const auto constant = parseConstant(word)) return *constant; // ON OFF Y N
        return readVariable(std::string(word));
    }

    std::int64_t parenthesised() {
        ++m_pos; // '('
        if (++m_depth > 2) throw Failure{94};
        const std::int64_t v = sum();
        if (m_pos >= m_text.size() || m_text[m_pos] != ')') throw Failure{95};
        ++m_pos;
        --m_depth;
        return v;
    }

    std::int64_t readVariable(const std::string& name) {
        const auto v = m_read(name);
        if (!v) throw Failure{80};
        return *v;
    }

    static std::int64_t checked(std::int64_t v) {
        if (v > kMax || v < kMin) throw Failure{93};
        return v;
    }

    // Division rounds to the nearest integer (53/100 -> 1, L1730); halves round away from zero
    // (the manual is silent on halves; chosen as what a programmer of the day would expect).
    static std::int64_t divideRounded(std::int64_t a, std::int64_t b) {
        if (b == 0) throw Failure{92};
        std::int64_t q = a / b;
        const std::int64_t r = a % b;
        if (2 * (r < 0 ? -r : r) >= (b < 0 ? -b : b)) q += ((a < 0) != (b < 0)) ? -1 : 1;
        return checked(q);
    }

    std::string_view m_text;
    const VariableReader& m_read;
    std::size_t m_pos = 0;
    int m_depth = 0;
};

} // namespace

std::optional<std::int32_t> parseConstant(std::string_view text) {
    if (text == "ON" || text == "Y") return 1;
    if (text == "OFF" || text == "N") return 0;
    bool negative = false;
    if (!text.empty() && (text.front() == '-' || text.front() == '+')) {
        negative = text.front() == '-';
        text.remove_prefix(1);
    }
    if (text.empty() || !isDigit(text.front())) return std::nullopt; // hex must start with a digit (L1680)
    int base = 10;
    if (text.back() == 'H') {
        base = 16;
        text.remove_suffix(1);
    }
    std::int64_t value = 0;
    const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), value, base);
    if (ec != std::errc{} || ptr != text.data() + text.size()) return std::nullopt;
    if (negative) value = -value;
    if (base == 16 && value > kMax && value <= 0xFFFFFFFFLL) value -= 0x100000000LL; // 0FFFFFFFFH is -1
    if (value > kMax || value < kMin) return std::nullopt;
    return std::int32_t(value);
}

ExpressionResult evaluate(std::string_view expression, const VariableReader& read) {
    try {
        return {Evaluator(expression, read).run(), 0};
    } catch (const Failure& f) {
        return {0, f.error};
    }
}

} // namespace drive_core::bds5
