// How numbers travel on the PMC-960's serial line: decimal, hex or binary per THC bits 7-6 (L1828-1910).
// Formats values for displays and polls, and doubles '#' (23H) in binary output so a lone # means an error.
#pragma once

#include <cstdint>
#include <string>

namespace drive_core::pmc960 {

enum class NumberFormat { Decimal, Hex, Binary };

class Pmc960Format {
public:
    explicit Pmc960Format(int thc = 0) : m_thc(thc & 0xFF) {}

    NumberFormat input() const;  // 11 binary; 10, 01 hex; 00 decimal
    NumberFormat output() const; // 11, 10 binary; 01 hex; 00 decimal
    bool echo() const { return (m_thc & 0x01) == 0; }
    bool trace() const { return (m_thc & 0x02) != 0; }
    bool singleStep() const { return (m_thc & 0x04) != 0; }
    bool engineeringUnits() const { return (m_thc & 0x10) != 0; }
    // "Computer host mode" (L2290): binary output; async errors wait for the next prompt.
    bool hostMode() const { return output() == NumberFormat::Binary; }

    // A signed value of `bits` width as the current output format writes it: decimal with a leading '-',
    // hex as bits/4 upper-case digits (two's complement), binary as bits/8 bytes MSB first, '#' doubled.
    std::string number(std::int64_t value, int bits) const;
    // A value the manual always shows in hex (OB, SE, SS, SI, SP, THC, THR, TGE/TGB): `digits` hex digits
    // in decimal and hex output, bytes in binary output.
    std::string hex(std::int64_t value, int digits) const;
    // Doubles each 23H in binary output (L1906-1910); other formats unchanged.
    std::string escaped(std::string bytes) const;

    static std::string hexDigits(std::int64_t value, int digits);

private:
    int m_thc = 0;
};

} // namespace drive_core::pmc960
