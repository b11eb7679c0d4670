// What to do about an SC750 fault and a PMC-960 error: the manuals list the codes but say little about
// remedies, so these are written from the sections they do have (line references in the text) and otherwise
// from what a user of the drive would check first. Data for catalog::ErrorEntry::whatToDo.
#include "pmc960_catalog.h"
#include "sc750_catalog.h"

#include <algorithm>
#include <iterator>

namespace drive_core::catalog {

namespace {

struct Remedy {
    int code;
    std::string_view text;
};

constexpr Remedy kSc750Faults[] = {
    {0, "Set ENABLE = 1 and assert the ENABLE input (J53-4) to enable the amplifier (L1496-L1520)."},
    {1, "The motor ran faster than the resolver allows: lower the commanded speed or the gains that overshoot, check "
        "the resolver wiring."},
    {2, "Let the motor cool; check its load, duty cycle and thermostat wiring."},
    {3, "Let the controller cool; check its ventilation and the ambient temperature, lower the duty cycle."},
    {4, "The I\u00b7t protection tripped: lower the RMS current (accelerations, load, duty cycle)."},
    {5, "Check the motor cable for a short between phases or to ground."},
    {6, "Check the control supply voltage."},
    {7, "Check the bus supply and the motor cable; a load that regenerates may need a shunt regulator."},
    {8, "No fault: the amplifier is enabled."},
    {9, "The load returns more energy than the shunt regulator can take: lower DECEL.RATE or fit a larger shunt."},
    {10, "Check the bus supply voltage and the control supply."},
    {11, "Check the encoder's +5 V wiring and what it draws."},
    {12, "Check what the terminal +5 V powers and its wiring."},
    {13, "Check the control supply; if the fault stays, the power stage needs service."},
    {14, "Cycle the power; if the fault stays, the controller needs service."},
    {241, "The motor could not follow the profile: lower ACCEL.RATE, DECEL.RATE or the speed, check the load and the "
          "velocity loop gains."},
    {242,
     "Download the program again (Compile > Run Program); if the fault comes back, the program memory is failing."},
    {243,
     "Set the parameters again (Controller > Edit Parameters, Controller Set Up) and check them after a power cycle."},
    {244, "The program stopped at the line shown: correct it and run again (Reset Program clears F 4)."},
    {245, "Check the PacLAN cabling and that every axis the program addresses is on the network (L2285, L2360)."},
    {246, "The .BIN came from another Motion Dialogue version: compile the program with this one and download it again "
          "(L1554, L1585)."},
};

constexpr Remedy kPmc960Errors[] = {
    {0x83, "Reduce the change in velocity, increase the acceleration or lower the current speed (L2301)."},
    {0x86, "Use a smaller change in velocity or make it over a longer distance (L2304)."},
    {0x8B, "Give the Cam command a non-zero start speed."},
    {0x90, "Enter a value within the command's range (Help: the command's page lists it)."},
    {0x91, "Enter a value within the command's range (Help: the command's page lists it)."},
    {0x92, "Enter a value within the command's range (Help: the command's page lists it)."},
    {0x93, "Enter a value within the command's range (Help: the command's page lists it)."},
    {0x97, "Enter a value within the command's range (Help: the command's page lists it)."},
    {0x94,
     "Enter a speed within the velocity range; after changing the range (TUV, TUS), enter the speed again (L2320)."},
    {0x95, "Enter 0 or 1."},
    {0x96, "Name an input bank the controller has (a hex digit for a muxed bank)."},
    {0x98, "Enter a higher speed, or choose a lower velocity range (TUV)."},
    {0x99, "Use a smaller position or distance, or coarser position units."},
    {0x9A, "Leave the bank out, or enable muxed inputs first (THM)."},
    {0x9B, "Enter a home location below the resolver size set with THA."},
    {0x9C, "Use a smaller feedforward gain: it overflows in another velocity range."},
    {0xA1, "Check the command's letters: MPL commands are one or two upper-case letters (Help lists them)."},
    {0xA2, "End the command with a carriage return or one of its display characters (? ! % &)."},
    {0xAA, "Write the number with one ':' at most."},
    {0xB1, "Make SD larger than the deceleration distance plus the following error."},
    {0xB2, "Wait until the motion has stopped (or the FPS state ended), then send the command again."},
    {0xB3, "Unassert ESTOP' and try again (L2348)."},
    {0xB6, "Enable the servodrive first: SM1 or SM2 (L2351)."},
    {0xB8, "Move in reverse, off the forward limit (+LIMIT')."},
    {0xB9, "Move forward, off the reverse limit (-LIMIT')."},
    {0xC1, "Shorten the program: the program buffer is full."},
    {0xC2, "Define the label (@<label>) the command looks for, or correct its name."},
    {0xC3, "Enter the program again; if the fault comes back, the ZeroPower RAM is failing."},
    {0xC5, "Use a label character between \" and z."},
    {0xC6, "Stop the program first (ESC, MPL > Stop), then edit it."},
    {0xC8, "Use loop counter X, Y or Z."},
    {0xD3, "Write-enable the table and program buffer first (SW)."},
    {0xD4, "Keep TUS times TUV below 384000."},
    {0xD8, "Send contour segments sooner, before the running segment ends."},
    {0xE0, "Motion stopped: release ESTOP', then enable again with SM1 or SM2 before moving."},
    {0xE1, "Clear the overflow with SM0, then SM1 or SM2 (L2382)."},
    {0xE2, "Check that the servodrive is powered and ready (DRVRDY'), then SM1 or SM2 again."},
    {0xE3, "Clear the fault the FAULT input reports, then enable again with SM1 or SM2."},
};

std::string_view find(std::span<const Remedy> table, int code) {
    const auto it = std::find_if(table.begin(), table.end(), [code](const Remedy& r) { return r.code == code; });
    return it == table.end() ? std::string_view() : it->text;
}

} // namespace

std::string_view sc750::faultRemedy(int code) {
    return find(kSc750Faults, code);
}

std::string_view pmc960::errorRemedy(int code) {
    return find(kPmc960Errors, code);
}

} // namespace drive_core::catalog
