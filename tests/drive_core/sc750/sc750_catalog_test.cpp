// The SC750 catalog as data: every family the digest lists (§4-§6) is there, with line references,
// consistent types and ranges, and the look-ups the compiler and the IDE use are case-insensitive.
#include "drive_core/catalog/sc750_catalog.h"
#include "drive_core/catalog/sc750_motors.h"

#include <gtest/gtest.h>

#include <set>
#include <string>
#include <utility>
#include <vector>

namespace {

namespace cat = drive_core::catalog::sc750;

TEST(Sc750Catalog, HasTheManualsInventories) {
    EXPECT_EQ(cat::functions().size(), 28u);        // 12 arithmetic + 16 string (§4.6)
    EXPECT_EQ(cat::interruptSources().size(), 41u); // L1789-L1862
    EXPECT_EQ(cat::dacMap().size(), 14u);           // DACMAP 0..13 (L2147-L2161)
    EXPECT_EQ(cat::faults().size(), 21u);           // display codes 0-E and F 1-F 6 (UC has no FAULTCODE)
    for (const char* s : {"GO.VEL", "GO.INCR", "GO.ABS", "GO.HOME", "ABORT.MOTION", "UPD.MOVE", "PAUSE", "WHEN",
                          "TMRSET", "INTERRUPT", "RESTART", "SWAP", "CALL", "CLS", "BEEP", "LANINTERRUPT"})
        EXPECT_NE(cat::findStatement(s), nullptr) << s;
}

TEST(Sc750Catalog, VariablesAreUniqueReferencedAndConsistent) {
    std::set<std::string> names;
    for (const cat::VariableInfo& v : cat::variables()) {
        EXPECT_TRUE(names.insert(std::string(v.name)).second) << v.name;
        EXPECT_FALSE(v.manualLines.empty()) << v.name;
        if (v.type != cat::ValueType::String) {
            EXPECT_LE(v.minimum, v.defaultValue) << v.name;
            EXPECT_LE(v.defaultValue, v.maximum) << v.name;
        }
    }
    for (const char* n : {"INP16", "OUT12", "INTR.POS.ERROR", "INTR.I16LO", "TMENABLE6", "TMOUT_6", "WHEN.VELCMD",
                          "POS.COMMAND", "IN.POS.LIMIT", "AUTOSTART", "COMMOFF"})
        EXPECT_NE(cat::findVariable(n), nullptr) << n;
}

TEST(Sc750Catalog, ParametersAreTheBoilerplatesPlusAutostart) {
    int parameters = 0;
    for (const cat::VariableInfo& v : cat::variables())
        if (v.access == cat::Access::Parameter) ++parameters;
    EXPECT_EQ(parameters, 23); // 22 in the PARAMS boiler-plate (L945-L974) + AUTOSTART
    EXPECT_EQ(cat::findVariable("KVP")->defaultValue, 0.087086);
    EXPECT_EQ(cat::findVariable("BLKTYPE")->maximum, 3);
}

TEST(Sc750Catalog, LookupsIgnoreCase) {
    EXPECT_EQ(cat::findVariable("run.speed"), cat::findVariable("RUN.SPEED"));
    EXPECT_NE(cat::findFunction("mid$"), nullptr);
    EXPECT_EQ(cat::interruptIndex("pos.error"), 40);
    EXPECT_EQ(cat::findFault(244)->display, "F 4");
    EXPECT_EQ(cat::findFault(99), nullptr);
}

} // namespace

