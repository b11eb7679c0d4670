// The PLAY listing parser (the simulated BDS5's layout and malformed listings) and the .CSV layout
// (round trip, files without the RECORD line, errors named by line).
#include "scope/capture_csv.h"
#include "scope/play_parser.h"

#include <gtest/gtest.h>

using scope::Capture;
using scope::parsePlay;
using scope::readCsv;
using scope::writeCsv;

namespace {
std::string unitOf(const std::string& name) {
    return name == "ICMD" ? "I" : "VEL";
}
} // namespace

TEST(PlayParser, ReadsTheDrivesListingWithUnits) {
    const std::vector<std::string> lines = {"RECORD 3 2 VCMD VFB ICMD", "           0           0           0",
                                            "         500         498          12",
                                            "        1000        1003          -4"};
    const auto r = parsePlay(lines, unitOf);
    ASSERT_TRUE(r.capture) << r.error;
    const Capture& c = *r.capture;
    EXPECT_EQ(r.requestedSamples, 3);
    EXPECT_DOUBLE_EQ(c.interval_s, 0.002);
    ASSERT_EQ(c.channels.size(), 3u);
    EXPECT_EQ(c.channels[1].name, "VFB");
    EXPECT_EQ(c.channels[1].unit, "VEL");
    EXPECT_EQ(c.channels[2].unit, "I");
    EXPECT_EQ(c.channels[1].values, (std::vector<double>{0, 498, 1003}));
    EXPECT_EQ(c.channels[2].values.back(), -4);
    EXPECT_DOUBLE_EQ(c.timeAt(2), 0.004);
}

TEST(PlayParser, AcceptsDecimalsAndFewerRowsThanRequested) {
    const auto r = parsePlay({"", "RECORD 100 10 PFB", "      12.500", "     -3.25"});
    ASSERT_TRUE(r.capture) << r.error;
    EXPECT_EQ(r.requestedSamples, 100);
    EXPECT_EQ(r.capture->channels[0].values, (std::vector<double>{12.5, -3.25}));
}

TEST(PlayParser, NamesTheLineItCannotRead) {
    EXPECT_EQ(parsePlay({}).error, "PLAY printed nothing");
    EXPECT_NE(parsePlay({"HELLO"}).error.find("line 1"), std::string::npos);
    EXPECT_EQ(parsePlay({"RECORD 2 1 VCMD VFB", "1 2", "3"}).error, "line 3: 1 values, expected 2");
    EXPECT_EQ(parsePlay({"RECORD 2 1 VFB", "abc"}).error, "line 2: \"abc\" is not a number");
    EXPECT_EQ(parsePlay({"RECORD 2 1 VFB", "nan"}).error, "line 2: \"nan\" is not a number");
}

// capture_files_fuzz finding: a RECORD count past int's range was converted to int (undefined).
TEST(PlayParser, RefusesACountOrIntervalNoDriveCouldPrint) {
    for (const char* head : {"RECORD 66666666666666666666 2 PFB", "RECORD 2.5 2 PFB", "RECORD 0 2 PFB",
                             "RECORD 2 inf PFB", "RECORD 2 nan PFB"}) {
        const auto r = parsePlay({head, "1"});
        EXPECT_FALSE(r.capture) << head;
        EXPECT_NE(r.error.find("line 1: expected \"RECORD <n> <t> <variables>\""), std::string::npos) << head;
    }
    EXPECT_EQ(parsePlay({"RECORD 1000000 1 PFB", "1"}).requestedSamples, 1000000);
}

TEST(CaptureCsv, RoundTripKeepsNamesUnitsIntervalAndValues) {
    Capture c;
    c.interval_s = 0.005;
    c.channels = {{"VCMD", "VEL", {0, 1000, 1000.5}}, {"X1", "", {-1, 2, 3}}};
    const std::string text = writeCsv(c);
    EXPECT_EQ(text.substr(0, text.find("\r\n", text.find("\r\n") + 2)), "RECORD,3,5,VCMD,X1\r\nTime (s),VCMD (VEL),X1");
    EXPECT_NE(text.find("0.01,1000.5,3\r\n"), std::string::npos);
    const auto back = readCsv(text);
    ASSERT_TRUE(back.capture) << back.error;
    EXPECT_DOUBLE_EQ(back.capture->interval_s, 0.005);
    ASSERT_EQ(back.capture->channels.size(), 2u);
    EXPECT_EQ(back.capture->channels[0].unit, "VEL");
    EXPECT_EQ(back.capture->channels[1].unit, "");
    EXPECT_EQ(back.capture->channels[0].values, c.channels[0].values);
    EXPECT_EQ(back.capture->channels[1].values, c.channels[1].values);
}

TEST(CaptureCsv, ReadsASpreadsheetFileWithoutTheRecordLine) {
    const auto r = readCsv("Time (s),PFB (POS)\n0,1\n0.25,2\n0.5,3\n");
    ASSERT_TRUE(r.capture) << r.error;
    EXPECT_DOUBLE_EQ(r.capture->interval_s, 0.25);
    EXPECT_EQ(r.capture->channels[0].name, "PFB");
    EXPECT_EQ(r.capture->sampleCount(), 3u);
}

TEST(CaptureCsv, NamesTheLineItCannotRead) {
    EXPECT_EQ(readCsv("RECORD,2,1,VFB\nTime (s),VFB\n0,1\n0.001,x\n").error, "line 4: \"x\" is not a number");
    EXPECT_EQ(readCsv("RECORD,2,1,VFB\nTime (s),VFB\n0,1,2\n").error, "line 3: 3 values, expected 2");
    EXPECT_EQ(readCsv("").error, "line 1: no column titles");
    // A column title left empty (capture_files_fuzz): refused, as it could not be written back.
    EXPECT_EQ(readCsv("Time (s),VFB,\n0,1,2\n").error, "line 1: column 3 has no variable name");
}
