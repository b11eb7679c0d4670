// PMC-960 error codes: all 65 of 7.22 (L2286-2384), #80-#E3. Texts are the manual's; the OCR-damaged "SMO"
// in E1 reads SM0 (digest §11.1 #12). Conflicts the digest lists (§11.2 #7-#9) are noted on the entries.
#include "pmc960_catalog.h"

#include <algorithm>
#include <array>

namespace drive_core::catalog::pmc960 {
namespace {

using G = ErrorGroup;

// clang-format off
constexpr std::array kErrors{
    ErrorInfo{0x80, "Cam not at top velocity", "The Cam command must be at top velocity to change speed.", G::Cam, false, false, "L2298"},
    ErrorInfo{0x81, "Cam not running", "A Cam change is allowed only while Cam is running.", G::Cam, false, false, "L2299"},
    ErrorInfo{0x82, "Cam direction change not at rest", "When using the Cam command, system must be at rest before direction of the system can be changed.", G::Cam, false, false, "L2300"},
    ErrorInfo{0x83, "Cam ramp too long", "The ramp for changing velocity during the Cam command is too long for the PMC's internal calculations. Reduce the change in velocity, increase the acceleration or lower the current speed.", G::Cam, false, false, "L2301"},
    ErrorInfo{0x84, "Cam position while in motion", "A new camming <position> was requested while the system was already in motion.", G::Cam, false, false, "L2302"},
    ErrorInfo{0x85, "Cam too close to end point", "The Cam command was given too close to the desired endpoint. The PMC does not have time to complete the command.", G::Cam, false, false, "L2303"},
    ErrorInfo{0x86, "Cam acceleration too high", "The internally calculated acceleration rate generated during the Cam command exceeds the maximum acceleration parameter. Use a smaller change in the velocity rate or do it over a larger distance.", G::Cam, false, false, "L2304-2306"},
    ErrorInfo{0x87, "Break waiting for stop (Cam)", "A BREAK character was received while the Cam command was waiting for the current motion to stop.", G::Cam, false, false, "L2308"},
    ErrorInfo{0x88, "Break waiting for top velocity (Cam)", "A BREAK character was received while the Cam command was waiting for the top velocity to be reached.", G::Cam, false, false, "L2309"},
    ErrorInfo{0x89, "Break waiting for ^ (Cam)", "A BREAK character was received while the Cam command was waiting for the synchronization character (^) to be received.", G::Cam, false, false, "L2310"},
    ErrorInfo{0x8A, "Cam segment already waiting", "A new cam segment is waiting to be executed. Another cam segment cannot be entered until the acceleration period begins on the current cam segment.", G::Cam, false, false, "L2311"},
    ErrorInfo{0x8B, "Cam start speed zero", "A non-zero start speed must be specified for the Cam command to operate properly.", G::Cam, false, false, "L2312"},

    ErrorInfo{0x90, "Value out of range", "Value entered is out of the allowable range.", G::InputRange, false, false, "L2316"},
    ErrorInfo{0x91, "Index distance out of range", "Index distance entered is out of the allowable range.", G::InputRange, false, false, "L2317"},
    ErrorInfo{0x92, "Acceleration out of range", "Acceleration entered is out of the allowable range.", G::InputRange, false, false, "L2318"},
    ErrorInfo{0x93, "Absolute distance out of range", "The absolute distance entered is out of the allowable range. Absolute distance cannot be greater than 31 bits.", G::InputRange, false, false, "L2319"},
    ErrorInfo{0x94, "Velocity out of range", "Velocity rate entered when using C, H, J or V command is out of the allowable range. This error can occur when motion is commanded after changing the velocity range and the stored speed is invalid in the new range.", G::InputRange, false, false, "L2320"},
    ErrorInfo{0x95, "Not a boolean", "Value entered is not a boolean value. A 0 or 1 is required.", G::InputRange, false, false, "L2321"},
    ErrorInfo{0x96, "Invalid input bank", "An invalid input bank has been requested.", G::InputRange, false, false, "L2322"},
    ErrorInfo{0x97, "Floating point value out of range", "The floating point value entered is out of the allowable range.", G::InputRange, false, false, "L2323"},
    ErrorInfo{0x98, "Velocity too small", "The specified velocity is too small to cause motion. After engineering units conversion the velocity is below the minimum possible for the velocity range.", G::InputRange, false, false, "L2324"},
    ErrorInfo{0x99, "Position units overflow", "An overflow occurred converting position engineering units. The selected position or distance is too large.", G::InputRange, false, false, "L2325"},
    ErrorInfo{0x9A, "Input bank without THM", "Specifying an input bank is illegal when MUXED input support is disabled. (See the THM command.)", G::InputRange, false, false, "L2326"},
    ErrorInfo{0x9B, "Home location too large", "Requested home location is greater than the specified resolver size using the THA command.", G::InputRange, false, false, "L2327"},
    ErrorInfo{0x9C, "Feedforward gain overflow", "Overflow during feedforward gain entry. Automatic calculation of gain in another velocity range has resulted in an overflow.", G::InputRange, false, false, "L2328"},

    ErrorInfo{0xA1, "Invalid command", "An invalid command has been used.", G::Syntax, false, false, "L2332"},
    ErrorInfo{0xA2, "Invalid terminator or designator", "An invalid terminator or designator has been used. (Also ESC during a contour count, L2206.)", G::Syntax, false, false, "L2333"},
    ErrorInfo{0xA3, "Reserved", "Reserved.", G::Syntax, true, false, "L2334"},
    // Listed as reserved, yet 7.21 raises it for a contour count above the tick's maximum (digest §11.2 #8).
    ErrorInfo{0xA4, "Contour count too large", "Reserved in 7.22.3; 7.21 uses it when a contour count exceeds the tick's maximum.", G::Syntax, true, false, "L2335, L2204"},
    ErrorInfo{0xA5, "Invalid axis address", "Invalid address entered while executing THI command. Valid addresses are printable ASCII characters other than the \"space\" character.", G::Syntax, false, false, "L2336"},
    ErrorInfo{0xA6, "Reserved", "Reserved.", G::Syntax, true, false, "L2337"},
    ErrorInfo{0xA7, "Reserved", "Reserved.", G::Syntax, true, false, "L2338"},
    ErrorInfo{0xA8, "No program in socket", "No valid program in the optional socket.", G::Syntax, false, false, "L2339"},
    ErrorInfo{0xA9, "Machine code not recognized", "The requested machine code is not recognized.", G::Syntax, false, false, "L2341"},
    ErrorInfo{0xAA, "Only one : per number", "Only one floating point designator (:) allowed per number.", G::Syntax, false, false, "L2342"},

    ErrorInfo{0xB1, "Adaptive depth too small", "Adaptive depth value not large enough for given motion. The SD value must be greater than the deceleration distance plus the following error.", G::Motion, false, false, "L2346"},
    ErrorInfo{0xB2, "Not valid in motion or FPS", "Command not valid while system is in motion or in an FPS (Feed to Positive Stop) state. A motion designator or programming command was entered.", G::Motion, false, false, "L2347"},
    ErrorInfo{0xB3, "ESTOP' asserted", "Motion cannot be initiated with ESTOP' asserted. Unassert ESTOP' and try again.", G::Motion, false, false, "L2348"},
    ErrorInfo{0xB4, "Adaptive depth with decel stop", "Adaptive depth control and Deceleration Stop not allowed on the same motion.", G::Motion, false, false, "L2349"},
    ErrorInfo{0xB5, "ESC during synchronization", "An ESCAPE character was received during a synchronization command.", G::Motion, false, false, "L2350"},
    ErrorInfo{0xB6, "Servodrive not enabled", "Servodrive not enabled by the user. You must be in mode 1 or mode 2 (see SM command) before commanding motion.", G::Motion, false, false, "L2351"},
    ErrorInfo{0xB7, "Reserved", "Reserved.", G::Motion, true, false, "L2352"},
    ErrorInfo{0xB8, "Forward limit asserted", "Attempt to move forward with forward limit (+LIMIT') asserted.", G::Motion, false, false, "L2353"},
    ErrorInfo{0xB9, "Reverse limit asserted", "Attempt to move in reverse with reverse limit (-LIMIT') asserted.", G::Motion, false, false, "L2354"},

    ErrorInfo{0xC1, "Program buffer full", "Program buffer overflow. The program buffer is full.", G::Programming, false, false, "L2358"},
    ErrorInfo{0xC2, "Label undefined", "Program label undefined. Could not find the requested label during a search (B, L, F or P commands.)", G::Programming, false, false, "L2359"},
    ErrorInfo{0xC3, "Program memory fault", "The program memory has a storage fault. The last entered programming character was not saved in program buffer due to hardware failure of the ZeroPower RAM.", G::Programming, false, false, "L2360"},
    ErrorInfo{0xC4, "ESC during program", "An ESCAPE character was received during program execution.", G::Programming, false, false, "L2361"},
    ErrorInfo{0xC5, "Invalid label", "Invalid label entered on command. A valid label can be any ASCII character between ASCII \" (22H) and a lower case z (7AH) inclusive.", G::Programming, false, false, "L2362"},
    ErrorInfo{0xC6, "P during program execution", "A Program command cannot be executed during program execution.", G::Programming, false, false, "L2363"},
    ErrorInfo{0xC7, "BREAK' during program", "The hardware BREAK input was detected during program execution.", G::Programming, false, false, "L2364"},
    ErrorInfo{0xC8, "Invalid loop counter", "An invalid loop counter ID was entered. Only X, Y & Z are valid.", G::Programming, false, false, "L2365"},

    // 7.19 says ESC during Until gives D0; the table's D6 is used (digest §11.2 #7).
    ErrorInfo{0xD0, "ESC during dwell", "An ESCAPE character was received during a Dwell command.", G::Miscellaneous, false, false, "L2369"},
    ErrorInfo{0xD1, "Reserved", "Reserved.", G::Miscellaneous, true, false, "L2370"},
    ErrorInfo{0xD2, "Input aborted by ESC", "Input operation aborted due to ESCAPE entered.", G::Miscellaneous, false, false, "L2371"},
    ErrorInfo{0xD3, "Write protected", "The Parameter Table and/or program buffer is write protected, so changes cannot be made. See SW command.", G::Miscellaneous, false, false, "L2372"},
    ErrorInfo{0xD4, "Velocity range too large", "The velocity range requested is too large. Value entered for TUS multiplied by the value entered for TUV must be less than 384000.", G::Miscellaneous, false, false, "L2373"},
    ErrorInfo{0xD5, "Break during single step", "Break character received during Single Step wait during @ command.", G::Miscellaneous, false, false, "L2374"},
    ErrorInfo{0xD6, "ESC during until", "An ESCAPE character was received during an Until command.", G::Miscellaneous, false, false, "L2375"},
    ErrorInfo{0xD7, "ESC during contour sync", "ESC received during contour command sync.", G::Miscellaneous, false, false, "L2376"},
    ErrorInfo{0xD8, "Contour data late", "Attempt to enter a Contour segment during a contour stop or the contour command did not receive new data before a segment ended.", G::Miscellaneous, false, false, "L2377"},

    ErrorInfo{0xE0, "ESTOP' in motion", "ESTOP' line asserted while system in motion.", G::SystemStatus, false, true, "L2381"},
    ErrorInfo{0xE1, "PSJ overflow", "PSJ (Position Summing Junction) overflow exists. Use an SM0 then SM1 or SM2 to clear the overflow condition.", G::SystemStatus, false, true, "L2382"},
    ErrorInfo{0xE2, "Servodrive not ready", "The servodrive was not ready (DRVRDY' not true) when enabled by the user (SM1 or SM2 issued).", G::SystemStatus, false, true, "L2383"},
    ErrorInfo{0xE3, "FAULT' detected", "A FAULT input has been detected.", G::SystemStatus, false, true, "L2384"},
};
// clang-format on
static_assert(kErrors.size() == 65, "7.22 lists 65 codes");

} // namespace

std::span<const ErrorInfo> errors() {
    return kErrors;
}

const ErrorInfo* findError(int code) {
    const auto it = std::find_if(kErrors.begin(), kErrors.end(), [code](const ErrorInfo& e) { return e.code == code; });
    return it == kErrors.end() ? nullptr : &*it;
}

} // namespace drive_core::catalog::pmc960
