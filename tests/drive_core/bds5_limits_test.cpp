// Writes from the terminal against the program limits of Appendix E (Table E.1 L7553-7684, Table E.2
// L7686-7691): a value outside them is ERR 83 BAD OR OUT OF RANGE, a parameter "too large or too small"
// (L7380-7382), and the variable keeps its value. Limits that are sets (ADDR) or other variables (ACC and
// DEC up to AMAX, VDEFAULT up to VMAX, VOSPD up to 1.2 VMAX, ILIM up to IMAX) included.
#include "bds5_test_drive.h"

#include "drive_core/catalog/bds5_catalog.h"

#include <string>

using namespace bds5_test;
namespace cat = drive_core::catalog::bds5;

namespace {

// The number P prints for a variable (user units), without its padding.
std::string value(TestDrive& t, const std::string& name) {
    const std::string out = t.type("P " + name + "\r");
    const auto start = out.find_first_not_of(' ', out.find("\r\n") + 2);
    return out.substr(start, out.find("\r\n", start) - start);
}

// "NAME=v" typed at -->: true when the drive answered only with the echo and the prompt.
bool accepted(TestDrive& t, const std::string& name, long long v) {
    const std::string line = name + "=" + std::to_string(v);
    return t.type(line + "\r") == line + "\r\n-->";
}

// "NAME=v" typed at -->: true when the drive answered ERR 83 naming the value, then the prompt.
bool refusedAsOutOfRange(TestDrive& t, const std::string& name, long long v) {
    const std::string out = t.type(name + "=" + std::to_string(v) + "\r");
    return out.find("\aERR 83 '" + std::to_string(v) + "'") != std::string::npos &&
           out.ends_with("BAD OR OUT OF RANGE\r\n-->");
}

} // namespace

// ADDR: "0,48-57,65-90" (Table E.1 L7558), valid addresses 48 ('0') to 57 ('9') and 65 ('A') to 90 ('Z')
// (L5424-5426). The values between the runs are no addresses, though they lie between 0 and 90.
TEST(Bds5Limits, AddressTakesOnlyZeroDigitsAndLetters) {
    TestDrive t;
    for (const long long bad : {1LL, 47LL, 58LL, 64LL, 91LL, -1LL}) {
        EXPECT_TRUE(refusedAsOutOfRange(t, "ADDR", bad)) << bad;
        EXPECT_EQ(value(t, "ADDR"), "0") << "a refused ADDR leaves the drive single-drop";
    }
    // Each run's ends are addresses: the drive takes the ID and sleeps until '\' + ID (L5449-5451).
    for (const long long good : {48LL, 57LL, 65LL, 90LL}) {
        const std::string line = "ADDR=" + std::to_string(good);
        EXPECT_EQ(t.type(line + "\r"), line + "\r\n") << good;
        const std::string id(1, char(good));
        EXPECT_EQ(t.type("\\" + id), "\r\n" + id + "->") << good;
        EXPECT_EQ(t.type("ADDR=0\r"), "ADDR=0\r\n-->") << "0 is single-drop again";
    }
}

TEST(Bds5Limits, CatalogKnowsTheAddressSet) { // Table E.1 L7558
    const auto addr = cat::findVariable("ADDR");
    ASSERT_TRUE(addr.has_value());
    for (const std::int64_t v : {0, 48, 53, 57, 65, 77, 90}) EXPECT_TRUE(cat::withinLimits(*addr->info, v)) << v;
    for (const std::int64_t v : {-1, 1, 32, 47, 58, 64, 91, 97}) EXPECT_FALSE(cat::withinLimits(*addr->info, v)) << v;
}

// "Attempting to set ACC to a value greater than AMAX will generate an error", DEC likewise (L2186-2188);
// Table E.1 gives both "0-AMAX" (L7556, L7571). AMAX is 100000 RPM/s at first (L1522).
TEST(Bds5Limits, AccAndDecAboveAmaxAreOutOfRange) {
    TestDrive t;
    const std::string amax = value(t, "AMAX");
    ASSERT_EQ(amax, "100000");
    for (const char* name : {"ACC", "DEC"}) {
        EXPECT_TRUE(accepted(t, name, 100000)) << name << ": up to AMAX";
        EXPECT_TRUE(refusedAsOutOfRange(t, name, 100001)) << name;
        EXPECT_TRUE(refusedAsOutOfRange(t, name, 1000000)) << name;
        EXPECT_EQ(value(t, name), "100000") << name << " keeps its value";
        EXPECT_TRUE(refusedAsOutOfRange(t, name, -1)) << name << ": 0-AMAX";
        EXPECT_TRUE(accepted(t, name, 0)) << name;
    }
    // AMAX changes only while disabled (L2180); raised, it lets ACC and DEC rise with it.
    EXPECT_TRUE(accepted(t, "AMAX", 200000));
    EXPECT_TRUE(accepted(t, "ACC", 200000));
    EXPECT_TRUE(accepted(t, "DEC", 150000));
    EXPECT_TRUE(refusedAsOutOfRange(t, "DEC", 200001));
}

