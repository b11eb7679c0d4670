// The BDS5 catalog answers look-ups the simulator and the IDE rely on, with the manual's numbers and texts.
#include "drive_core/catalog/bds5_catalog.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>

namespace cat = drive_core::catalog::bds5;

namespace {

const cat::VariableInfo& variable(std::string_view name) {
    const auto ref = cat::findVariable(name);
    if (!ref) throw std::runtime_error("no variable " + std::string(name));
    return *ref->info;
}

bool hasLowerCase(std::string_view s) {
    return std::any_of(s.begin(), s.end(), [](char c) { return std::islower(static_cast<unsigned char>(c)); });
}

// Basic units from the standard user units (digest §5.8): RPM x 44739/10, RPM/s x 4474/1000.
constexpr std::int64_t rpmToBasic(std::int64_t rpm) {
    return (rpm * 44739 + 5) / 10;
}
constexpr std::int64_t rpmPerSecondToBasic(std::int64_t rpmPerS) {
    return (rpmPerS * 4474 + 500) / 1000;
}

} // namespace

TEST(Bds5Catalog, ZeroDivideHasTheManualsText) {
    const cat::ErrorInfo* e = cat::findError(92);
    ASSERT_NE(e, nullptr);
    EXPECT_EQ(e->message, "ZERO DIVIDE");
}

TEST(Bds5Catalog, IndexedUserVariablesResolve) {
    auto x12 = cat::findVariable("X12");
    ASSERT_TRUE(x12);
    EXPECT_EQ(x12->info->name, "X");
    EXPECT_EQ(x12->index, 12);
    // v3: X251-X750 resolve (the drive decides with EXTDX whether they exist, L9309); nothing past X750.
    const auto x251 = cat::findVariable("X251");
    ASSERT_TRUE(x251);
    EXPECT_EQ(x251->info, x12->info);
    EXPECT_EQ(x251->index, 251);
    EXPECT_TRUE(cat::findVariable("X750"));
    EXPECT_FALSE(cat::findVariable("X751"));
    EXPECT_FALSE(cat::findVariable("X0"));
    auto xs3 = cat::findVariable("XS3");
    ASSERT_TRUE(xs3);
    EXPECT_EQ(xs3->info->name, "XS");
}

// ---- Errors (App. D) ----

TEST(Bds5CatalogErrors, HasExactlyTheHundredDistinctCodesInAscendingOrder) {
    const auto table = cat::errors();
    EXPECT_EQ(table.size(), 100u);
    std::set<int> codes;
    for (const cat::ErrorInfo& e : table) codes.insert(e.code);
    EXPECT_EQ(codes.size(), table.size()) << "duplicate error codes";
    EXPECT_TRUE(std::is_sorted(table.begin(), table.end(),
                               [](const cat::ErrorInfo& a, const cat::ErrorInfo& b) { return a.code < b.code; }));
    EXPECT_EQ(*codes.begin(), 2);
    EXPECT_EQ(*codes.rbegin(), 255);
}

TEST(Bds5CatalogErrors, EveryErrorHasMessageMeaningAndManualLines) {
    for (const cat::ErrorInfo& e : cat::errors()) {
        SCOPED_TRACE(e.code);
        EXPECT_FALSE(e.message.empty());
        EXPECT_FALSE(e.meaning.empty());
        EXPECT_TRUE(e.manualLines.starts_with("L")) << e.manualLines;
        // Upper case as the drive prints it; only the manual's "w/" and "w/o" abbreviations are lower case.
        std::string withoutAbbreviations(e.message);
        for (const char* abbreviation : {"w/o", "w/"}) {
            for (auto at = withoutAbbreviations.find(abbreviation); at != std::string::npos;
                 at = withoutAbbreviations.find(abbreviation))
                withoutAbbreviations.erase(at, std::string_view(abbreviation).size());
        }
        EXPECT_FALSE(hasLowerCase(withoutAbbreviations)) << e.message;
        EXPECT_LE(e.message.size(), 40u) << "messages are abbreviated to fit after column 40";
    }
}

