// BDS5 print formats (L4191-4378, L6951-6985): default 12-column right justification, [w], [w.d.p],
// [H] hex, [C] character, [B] binary, [S] ON/OFF.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace drive_core::bds5 {

// Formats a value with the text between the brackets ("" for the default). nullopt: bad format (ERR 79).
std::optional<std::string> formatValue(std::int32_t value, std::string_view format);

// Expands the ^X control-character notation of quoted print text (L4308-4331).
std::string expandControlCharacters(std::string_view text);

} // namespace drive_core::bds5