// A program's ACC above AMAX is the same error, and it breaks the program (ERR 83 is severity 2, L7380).
TEST(Bds5Limits, ProgramAccAboveAmaxBreaksWithErr83) {
    TestDrive t;
    t.download({"1$", "ACC=500000", "P \"NOT REACHED\"", "B"});
    const std::string out = t.type("RUN 1\r", 50ms);
    EXPECT_NE(out.find("\aERR 83 LINE 2 '500000'"), std::string::npos) << out;
    EXPECT_EQ(out.find("NOT REACHED"), std::string::npos) << out;
}

// VDEFAULT "<VMAX" (L7665), read as up to VMAX, the way Table E.2's "<" bounds are (decision 3).
TEST(Bds5Limits, VdefaultUpToVmax) {
    TestDrive t;
    const long long vmax = std::stoll(value(t, "VMAX"));
    EXPECT_TRUE(accepted(t, "VDEFAULT", vmax));
    EXPECT_TRUE(refusedAsOutOfRange(t, "VDEFAULT", vmax + 1));
    EXPECT_EQ(value(t, "VDEFAULT"), std::to_string(vmax));
}

// "You can set VOSPD to any level below 1.2 VMAX" (L2048); its initial value is VMAX x 1.2 (L1563).
TEST(Bds5Limits, VospdUpToTwelveTenthsOfVmax) {
    TestDrive t;
    const long long vmax = std::stoll(value(t, "VMAX"));
    const long long cap = vmax * 12 / 10;
    EXPECT_EQ(value(t, "VOSPD"), std::to_string(cap));
    EXPECT_TRUE(refusedAsOutOfRange(t, "VOSPD", cap + 1));
    EXPECT_TRUE(accepted(t, "VOSPD", vmax));
    EXPECT_TRUE(accepted(t, "VOSPD", cap));
}

// ILIM "1-IMAX" (L7587), in percent of IMAX with the standard units (L1536-1538).
TEST(Bds5Limits, IlimFromOneToImax) {
    TestDrive t;
    EXPECT_TRUE(refusedAsOutOfRange(t, "ILIM", 0));
    EXPECT_TRUE(accepted(t, "ILIM", 1));
    EXPECT_TRUE(accepted(t, "ILIM", 100));
    EXPECT_TRUE(refusedAsOutOfRange(t, "ILIM", 101));
}

// The numeric limits of Table E.1 (with Table E.2's classes): each end is accepted, one beyond is ERR 83.
TEST(Bds5Limits, TableE1RangesAndClasses) {
    struct Limit {
        const char* name;
        long long low, high;
        const char* lines;
    };
    const Limit limits[] = {
        {"ABAUD", 0, 1, "L7555"},          {"BAUD", 300, 19200, "L7562"},  {"CAP", 0, 1, "L7563"},
        {"GEARI", -32768, 32767, "L7580"}, {"KC", 0, 255, "L7593"},        {"KP", 0, 32767, "L7595"},
        {"LPFHZ", 0, 500, "L7603"},        {"OUT", 0, 255, "L7614"},       {"PEMAX", 0, 32767, "L7620"},
        {"REGKHZ", 1, 2000, "L7642"},      {"WTIME", 0, 32767, "L7679"},   {"XS7", 0, 1, "L7681"},
    };
    for (const Limit& l : limits) {
        TestDrive t;
        EXPECT_TRUE(refusedAsOutOfRange(t, l.name, l.low - 1)) << l.name << " " << l.lines;
        EXPECT_TRUE(refusedAsOutOfRange(t, l.name, l.high + 1)) << l.name << " " << l.lines;
        EXPECT_TRUE(accepted(t, l.name, l.low)) << l.name << " " << l.lines;
        EXPECT_TRUE(accepted(t, l.name, l.high)) << l.name << " " << l.lines;
    }
}

// DUMP is made to be sent back to a drive (L5396-5414). A drive whose AMAX, ACC and DEC were raised is
// restored without an error: AMAX is listed before the ACC and DEC it bounds (decision 8).
TEST(Bds5Limits, DumpOfRaisedAmaxAndAccRestoresWithoutError) {
    TestDrive from;
    ASSERT_TRUE(accepted(from, "AMAX", 300000));
    ASSERT_TRUE(accepted(from, "ACC", 250000));
    ASSERT_TRUE(accepted(from, "DEC", 200000));
    const std::string dump = from.type("DUMP\r");
    ASSERT_TRUE(dump.ends_with("\r\n-->")) << dump.size();
    TestDrive to;
    int errors = 0;
    std::size_t start = dump.find("\r\n") + 2;
    for (std::size_t end; (end = dump.find("\r\n", start)) != std::string::npos; start = end + 2) {
        const std::string line = dump.substr(start, end - start);
        if (line.empty() || line == "-->") continue;
        const std::string answer = to.type(line + "\r");
        if (answer.find("\aERR") != std::string::npos) {
            ++errors;
            ADD_FAILURE() << line << " -> " << answer;
        }
    }
    EXPECT_EQ(errors, 0);
    EXPECT_EQ(value(to, "AMAX"), "300000");
    EXPECT_EQ(value(to, "ACC"), "250000");
    EXPECT_EQ(value(to, "DEC"), "200000");
}
