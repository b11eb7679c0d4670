// The motors and controller models Controller Set Up knows (Options > Controller Set Up, L2430-L2610),
// and the one rule that turns a motor's set-up data and a controller model into the PARAMS values (Auto
// fills the data from the motor table, Manual from the user's "Controller Set Up Data" screen). The
// manual gives neither a motor catalogue nor formulas: see drive_core/sc750/DECISIONS.md, decisions 44 and 46.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace drive_core::catalog::sc750 {

// A motor's electrical and mechanical characteristics, the "Controller Set Up Data" (L2530-L2553). The
// defaults are the boiler-plate motor (R32G), whose Auto values are the catalog's defaults (L946-L973).
struct SetupData {
    double torqueConstant_NmPerA = 0.30; // Kt, per A RMS
    double resistance_ohm = 5.0;         // winding, line to line
    double inductance_mH = 6.5;          // winding, line to line
    double rotorInertia_kgcm2 = 0.80;    // kg·cm², as motor data sheets give it
    double loadInertia_kgcm2 = 0;        // reflected to the motor shaft; Auto assumes none
    int poleCount = 4;                   // POLECOUNT
    double continuous_A = 2.4;           // RMS
    double peak_A = 7.2;                 // RMS
    double maxSpeed_rpm = 6370;
    bool gentle = false; // System Response: Gentle/Low Bandwidth (L2246)
};

struct MotorInfo {
    std::string_view part; // the first four characters of the part number, as the user types them
    std::string_view description;
    SetupData data;
    std::string_view source; // the manual's lines its Auto values reproduce, or "chosen"
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

// The set-up data Auto uses: the motor's row, or the boiler-plate motor (SetupData{}) for an unknown part.
SetupData setupData(std::string_view motorPart, bool gentle);

// Name and value of every PARAMS parameter (catalog order, AUTOSTART left out) for data on a controller
// MODEL (0 = unknown): the boiler-plate set (L946-L973) scaled from the boiler-plate motor by
//   KVP        ∝ (rotor + load inertia) / Kt     (same velocity-loop bandwidth for any inertia)
//   ILC        ∝ L / R                           (the current loop's zero on the winding's pole)
//   SIX.THRESH ∝ Kt × peak current × max speed   (SIG.THRESH = 0.9 × SIX.THRESH, as in both manual sets)
// rounded to 6 decimals (ILC to an integer), POLECOUNT = poles; ILMT.PLUS/MINUS cap the current at the
// motor's peak when the controller's peak is higher (the warning at L2438); Gentle halves KVP, KVI and KPP
// and lowers ARF0/ARF1 to 100/500 Hz.
std::vector<std::pair<std::string, double>> setupParameters(const SetupData& data, int model);
// Auto: setupParameters(setupData(motorPart, gentle), model).
std::vector<std::pair<std::string, double>> setupParameters(std::string_view motorPart, int model, bool gentle);

} // namespace drive_core::catalog::sc750