TEST(Bds5CatalogErrors, SpotChecksAgainstTheManual) {
    struct Expected {
        int code;
        std::string_view message;
        cat::Severity severity;
    };
    const Expected expected[] = {
        {2, "HARDWARE- U-P FAIL", cat::Severity::Firmware},
        {5, "+5 VOLTS", cat::Severity::Firmware},
        {10, "REMOTE OFF", cat::Severity::Break},
        {17, "FEEDBACK LOSS", cat::Severity::Disable},
        {25, "PE OVERFLOW", cat::Severity::Disable},
        {42, "MOVE w/o TIME", cat::Severity::Break},
        {50, "DRIVE INHIBITED", cat::Severity::Break},
        {52, "NOT FROM TERMINAL", cat::Severity::Warning},
        {63, "NOT AT THIS LEVEL", cat::Severity::Break},
        {65, "RECORD NOT READY", cat::Severity::Disable},
        {74, "ERROR$ MUST BE LAST", cat::Severity::Break},
        {83, "BAD OR OUT OF RANGE", cat::Severity::Break},
        {94, ">2 PARENTHESES", cat::Severity::Break},
        {97, "GEAR OVERFLOW", cat::Severity::Disable},
        {103, "BAUD RATE", cat::Severity::HistoryOnly},
        {104, "ABAUD & MULTIDROP", cat::Severity::HistoryOnly},
        {105, "SERIAL WDOG", cat::Severity::Disable},
        {110, "EDIT PASSWORD", cat::Severity::Warning},
        {111, "FACTORY SETTABLE", cat::Severity::Break},
        {115, "IF w/o ENDIF", cat::Severity::Break},
        {199, "DRIVE POWERED UP", cat::Severity::HistoryOnly},
        {202, "USER PROGRAM CORRUPT", cat::Severity::Disable},
        {205, "MBUF OVRRUN", cat::Severity::Disable},
        {255, "UNKNOWN", cat::Severity::Disable},
    };
    for (const Expected& x : expected) {
        SCOPED_TRACE(x.code);
        const cat::ErrorInfo* e = cat::findError(x.code);
        ASSERT_NE(e, nullptr);
        EXPECT_EQ(e->message, x.message);
        EXPECT_EQ(e->severity, x.severity);
    }
}

TEST(Bds5CatalogErrors, InternalErrors211To219AreListedOneByOne) {
    for (int n = 1; n <= 9; ++n) {
        const cat::ErrorInfo* e = cat::findError(210 + n);
        ASSERT_NE(e, nullptr) << 210 + n;
        EXPECT_EQ(e->message, "INTERNAL " + std::to_string(n));
        EXPECT_EQ(e->severity, cat::Severity::Disable);
    }
}

TEST(Bds5CatalogErrors, FirmwareErrorsAreExactlyTwoToFiveAndUnknownCodesAreAbsent) {
    for (const cat::ErrorInfo& e : cat::errors())
        EXPECT_EQ(e.severity == cat::Severity::Firmware, e.code >= 2 && e.code <= 5) << e.code;
    for (int missing : {0, 1, 6, 16, 21, 49, 91, 100, 106, 112, 120, 198, 207, 210, 220, 254, 256})
        EXPECT_EQ(cat::findError(missing), nullptr) << missing;
}

// ---- Commands (App. C, assignment, v3.0.0, editor) ----

TEST(Bds5CatalogCommands, EveryFormHasSyntaxModesAndSaneEntryCounts) {
    const auto table = cat::commands();
    EXPECT_GE(table.size(), 64u);
    EXPECT_EQ(table.size(), 64u) << "49 App. C + assignment + 6 v3.0.0 + 8 editor commands";
    for (const cat::CommandInfo& c : table) {
        SCOPED_TRACE(std::string(c.name));
        EXPECT_FALSE(c.name.empty());
        EXPECT_FALSE(hasLowerCase(c.name));
        EXPECT_FALSE(c.longName.empty());
        EXPECT_FALSE(c.syntax.empty());
        EXPECT_FALSE(c.description.empty());
        EXPECT_FALSE(c.manualLines.empty());
        EXPECT_NE(c.modes, 0u);
        EXPECT_GE(c.minEntries, 0);
        EXPECT_LE(c.minEntries, c.maxEntries);
        EXPECT_LE(c.maxEntries, 14) << "the command word is one of the 15 entries";
    }
}

