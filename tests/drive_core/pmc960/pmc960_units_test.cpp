// Engineering units (THC bit 4, TUS/TUP, L2050-2115) and their conversion errors: #98 a speed too small to
// move after conversion, #99 a position or distance that overflows after conversion (L2324-2325).
#include "pmc960_test_drive.h"

namespace pmc960_test {
namespace {

// TUS 0:5 (0.5 Hz per unit) puts TUS x TUV in the 48 kHz range, whose least speed is 2 x 10 Hz (5.7).
TEST(Pmc960Units, SpeedBelowTheRangesLeastAfterConversionIs98) {
    TestDrive t;
    t.writeEnable();
    EXPECT_EQ(t.type("TUS0:5\r"), prompted("TUS0:5"));
    EXPECT_EQ(t.type("V39\r"), prompted("V39")); // internal units: no conversion, no #98
    EXPECT_EQ(t.type("THC10\r"), prompted("THC10"));
    EXPECT_EQ(t.type("V39\r"), prompted("V39#98")); // 19.5 Hz
    EXPECT_EQ(t.type("V40\r"), prompted("V40"));    // 20 Hz
    EXPECT_EQ(t.type("V?"), prompted("V?40"));
    EXPECT_EQ(t.type("J39\r"), prompted("J39#98"));
    t.enable();
    EXPECT_EQ(t.type("J39+"), prompted("J39+#98"));
    EXPECT_FALSE(t.drive.state().motion.moving());
    EXPECT_EQ(t.type("C100:39\r"), prompted("C100:39#98"));
    EXPECT_EQ(t.type("J40+", 100ms), "J40+");
    EXPECT_TRUE(t.drive.state().motion.jogging());
}

// TUP 65535 counts per unit: past 32,769 units an index overflows 2^31 - 1 counts, past 16,384 a go or
// normalize position overflows 2^30.
TEST(Pmc960Units, PositionOverflowingAfterConversionIs99) {
    TestDrive t;
    t.writeEnable();
    EXPECT_EQ(t.type("TUP65535\r"), prompted("TUP65535"));
    EXPECT_EQ(t.type("I40000\r"), prompted("I40000")); // internal units: 40,000 counts
    EXPECT_EQ(t.type("THC10\r"), prompted("THC10"));
    EXPECT_EQ(t.type("I40000\r"), prompted("I40000#99"));
    EXPECT_EQ(t.type("I32768\r"), prompted("I32768"));
    EXPECT_EQ(t.type("N16385+"), prompted("N16385+#99"));
    EXPECT_EQ(t.type("N16384-"), prompted("N16384-"));
    EXPECT_EQ(t.type("G!"), prompted("G!-16384"));
    t.enable();
    EXPECT_EQ(t.type("G16385+"), prompted("G16385+#99"));
    EXPECT_EQ(t.type("I40000+"), prompted("I40000+#99"));
    EXPECT_FALSE(t.drive.state().motion.moving());
    EXPECT_EQ(t.type("C16385:1\r"), prompted("C16385:1#99"));
}

} // namespace
} // namespace pmc960_test
