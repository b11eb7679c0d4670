// Controller Set Up's motor and controller tables and the Auto rule (see sc750_motors.h).
#include "sc750_motors.h"

#include "sc750_catalog.h"

#include <algorithm>
#include <cctype>
#include <cmath>

namespace drive_core::catalog::sc750 {

namespace {
// clang-format off
const MotorInfo kMotors[] = {
    // part, description, poles, cont A, peak A, ILC, SIX.THRESH, SIG.THRESH, KVP, source
    {"R32G", "small frame, short stack",  4, 2.4,  7.2, 13,  430.664063,  387.597656, 0.087086, "L946-L950 (boiler-plate)"},
    {"R33G", "small frame, long stack",   4, 3.6, 10.8, 22,  820.0,       738.0,      0.080,    "chosen"},
    {"R43G", "medium frame, short stack", 4, 5.0, 15.0, 37, 1700.0,      1530.0,      0.072,    "chosen"},
    {"R45G", "medium frame, long stack",  4, 7.5, 22.5, 59, 3147.836538, 2833.052885, 0.062053, "L2508-L2512 (auto example)"},
    {"R63G", "large frame",               6, 11.0, 33.0, 80, 4600.0,     4140.0,      0.055,    "chosen"},
};

const ControllerModelInfo kModels[] = {
    // MODEL, continuous A, peak A (chosen: the hardware reference manual is not in the seeds)
    {752, 2.5, 7.5}, {753, 5.0, 15.0}, {754, 7.5, 22.5}, {755, 10.0, 30.0}, {756, 15.0, 45.0},
};
// clang-format on

bool samePart(std::string_view a, std::string_view b) {
    if (a.size() < 4 || b.size() < 4) return false;
    for (std::size_t i = 0; i < 4; ++i)
        if (std::toupper(static_cast<unsigned char>(a[i])) != std::toupper(static_cast<unsigned char>(b[i])))
            return false;
    return true;
}
} // namespace

std::span<const MotorInfo> motors() {
    return kMotors;
}

std::span<const ControllerModelInfo> controllerModels() {
    return kModels;
}

const MotorInfo* findMotor(std::string_view part) {
    for (const MotorInfo& m : kMotors)
        if (samePart(part, m.part)) return &m;
    return nullptr;
}

const ControllerModelInfo* findControllerModel(int model) {
    for (const ControllerModelInfo& c : kModels)
        if (c.model == model) return &c;
    return nullptr;
}

std::vector<std::pair<std::string, double>> setupParameters(std::string_view motorPart, int model, bool gentle) {
    const MotorInfo* motor = findMotor(motorPart);
    const ControllerModelInfo* controller = findControllerModel(model);
    // Peak current cap in percent of the controller's peak, so the motor is never driven past its own.
    double currentLimit = 100;
    if (motor && controller && controller->peak_A > motor->peak_A)
        currentLimit = std::floor(100.0 * motor->peak_A / controller->peak_A);
    std::vector<std::pair<std::string, double>> values;
    for (const VariableInfo& v : variables()) {
        if (v.access != Access::Parameter || v.name == "AUTOSTART") continue;
        double value = v.defaultValue;
        if (motor) {
            if (v.name == "POLECOUNT") value = motor->poleCount;
            if (v.name == "ILC") value = motor->ilc;
            if (v.name == "SIX.THRESH") value = motor->sixThresh;
            if (v.name == "SIG.THRESH") value = motor->sigThresh;
            if (v.name == "KVP") value = motor->kvp;
        }
        if (v.name == "ILMT.PLUS" || v.name == "ILMT.MINUS") value = currentLimit;
        if (gentle) {
            if (v.name == "KVP" || v.name == "KVI" || v.name == "KPP") value /= 2;
            if (v.name == "ARF0") value = 100;
            if (v.name == "ARF1") value = 500;
        }
        values.emplace_back(std::string(v.name), value);
    }
    return values;
}

} // namespace drive_core::catalog::sc750