TEST(Bds5CatalogCommands, NamesAreUniquePerModeFamily) {
    std::set<std::pair<std::string_view, bool>> seen;
    for (const cat::CommandInfo& c : cat::commands()) {
        const bool editorOnly = c.modes == cat::kEditor;
        EXPECT_TRUE(seen.insert({c.name, editorOnly}).second) << "duplicate " << c.name;
    }
}

TEST(Bds5CatalogCommands, PrintIsFoundBeforeTheEditorPrint) {
    const cat::CommandInfo* p = cat::findCommand("P");
    ASSERT_NE(p, nullptr);
    EXPECT_EQ(p->longName, "PRINT");
    EXPECT_EQ(p->modes, unsigned(cat::kInteractive | cat::kMonitor | cat::kProgram));
    EXPECT_EQ(p->minEntries, 1);
    EXPECT_EQ(p->maxEntries, 14);
    const auto table = cat::commands();
    const auto editorPrint = std::find_if(
        table.begin(), table.end(), [](const cat::CommandInfo& c) { return c.name == "P" && c.modes == cat::kEditor; });
    ASSERT_NE(editorPrint, table.end());
    EXPECT_EQ(editorPrint->maxEntries, 2); // P BEG END
}

TEST(Bds5CatalogCommands, SpecialFormsAndBlockIfArePresent) {
    for (std::string_view name : {";", "$", "=", "?", "IF", "ELIF", "ELSE", "ENDIF", "ERR", "DUMP", "<BDS", ">BDS",
                                  "PASS", "DEL", "SIZE", "NEW", "I", "F", "C"})
        EXPECT_NE(cat::findCommand(name), nullptr) << name;
    for (std::string_view name : {"IF", "ELIF", "ELSE", "ENDIF"})
        EXPECT_EQ(cat::findCommand(name)->modes, unsigned(cat::kProgram)) << name;
    EXPECT_EQ(cat::findCommand("IF")->minEntries, 3);
    EXPECT_EQ(cat::findCommand("ED")->modes, unsigned(cat::kInteractive));
    EXPECT_EQ(cat::findCommand("NEW")->modes, unsigned(cat::kEditor));
    EXPECT_EQ(cat::findCommand("PRINT"), nullptr) << "names are as typed";
}

TEST(Bds5CatalogCommands, VersionThreeAdditionsAreFlaggedAndEchoMsgMonitorAreVariables) {
    std::set<std::string_view> v3;
    for (const cat::CommandInfo& c : cat::commands())
        if (c.version3) v3.insert(c.name);
    EXPECT_EQ(v3, (std::set<std::string_view>{"PA", "PAS", "CLEARX", "RAND", "TRECORD", "TPLAY"}));
    for (std::string_view name : {"ECHO", "MSG", "MONITOR", "EXTDX"}) {
        EXPECT_EQ(cat::findCommand(name), nullptr) << name;
        ASSERT_TRUE(cat::findVariable(name)) << name;
        EXPECT_TRUE(cat::findVariable(name)->info->version3) << name;
    }
    EXPECT_TRUE(cat::findCommand("RUN")->modes & cat::kProgram) << "v3.0.0 allows RUN in a program";
}

TEST(Bds5CatalogCommands, MonitorModeAcceptsExactlyTable24) {
    std::set<std::string_view> monitor;
    for (const cat::CommandInfo& c : cat::commands())
        if (c.modes & cat::kMonitor) monitor.insert(c.name);
    // Table 2.4 (L1300-1304) plus assignments and the v3.0.0 print forms.
    const std::set<std::string_view> expected{"?",  ";", "B",  "DIS", "EN",  "ERR", "K",  "MOTOR", "P",
                                              "PS", "R", "RS", "S",   "ZPE", "=",   "PA", "PAS"};
    EXPECT_EQ(monitor, expected);
}

