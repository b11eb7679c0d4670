// The motors and controller models Controller Set Up knows (Options > Controller Set Up, L2430-L2610),
// and the Auto rule that turns a motor and a controller model into the PARAMS values. Only two motor
// rows carry the manual's numbers; the rest is our data, marked `chosen` (the motor catalogue and the
// set-up formulas are not in the seeds). See drive_core/sc750/DECISIONS.md, decision 44.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace drive_core::catalog::sc750 {

struct MotorInfo {
    std::string_view part; // the first four characters of the part number, as the user types them
    std::string_view description;
    int poleCount = 4;
    double continuous_A = 0; // RMS
    double peak_A = 0;
    int ilc = 13;                  // ILC
    double sixThresh = 430.664063; // SIX.THRESH
    double sigThresh = 387.597656; // SIG.THRESH, 0.9 x SIX.THRESH in both of the manual's sets
    double kvp = 0.087086;         // KVP for the Stiff/High Bandwidth response
    std::string_view source;       // the manual's lines, or "chosen"
};

struct ControllerModelInfo {
    int model = 752; // MODEL
    double continuous_A = 0;
    double peak_A = 0;
};

std::span<const MotorInfo> motors();
std::span<const ControllerModelInfo> controllerModels();
const MotorInfo* findMotor(std::string_view part); // case-insensitive on the first four characters
const ControllerModelInfo* findControllerModel(int model);

// The Auto values, name and value of every PARAMS parameter (catalog order, AUTOSTART left out): the
// boiler-plate set (L946-L973) with the motor's POLECOUNT, ILC, SIX.THRESH, SIG.THRESH and KVP when the part is
// known; ILMT.PLUS/MINUS cap the current at the motor's peak when the controller's peak is higher (the
// warning at L2438); Gentle halves KVP, KVI and KPP and lowers ARF0/ARF1 to 100/500 Hz. model 0 = unknown.
std::vector<std::pair<std::string, double>> setupParameters(std::string_view motorPart, int model, bool gentle);

} // namespace drive_core::catalog::sc750
