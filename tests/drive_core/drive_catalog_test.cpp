// The common catalog schema against the manuals: one fact per family checked at its manual line, the
// indexed and extended BDS5 names, every family's errors with the code as the drive shows it, and the
// invariants every entry must keep (unique names, ranges in order, power-up values inside them).
#include "drive_core/catalog/drive_catalog.h"

#include <gtest/gtest.h>

#include <set>
#include <string>

namespace cat = drive_core::catalog;
using drive_core::DriveFamily;

namespace {
constexpr DriveFamily kFamilies[] = {DriveFamily::Bds5, DriveFamily::Sc750, DriveFamily::Pmc960};
}

// BDS5 manual L2046: VMAX, units VEL, factory-set; L2048-2050: VOSPD written only while disabled.
TEST(DriveCatalog, Bds5VariablesCarryTheirWriteConditions) {
    const cat::Parameter* vmax = cat::findParameter(DriveFamily::Bds5, "vmax");
    ASSERT_NE(vmax, nullptr);
    EXPECT_EQ(vmax->unit, "VEL");
    EXPECT_EQ(vmax->writable, cat::Writable::Factory);
    EXPECT_EQ(cat::findParameter(DriveFamily::Bds5, "VOSPD")->writable, cat::Writable::WhenDisabled);
    // X1..X250, and X251..X750 that EXTDX adds (L9309); no X0, no bare stem.
    const cat::Parameter* x = cat::findParameter(DriveFamily::Bds5, "X12");
    ASSERT_NE(x, nullptr);
    EXPECT_EQ(x->name, "X");
    EXPECT_EQ(x->firstIndex, 1);
    EXPECT_EQ(x->lastIndex, 250);
    EXPECT_EQ(cat::findParameter(DriveFamily::Bds5, "X600"), x);
    EXPECT_EQ(cat::findParameter(DriveFamily::Bds5, "X0"), nullptr);
    EXPECT_EQ(cat::findParameter(DriveFamily::Bds5, "X"), nullptr);
    EXPECT_EQ(cat::findParameter(DriveFamily::Bds5, "X12A"), nullptr);
}

// SC750 manual L950: KVP, a FLOAT set-up parameter, 0.087086 in the example PARAMS block.
TEST(DriveCatalog, Sc750ParametersAreDecimalsKeptWithoutPower) {
    const cat::Parameter* kvp = cat::findParameter(DriveFamily::Sc750, "KVP");
    ASSERT_NE(kvp, nullptr);
    EXPECT_EQ(kvp->type, cat::ValueType::Decimal);
    EXPECT_TRUE(kvp->nonVolatile);
    ASSERT_TRUE(kvp->powerUp);
    EXPECT_DOUBLE_EQ(*kvp->powerUp, 0.087086);
}

// PMC-960 manual L912, the parameter table: Position Loop Gain (TGP) 0-255, factory value 16 (L208 and L607 say
// "1 to 255" for the adjustment; the table's range is what TGP accepts).
TEST(DriveCatalog, Pmc960GainsSpanAByteFromTheirFactoryValue) {
    const cat::Parameter* tgp = cat::findParameter(DriveFamily::Pmc960, "TGP");
    ASSERT_NE(tgp, nullptr);
    EXPECT_TRUE(tgp->ranged);
    EXPECT_EQ(tgp->minimum, 0);
    EXPECT_EQ(tgp->maximum, 255);
    EXPECT_EQ(tgp->powerUp, 16);
    EXPECT_TRUE(tgp->nonVolatile);
    EXPECT_EQ(tgp->group, "Parameter table (T)");
}

TEST(DriveCatalog, ErrorsReadAsTheDriveShowsThem) {
    const cat::ErrorEntry* pe = cat::findError(DriveFamily::Bds5, 25); // L7230: ERROR 25 "PE OVERFLOW"
    ASSERT_NE(pe, nullptr);
    EXPECT_EQ(pe->codeText, "25");
    EXPECT_EQ(pe->message, "PE OVERFLOW");
    const cat::ErrorEntry* b6 = cat::findError(DriveFamily::Pmc960, 0xB6); // L2351: servodrive not enabled
    ASSERT_NE(b6, nullptr);
    EXPECT_EQ(b6->codeText, "#B6");
    EXPECT_EQ(b6->severity, "Refused");
    EXPECT_NE(b6->whatToDo.find("SM1"), std::string_view::npos);
    const cat::ErrorEntry* enabled = cat::findError(DriveFamily::Sc750, 8); // L235: "8" = enabled, no fault
    ASSERT_NE(enabled, nullptr);
    EXPECT_EQ(enabled->level, cat::ErrorLevel::Info);
    EXPECT_EQ(cat::findError(DriveFamily::Sc750, 9999), nullptr);
}

TEST(DriveCatalog, EveryEntryKeepsTheSchemasInvariants) {
    for (DriveFamily family : kFamilies) {
        SCOPED_TRACE(int(family));
        std::set<std::string_view> names;
        ASSERT_FALSE(cat::parameters(family).empty());
        for (const cat::Parameter& p : cat::parameters(family)) {
            SCOPED_TRACE(std::string(p.name));
            EXPECT_TRUE(names.insert(p.name).second) << "listed twice";
            EXPECT_FALSE(p.group.empty());
            EXPECT_FALSE(p.manualLines.empty());
            EXPECT_LE(p.firstIndex, p.lastIndex);
            if (!p.ranged) continue;
            EXPECT_LE(p.minimum, p.maximum);
            if (p.powerUp && p.writable != cat::Writable::Never) {
                EXPECT_GE(*p.powerUp, p.minimum);
                EXPECT_LE(*p.powerUp, p.maximum);
            }
        }
        std::set<int> codes;
        ASSERT_FALSE(cat::errors(family).empty());
        for (const cat::ErrorEntry& e : cat::errors(family)) {
            EXPECT_TRUE(codes.insert(e.code).second) << "code " << e.code << " listed twice";
            EXPECT_FALSE(e.codeText.empty());
            EXPECT_FALSE(e.severity.empty());
            EXPECT_EQ(cat::findError(family, e.code), &e);
        }
    }
}