TEST(Bds5CatalogCommands, OnlyTheDocumentedCommandsIdle) {
    std::set<std::string_view> idling;
    for (const cat::CommandInfo& c : cat::commands())
        if (c.idling) idling.insert(c.name);
    EXPECT_EQ(idling, (std::set<std::string_view>{"D", "H", "INPUT", "W", "RD"}));
    EXPECT_FALSE(cat::findCommand("TIL")->idling) << "TIL busy-waits (L4754-4766)";
}

TEST(Bds5CatalogCommands, NoCommandWordIsAlsoAVariable) {
    for (const cat::CommandInfo& c : cat::commands())
        EXPECT_FALSE(cat::findVariable(c.name)) << c.name << " would be read as an assignment";
}

// ---- Variables (App. E) ----

TEST(Bds5CatalogVariables, CountsAndUniqueNames) {
    // 121 rows of Table E.1 - 3 (TMR1-TMR4 is one family) - 1 (X(Xn) is syntax, not a variable)
    // + 6 v3.0.0 + RTMR + CHECKSUM + 22 rows of Table E.3.
    EXPECT_EQ(cat::variables().size(), 147u);
    std::set<std::string_view> names;
    for (const cat::VariableInfo& v : cat::variables()) {
        SCOPED_TRACE(std::string(v.name));
        EXPECT_TRUE(names.insert(v.name).second) << "duplicate";
        EXPECT_FALSE(hasLowerCase(v.name));
        EXPECT_FALSE(v.description.empty());
        EXPECT_FALSE(v.manualLines.empty());
        EXPECT_EQ(v.firstIndex == 0, v.lastIndex == 0);
        EXPECT_LE(v.firstIndex, v.lastIndex);
    }
}

TEST(Bds5CatalogVariables, FamiliesResolveWithTheirIndexRange) {
    // Table E.1's ranges; X alone is extended, by v3's EXTDX to X750 (L9309).
    struct Family {
        std::string_view stem;
        int last;
        int extendedLast;
    };
    const Family families[] = {{"X", 250, 750}, {"XS", 50, 0}, {"I", 16, 0}, {"O", 8, 0}, {"TMR", 4, 0}, {"A", 16, 0}};
    for (const auto& [stem, last, extendedLast] : families) {
        SCOPED_TRACE(std::string(stem));
        const auto first = cat::findVariable(std::string(stem) + "1");
        ASSERT_TRUE(first);
        EXPECT_EQ(first->info->name, stem);
        EXPECT_EQ(first->info->firstIndex, 1);
        EXPECT_EQ(first->info->lastIndex, last);
        EXPECT_EQ(first->info->extendedLastIndex, extendedLast);
        EXPECT_EQ(first->info->extendedBy, extendedLast ? "EXTDX" : "");
        const int highest = extendedLast ? extendedLast : last;
        EXPECT_EQ(cat::highestIndex(*first->info), highest);
        EXPECT_TRUE(cat::findVariable(std::string(stem) + std::to_string(highest)));
        EXPECT_FALSE(cat::findVariable(std::string(stem) + std::to_string(highest + 1)));
        EXPECT_FALSE(cat::findVariable(stem)) << "a family needs an index";
    }
    const auto tmr2 = cat::findVariable("TMR2");
    ASSERT_TRUE(tmr2);
    EXPECT_EQ(tmr2->info->name, "TMR");
    EXPECT_EQ(tmr2->index, 2);
    const auto i16 = cat::findVariable("I16");
    ASSERT_TRUE(i16);
    EXPECT_EQ(i16->info->name, "I");
    EXPECT_EQ(i16->index, 16);
    EXPECT_FALSE(cat::findVariable("O9"));
    EXPECT_FALSE(cat::findVariable("O0"));
    EXPECT_EQ(cat::findVariable("IN")->info->name, "IN") << "plain names win over the I family";
    EXPECT_EQ(cat::findVariable("OUT")->info->name, "OUT");
    EXPECT_EQ(cat::findVariable("IN")->index, 0);
}

