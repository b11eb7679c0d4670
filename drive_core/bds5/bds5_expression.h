// BDS5 integer expressions (L1702-1798, Table 3.3): 32-bit, '* / &' before '+ - !', left to right,
// division rounded to nearest, at most two levels of parentheses, no spaces, X(Xn) indirection.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string_view>

namespace drive_core::bds5 {

// Reads a variable by upper-case name ("X12", "VMAX"), in user units. Returns nullopt if the name is
// no variable the drive has now (the evaluator then reports ERR 80, or ERR 85 for the Xn an indirect
// X(X1) points at). Indirection X(X1) is resolved by the evaluator.
using VariableReader = std::function<std::optional<std::int32_t>(std::string_view name)>;

struct ExpressionResult {
    std::int32_t value = 0;
    int error = 0; // 0 on success, else the BDS5 error number (80, 83, 85, 92, 93, 94, 95)
};

// Parses a numeric constant: decimal "-5000", hex "0FFH" (must start with a digit), ON/OFF/Y/N.
std::optional<std::int32_t> parseConstant(std::string_view text);

ExpressionResult evaluate(std::string_view expression, const VariableReader& read);

} // namespace drive_core::bds5
