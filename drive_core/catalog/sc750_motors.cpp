// Controller Set Up's motor and controller tables and the Auto rule (see sc750_motors.h).
#include "sc750_motors.h"

#include "sc750_catalog.h"

#include <algorithm>
#include <cctype>
#include <cmath>

namespace drive_core::catalog::sc750 {

namespace {
// clang-format off
// Kt N·m/A, R ohm, L mH, rotor kg·cm², load, poles, cont A, peak A, max rpm. R32G is the boiler-plate motor
// (SetupData's defaults); R45G's data give the manual's auto example exactly; every number is chosen.
const MotorInfo kMotors[] = {
    {"R32G", "small frame, short stack",  {0.30, 5.0, 6.5,  0.80,    0, 4,  2.4,  7.2, 6370}, "L946-L950 (boiler-plate)"},
    {"R33G", "small frame, long stack",   {0.45, 2.8, 5.0,  1.30,    0, 4,  3.6, 10.8, 6000}, "chosen"},
    {"R43G", "medium frame, short stack", {0.62, 1.9, 6.8,  1.35,    0, 4,  5.0, 15.0, 5000}, "chosen"},
    {"R45G", "medium frame, long stack",  {0.97, 1.4, 8.26, 1.84313, 0, 4,  7.5, 22.5, 4608}, "L2508-L2512 (auto example)"},
    {"R63G", "large frame",               {1.30, 0.9, 7.2,  4.20,    0, 6, 11.0, 33.0, 3500}, "chosen"},
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

SetupData setupData(std::string_view motorPart, bool gentle) {
    const MotorInfo* motor = findMotor(motorPart);
    SetupData data = motor ? motor->data : SetupData{};
    data.gentle = gentle;
    return data;
}

std::vector<std::pair<std::string, double>> setupParameters(const SetupData& data, int model) {
    // The boiler-plate motor's values are the catalog defaults; SIX.THRESH's unrounded (441000/1024, L948).
    static const SetupData kRef;
    constexpr double kSixThreshRef = 430.6640625;
    const auto round6 = [](double v) { return std::round(v * 1e6) / 1e6; };
    const auto inertiaPerKt = [](const SetupData& d) {
        return (d.rotorInertia_kgcm2 + d.loadInertia_kgcm2) / d.torqueConstant_NmPerA;
    };
    const auto timeConstant = [](const SetupData& d) { return d.inductance_mH / d.resistance_ohm; };
    const auto sixScale = [](const SetupData& d) { return d.torqueConstant_NmPerA * d.peak_A * d.maxSpeed_rpm; };
    const double sixThresh = kSixThreshRef * sixScale(data) / sixScale(kRef);
    const ControllerModelInfo* controller = findControllerModel(model);
    // Peak current cap in percent of the controller's peak, so the motor is never driven past its own.
    double currentLimit = 100;
    if (controller && controller->peak_A > data.peak_A)
        currentLimit = std::floor(100.0 * data.peak_A / controller->peak_A);
    std::vector<std::pair<std::string, double>> values;
    for (const VariableInfo& v : variables()) {
        if (v.access != Access::Parameter || v.name == "AUTOSTART") continue;
        double value = v.defaultValue; // the boiler-plate motor's value: each rule scales it
        if (v.name == "POLECOUNT") value = data.poleCount;
        if (v.name == "ILC") value = std::round(value * timeConstant(data) / timeConstant(kRef));
        if (v.name == "SIX.THRESH") value = round6(sixThresh);
        if (v.name == "SIG.THRESH") value = round6(0.9 * sixThresh);
        if (v.name == "KVP") value = round6(value * inertiaPerKt(data) / inertiaPerKt(kRef));
        if (v.name == "ILMT.PLUS" || v.name == "ILMT.MINUS") value = currentLimit;
        if (data.gentle) {
            if (v.name == "KVP" || v.name == "KVI" || v.name == "KPP") value /= 2;
            if (v.name == "ARF0") value = 100;
            if (v.name == "ARF1") value = 500;
        }
        values.emplace_back(std::string(v.name), value);
    }
    return values;
}

std::vector<std::pair<std::string, double>> setupParameters(std::string_view motorPart, int model, bool gentle) {
    return setupParameters(setupData(motorPart, gentle), model);
}

} // namespace drive_core::catalog::sc750