TEST(Bds5CatalogVariables, SwitchesAreZeroOrOne) {
    for (const cat::VariableInfo& v : cat::variables()) {
        SCOPED_TRACE(std::string(v.name));
        EXPECT_EQ(v.isSwitch, v.limits == cat::LimitClass::Switch);
        if (v.isSwitch) {
            EXPECT_TRUE(v.powerUpValue == 0 || v.powerUpValue == 1);
        }
    }
}

TEST(Bds5CatalogVariables, PowerUpValuesLieWithinTheirLimits) {
    for (const cat::VariableInfo& v : cat::variables()) {
        SCOPED_TRACE(std::string(v.name));
        EXPECT_LE(cat::minimumOf(v), v.powerUpValue);
        EXPECT_GE(cat::maximumOf(v), v.powerUpValue);
        EXPECT_LE(cat::minimumOf(v), cat::maximumOf(v));
        if (v.unitClass == cat::UnitClass::Position || v.unitClass == cat::UnitClass::Velocity ||
            v.unitClass == cat::UnitClass::Acceleration || v.unitClass == cat::UnitClass::Current) {
            EXPECT_FALSE(v.units.empty()) << "scaled variables print their unit";
        }
    }
}

TEST(Bds5CatalogVariables, Table32PowerUpStateOfSwitches) {
    for (std::string_view name : {"CAP", "CLAMP", "DEP", "EXTLOOP", "FAULT", "GATEMODE", "GEAR", "O1", "O8", "PROP",
                                  "RAMP", "REG", "ROTARY", "SS", "STATMODE", "TRC", "TQ", "WATCH", "ZERO"}) {
        const cat::VariableInfo& v = variable(name);
        EXPECT_EQ(v.powerUpValue, 0) << name;
        EXPECT_EQ(v.persistence, cat::Persistence::Volatile) << name;
    }
    for (std::string_view name : {"CAPDIR", "DIR", "MULTI", "PL", "PLIM", "PROMPT", "TRIP"}) {
        const cat::VariableInfo& v = variable(name);
        EXPECT_EQ(v.powerUpValue, 1) << name;
        EXPECT_EQ(v.persistence, cat::Persistence::Volatile) << name;
    }
    for (std::string_view name : {"ABAUD", "LPF", "XS1", "ECHO", "MSG", "EXTDX"})
        EXPECT_EQ(variable(name).persistence, cat::Persistence::Remembered) << name;
    EXPECT_EQ(variable("MONITOR").persistence, cat::Persistence::Volatile);
}

TEST(Bds5CatalogVariables, DefaultsTheSimulatorNeeds) {
    const std::pair<std::string_view, std::int64_t> defaults[] = {
        {"PROMPT", 1},    {"ECHO", 1},    {"MSG", 1},     {"ADDR", 0},      {"ABAUD", 0},     {"BAUD", 9600},
        {"WTIME", 1000},  {"PNUM", 1},    {"PDEN", 1},    {"VNUM", 44739},  {"VDEN", 10},     {"ANUM", 4474},
        {"ADEN", 1000},   {"INUM", 4095}, {"IDEN", 100},  {"VXNUM", 44739}, {"VXDEN", 10},    {"PXNUM", 1},
        {"PXDEN", 1},     {"GEARI", 1},   {"GEARO", 3},   {"SCRV", 2},      {"REGKHZ", 1000}, {"PEMAX", 32767},
        {"PECLAMP", 100}, {"PMAX", 100},  {"PMIN", -100}, {"KF", 0},        {"KC", 200},      {"OUT", 0},
        {"PFB", 0},       {"TMR3", 0},    {"X250", 0},
    };
    for (const auto& [name, value] : defaults) EXPECT_EQ(variable(name).powerUpValue, value) << name;
}