namespace {

double param(const std::vector<std::pair<std::string, double>>& values, const std::string& name) {
    for (const auto& [n, v] : values)
        if (n == name) return v;
    ADD_FAILURE() << name << " is not in the PARAMS block";
    return -1;
}

TEST(Sc750SetUp, AutoTakesTheMotorsValuesFromTheTable) { // Controller Set Up, L2486-L2512
    const auto small = cat::setupParameters("R32GENC", 752, false);
    const auto medium = cat::setupParameters("r45g", 752, false);
    EXPECT_NE(small, medium);
    EXPECT_EQ(param(small, "ILC"), 13); // the boiler-plate motor (L946-L950)
    EXPECT_EQ(param(small, "SIX.THRESH"), 430.664063);
    EXPECT_EQ(param(medium, "ILC"), 59); // the manual's auto set-up example (L2508-L2512)
    EXPECT_EQ(param(medium, "SIX.THRESH"), 3147.836538);
    EXPECT_EQ(param(medium, "SIG.THRESH"), 2833.052885);
    EXPECT_EQ(param(medium, "KVP"), 0.062053);
    EXPECT_EQ(param(cat::setupParameters("R63G", 752, false), "POLECOUNT"), 6);
    // every PARAMS parameter but AUTOSTART, in catalog order, for known and unknown motors alike
    const auto unknown = cat::setupParameters("X999", 0, false);
    ASSERT_EQ(unknown.size(), small.size());
    EXPECT_EQ(unknown.front().first, "POLECOUNT");
    EXPECT_EQ(param(unknown, "KVP"), cat::variables()[std::size_t(cat::variableIndex("KVP"))].defaultValue);
}

TEST(Sc750SetUp, AutoCapsTheCurrentAtTheMotorsPeakOnABiggerController) {         // the warning at L2438
    EXPECT_EQ(param(cat::setupParameters("R32G", 756, false), "ILMT.PLUS"), 16); // 7.2 A of 45 A
    EXPECT_EQ(param(cat::setupParameters("R32G", 756, false), "ILMT.MINUS"), 16);
    EXPECT_EQ(param(cat::setupParameters("R32G", 752, false), "ILMT.PLUS"), 96);  // 7.2 A of 7.5 A
    EXPECT_EQ(param(cat::setupParameters("R45G", 752, false), "ILMT.PLUS"), 100); // the controller is smaller
    EXPECT_EQ(param(cat::setupParameters("R32G", 0, false), "ILMT.PLUS"), 100);   // model unknown
    const auto gentle = cat::setupParameters("R45G", 752, true);
    EXPECT_DOUBLE_EQ(param(gentle, "KVP"), 0.062053 / 2);
    EXPECT_EQ(param(gentle, "ARF0"), 100);
}

// Manual set-up (L2530-L2553) runs the same rule on the user's data: KVP follows (rotor + load inertia) / Kt,
// ILC follows L/R, SIX.THRESH and SIG.THRESH follow Kt x peak current x max speed, POLECOUNT the poles.
TEST(Sc750SetUp, TheComputationFollowsTheSetUpData) {
    const cat::SetupData motor = cat::setupData("R45G", false);
    EXPECT_EQ(cat::setupParameters(motor, 752), cat::setupParameters("R45G", 752, false)); // Auto = this data
    cat::SetupData load = motor;
    load.loadInertia_kgcm2 = motor.rotorInertia_kgcm2; // a load as heavy as the rotor: twice the gain
    EXPECT_NEAR(param(cat::setupParameters(load, 752), "KVP"), 2 * 0.062053, 1e-6);
    cat::SetupData stronger = motor;
    stronger.torqueConstant_NmPerA *= 2; // twice the torque per amp: half the gain, twice the threshold
    EXPECT_NEAR(param(cat::setupParameters(stronger, 752), "KVP"), 0.062053 / 2, 1e-6);
    EXPECT_NEAR(param(cat::setupParameters(stronger, 752), "SIX.THRESH"), 2 * 3147.836538, 1e-5);
    EXPECT_NEAR(param(cat::setupParameters(stronger, 752), "SIG.THRESH"), 0.9 * 2 * 3147.836538, 1e-5);
    cat::SetupData slow = motor;
    slow.inductance_mH *= 2; // twice the electrical time constant
    EXPECT_EQ(param(cat::setupParameters(slow, 752), "ILC"), 118);
    slow.poleCount = 8;
    slow.peak_A = 3.75; // half of SC752's 7.5 A
    EXPECT_EQ(param(cat::setupParameters(slow, 752), "POLECOUNT"), 8);
    EXPECT_EQ(param(cat::setupParameters(slow, 752), "ILMT.PLUS"), 50);
    load.gentle = true;
    EXPECT_NEAR(param(cat::setupParameters(load, 752), "KVP"), 0.062053, 1e-6);
    // an unknown part is the boiler-plate motor: the catalog's defaults
    EXPECT_EQ(param(cat::setupParameters(cat::setupData("X999", false), 0), "SIG.THRESH"), 387.597656);
}

} // namespace
