// PMC-960 parameters: the non-volatile parameter table (T commands, 7.18, L1713-2126) and the volatile system
// registers and motion buffer (S, A/V/J, 5.4-5.7, L859-919). Ranges and factory values from 5.7's table.
// Decisions where the seed is silent are marked "chosen" (see also drive_core/pmc960/DECISIONS.md).
#include "pmc960_catalog.h"

#include <algorithm>
#include <array>

namespace drive_core::catalog::pmc960 {
namespace {

using B = NumberBase;

// FixedPoint values (TUA/TUP/TUS) are stored x 10000: "5:7777" = 57777.
// clang-format off
constexpr std::array kParameters{
    // ---- motion buffer (volatile; power-up values = 192 kHz factory settings, L906-909) ----
    ParameterInfo{"A", "Acceleration (192 kHz range: kHz/s)", 1, 65535, 4000, 4000, B::Decimal, 16, false, "L1059-1073, L905"},
    ParameterInfo{"V", "Velocity for Index and Go (192 kHz range: 100 Hz)", 1, 1920, 400, 400, B::Decimal, 16, false, "L2140-2153, L905"},
    ParameterInfo{"J", "Jog speed (192 kHz range: 100 Hz)", 1, 1920, 100, 100, B::Decimal, 16, false, "L1262-1296, L905"},
    ParameterInfo{"I", "Index distance (counts)", 0, 2147483647, 0, 0, B::Decimal, 32, false, "L1252-1260, L905"},
    ParameterInfo{"G", "Go position (counts)", 0, 1073741824, 0, 0, B::Decimal, 32, false, "L1165-1189, L906"},
    ParameterInfo{"D", "Dwell (ms)", 0, 65535, 0, 0, B::Decimal, 16, false, "L1119-1134"},
    // ---- system registers (volatile) ----
    ParameterInfo{"SD", "Adaptive depth (counts)", 3, 65535, 3, 3, B::Decimal, 16, false, "L1476-1492"},
    ParameterInfo{"SF", "Following error trip (counts, power of 2)", 1, 32767, 2048, 2048, B::Decimal, 16, false, "L1505-1517"},
    ParameterInfo{"SM", "System mode", 0, 3, 0, 0, B::Decimal, 8, false, "L1577-1601"},
    ParameterInfo{"SP", "Motion profile bits", 0, 0xFF, 0, 0, B::Hex, 8, false, "L1612-1631"},
    ParameterInfo{"ST", "Positive stop torque (0.1 %)", 0, 1000, 0, 0, B::Decimal, 16, false, "L1655-1688"},
    ParameterInfo{"SV", "Feedrate override (%)", 1, 100, 100, 100, B::Decimal, 8, false, "L1690-1699"},
    ParameterInfo{"SW", "Write enable", 0, 1, 0, 0, B::Decimal, 8, false, "L1701-1711"},
    ParameterInfo{"SLF", "Forward software limit", -2147483647, 2147483647, 0, 0, B::Decimal, 32, false, "L1532-1575"},
    ParameterInfo{"SLR", "Reverse software limit", -2147483647, 2147483647, 0, 0, B::Decimal, 32, false, "L1532-1575"},
    // ---- parameter table (non-volatile) ----
    ParameterInfo{"TGP", "PLGAIN position loop gain", 0, 255, 16, 0, B::Decimal, 8, true, "L1741-1773, L912"},
    ParameterInfo{"TGV", "VLGAIN velocity loop gain", 0, 255, 16, 0, B::Decimal, 8, true, "L1741-1773, L913"},
    ParameterInfo{"TGT", "TGAIN tach gain", 0, 255, 160, 0, B::Decimal, 8, true, "L1741-1773, L914"},
    ParameterInfo{"TGF", "FFGAIN feedforward gain", 0, 255, 16, 0, B::Decimal, 8, true, "L1741-1773, L915"},
    ParameterInfo{"TGE", "PLCOMP position loop compensation (hex)", 0, 255, 0, 0, B::Hex, 8, true, "L1741-1773, L916"},
    ParameterInfo{"TGB", "VLCOMP velocity loop compensation (hex)", 0, 255, 0, 0, B::Hex, 8, true, "L1741-1773, L917"},
    ParameterInfo{"TGX", "XGAIN external velocity reference gain", 0, 255, 0, 0, B::Decimal, 8, true, "L1741-1773, L918"},
    ParameterInfo{"TGL", "ALGAIN analog lock gain", 0, 255, 0, 0, B::Decimal, 8, true, "L1741-1773, L919"},
    // chosen: THA factory 4096 (the manual's default units assume a 4096-count resolver, L1024)
    ParameterInfo{"THA", "Counts per revolution (0 = encoder)", 0, 65535, 4096, 0, B::Decimal, 16, true, "L1795-1804"},
    // chosen: THB factory 3 = 9600 baud (the seed gives no factory baud); generic power-up autobauds (L875)
    ParameterInfo{"THB", "Baud rate code (0 autobaud, 1 38400 .. 8 300)", 0, 8, 3, 0, B::Decimal, 8, true, "L1806-1826"},
    ParameterInfo{"THC", "Communications format bits", 0, 0xFF, 0, 0, B::Hex, 8, true, "L1828-1910"},
    // chosen: THI factory '=' (3DH), the axis ID the contour examples print before } (L2239-2264)
    ParameterInfo{"THI", "Axis ID", 0x21, 0x5A, 0x3D, 0x3D, B::Label, 8, true, "L1912-1918"},
    ParameterInfo{"THL", "Hardware limits on IN07'/IN06'", 0, 1, 0, 0, B::Hex, 8, true, "L1787, L1001-1005"},
    ParameterInfo{"THM", "Muxed input banks", 0, 1, 0, 0, B::Hex, 8, true, "L1788"},
    ParameterInfo{"THP", "Hardware program protection (IN05')", 0, 1, 0, 0, B::Hex, 8, true, "L1944-1951"},
    ParameterInfo{"THR", "Motion reference bits", 0, 0xFF, 0, 0, B::Hex, 8, true, "L1966-2001"},
    ParameterInfo{"THS", "Software limits enable", 0, 1, 0, 0, B::Hex, 8, true, "L2003-2014"},
    ParameterInfo{"TLB", "Label for B|", 0, 0x7A, 0, 0, B::Label, 8, true, "L2016-2033"},
    ParameterInfo{"TLP", "Power-up routine label", 0, 0x7A, 0, 0, B::Label, 8, true, "L2016-2033"},
    ParameterInfo{"TLV", "EXEC' routine label", 0, 0x7A, 0, 0, B::Label, 8, true, "L2016-2033"},
    // chosen factory units = the 192 kHz internal units, so engineering units on or off agree out of the box
    ParameterInfo{"TUA", "Acceleration constant (Hz/s per unit)", 1, 655359999, 10000000, 10000000, B::FixedPoint, 32, true, "L2050-2063"},
    ParameterInfo{"TUB", "Maximum acceleration (user units)", 1, 65535, 10000, 10000, B::Decimal, 16, true, "L2065-2074"},
    ParameterInfo{"TUH", "Home speed (user units)", 1, 65535, 20, 20, B::Decimal, 16, true, "L2076-2085"},
    ParameterInfo{"TUP", "Position constant (counts per unit)", 1, 655359999, 10000, 10000, B::FixedPoint, 32, true, "L2087-2100"},
    ParameterInfo{"TUS", "Velocity constant (Hz per unit)", 1, 655359999, 1000000, 1000000, B::FixedPoint, 32, true, "L2102-2115"},
    ParameterInfo{"TUV", "Maximum velocity (user units)", 1, 65535, 1920, 1920, B::Decimal, 16, true, "L2117-2126"},
};
// clang-format on

} // namespace

std::span<const ParameterInfo> parameters() {
    return kParameters;
}

const ParameterInfo* findParameter(std::string_view upperName) {
    const auto it = std::find_if(kParameters.begin(), kParameters.end(),
                                 [upperName](const ParameterInfo& p) { return p.name == upperName; });
    return it == kParameters.end() ? nullptr : &*it;
}

} // namespace drive_core::catalog::pmc960