TEST(Bds5CatalogVariables, RpmValuesAreStoredInBasicUnits) {
    EXPECT_EQ(variable("VMAX").powerUpValue, rpmToBasic(7500));
    EXPECT_EQ(variable("VOSPD").powerUpValue, rpmToBasic(9000)) << "1.2 x VMAX";
    EXPECT_EQ(variable("VDEFAULT").powerUpValue, rpmToBasic(1));
    for (std::string_view name : {"ACC", "DEC", "AMAX"})
        EXPECT_EQ(variable(name).powerUpValue, rpmPerSecondToBasic(100000)) << name;
    EXPECT_EQ(variable("ILIM").powerUpValue, 4095) << "100 % x 4095/100";
}

TEST(Bds5CatalogVariables, LimitsFromTableE1) {
    const cat::VariableInfo& baud = variable("BAUD");
    EXPECT_EQ(baud.limits, cat::LimitClass::Range);
    EXPECT_EQ(cat::minimumOf(baud), 300);
    EXPECT_EQ(cat::maximumOf(baud), 19200);
    const cat::VariableInfo& kf = variable("KF");
    EXPECT_EQ(kf.limits, cat::LimitClass::ShortPositive);
    EXPECT_EQ(cat::minimumOf(kf), 0);
    EXPECT_EQ(cat::maximumOf(kf), 32767);
    EXPECT_EQ(variable("PEMAX").limits, cat::LimitClass::ShortPositive);
    EXPECT_EQ(variable("GEARI").limits, cat::LimitClass::Short);
    EXPECT_EQ(variable("AMAX").limits, cat::LimitClass::LongPositive);
    EXPECT_EQ(variable("TMR1").limits, cat::LimitClass::LongPositive);
    EXPECT_EQ(variable("X7").limits, cat::LimitClass::Long);
    EXPECT_EQ(cat::maximumOf(variable("OUT")), 255);
    EXPECT_EQ(cat::maximumOf(variable("KC")), 255);
    EXPECT_EQ(cat::maximumOf(variable("LPFHZ")), 500);
    EXPECT_EQ(cat::minimumOf(variable("REGKHZ")), 1);
    EXPECT_EQ(cat::maximumOf(variable("REGKHZ")), 2000);
    EXPECT_EQ(cat::maximumOf(variable("ADDR")), 90);
    EXPECT_EQ(cat::minimumOf(variable("GEARO")), 1);
}

TEST(Bds5CatalogVariables, ProgrammingConditionsFromTableE1) {
    EXPECT_EQ(variable("PFB").write, cat::WriteCondition::NoMotion);
    for (std::string_view name : {"AMAX", "VOSPD", "EXTLOOP"})
        EXPECT_EQ(variable(name).write, cat::WriteCondition::Disabled) << name;
    for (std::string_view name : {"VMAX", "IMAX", "ICONT", "AMPS", "VOLTS", "POLES", "FOLDT"})
        EXPECT_EQ(variable(name).write, cat::WriteCondition::Factory) << name;
    for (std::string_view name : {"PCMD", "PE", "VFB", "VCMD", "ICMD", "IMON", "IN", "I3", "ACTIVE", "READY", "REMOTE",
                                  "LSTERR", "SEG", "PRD", "CAM", "PCAM", "ON", "N", "SLIP"})
        EXPECT_EQ(variable(name).write, cat::WriteCondition::Never) << name;
    for (std::string_view name : {"O1", "OUT", "X1", "XS1", "TMR4", "LSTLBL", "PEXT", "ILIM"})
        EXPECT_EQ(variable(name).write, cat::WriteCondition::Always) << name;
}

TEST(Bds5CatalogVariables, RecordCannotSampleTheForbiddenVariables) {
    for (std::string_view name : {"PE", "REMOTE", "TMR1", "TMR4", "VAVG", "VXAVG", "XS1", "XS50"})
        EXPECT_FALSE(variable(name).recordable) << name;
    for (std::string_view name : {"PFB", "PCMD", "VFB", "VCMD", "ICMD", "X1", "O1", "I1", "PEXT"})
        EXPECT_TRUE(variable(name).recordable) << name;
}

