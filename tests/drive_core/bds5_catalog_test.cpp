// The BDS5 catalog answers look-ups the simulator and the IDE rely on.
#include "drive_core/catalog/bds5_catalog.h"

#include <gtest/gtest.h>

namespace cat = drive_core::catalog::bds5;

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
    EXPECT_FALSE(cat::findVariable("X251"));
    EXPECT_FALSE(cat::findVariable("X0"));
    auto xs3 = cat::findVariable("XS3");
    ASSERT_TRUE(xs3);
    EXPECT_EQ(xs3->info->name, "XS");
}