TEST(Bds5CatalogVariables, VersionThreeVariablesAreFlagged) {
    std::set<std::string_view> v3;
    for (const cat::VariableInfo& v : cat::variables())
        if (v.version3) v3.insert(v.name);
    EXPECT_EQ(v3, (std::set<std::string_view>{"MONITOR", "ECHO", "MSG", "EXTDX", "CAM", "PCAM"}));
}

TEST(Bds5CatalogVariables, UnitsAsTheManualPrintsThem) {
    EXPECT_EQ(variable("VMAX").units, "VEL");
    EXPECT_EQ(variable("VMAX").unitClass, cat::UnitClass::Velocity);
    EXPECT_EQ(variable("ACC").units, "ACC");
    EXPECT_EQ(variable("ACC").unitClass, cat::UnitClass::Acceleration);
    EXPECT_EQ(variable("PMAX").units, "POS");
    EXPECT_EQ(variable("ILIM").units, "I");
    EXPECT_EQ(variable("ILIM").unitClass, cat::UnitClass::Current);
    EXPECT_EQ(variable("TMR1").units, "ms");
    EXPECT_EQ(variable("WTIME").units, "ms");
    EXPECT_EQ(variable("LPFHZ").units, "Hz");
    EXPECT_EQ(variable("REGKHZ").units, "kHz");
    EXPECT_EQ(variable("PEXT").unitClass, cat::UnitClass::ExtPosition);
    EXPECT_EQ(variable("VEXT").unitClass, cat::UnitClass::ExtVelocity);
    EXPECT_EQ(variable("PRD").unitClass, cat::UnitClass::None) << "raw R/D counts are never scaled";
    EXPECT_TRUE(variable("BAUD").units.empty());
}

TEST(Bds5CatalogVariables, LimitClassBoundsOfTableE2) {
    const std::pair<cat::LimitClass, std::pair<std::int64_t, std::int64_t>> classes[] = {
        {cat::LimitClass::Long, {-2147483648LL, 2147483647LL}},
        {cat::LimitClass::LongPositive, {0, 2147483647LL}},
        {cat::LimitClass::Short, {-32768, 32767}},
        {cat::LimitClass::ShortPositive, {0, 32767}},
        {cat::LimitClass::Switch, {0, 1}},
        {cat::LimitClass::None, {-2147483648LL, 2147483647LL}},
    };
    for (const auto& [limits, bounds] : classes) {
        cat::VariableInfo v{.name = "T", .limits = limits, .minimum = 7, .maximum = 9};
        EXPECT_EQ(cat::minimumOf(v), bounds.first) << int(limits);
        EXPECT_EQ(cat::maximumOf(v), bounds.second) << int(limits);
    }
    const cat::VariableInfo range{.name = "T", .limits = cat::LimitClass::Range, .minimum = 7, .maximum = 9};
    EXPECT_EQ(cat::minimumOf(range), 7);
    EXPECT_EQ(cat::maximumOf(range), 9);
}

// The IDE's help for PLAY is the catalog's description: it must say how to read the listing (the layout
// bds5_recorder.h chose, checked against the drive in Bds5Record.PlayListsOneLinePerInstantInRecordOrder).
TEST(Bds5Catalog, PlayHelpDescribesTheListing) {
    const cat::CommandInfo* play = cat::findCommand("PLAY");
    ASSERT_NE(play, nullptr);
    const std::string_view help = play->description;
    for (const char* phrase :
         {"RECORD <n> <t> <v1> [<v2> <v3> <v4>]", "one line per sampled instant", "in RECORD order",
          "integer in user units", "right-justified in 12 columns", "CR LF", "ERR 65"})
        EXPECT_NE(help.find(phrase), std::string_view::npos) << phrase;
}
