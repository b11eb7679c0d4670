// The PLAY listing parser (the simulated BDS5's layout and malformed listings) and the .CSV layout
// (round trip, files without the RECORD line, errors named by line; the in-place reader against a plain
// reference parse of a generated file).
#include "scope/capture_csv.h"
#include "scope/play_parser.h"

#include <gtest/gtest.h>

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <sstream>

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

// A spreadsheet that pads a title before its unit ("VFB   (RPM)", "V   ()"): the name is the text before
// the blanks, so the file ServoDesk writes back reads as the same channels (capture_files_fuzz finding).
TEST(CaptureCsv, BlanksBeforeAUnitAreNotPartOfTheName) {
    const auto r = readCsv("Time (s),VFB   (RPM),V   ()\n0,1,2\n");
    ASSERT_TRUE(r.capture) << r.error;
    EXPECT_EQ(r.capture->channels[0].name, "VFB");
    EXPECT_EQ(r.capture->channels[0].unit, "RPM");
    EXPECT_EQ(r.capture->channels[1].name, "V");
    EXPECT_EQ(r.capture->channels[1].unit, "");
    const std::string written = scope::writeCsv(*r.capture);
    EXPECT_NE(written.find("Time (s),VFB (RPM),V\r\n"), std::string::npos) << written;
    EXPECT_EQ(scope::writeCsv(*readCsv(written).capture), written);
}

TEST(CaptureCsv, NamesTheLineItCannotRead) {
    EXPECT_EQ(readCsv("RECORD,2,1,VFB\nTime (s),VFB\n0,1\n0.001,x\n").error, "line 4: \"x\" is not a number");
    EXPECT_EQ(readCsv("RECORD,2,1,VFB\nTime (s),VFB\n0,1,2\n").error, "line 3: 3 values, expected 2");
    EXPECT_EQ(readCsv("").error, "line 1: no column titles");
    // A column title left empty (capture_files_fuzz): refused, as it could not be written back.
    EXPECT_EQ(readCsv("Time (s),VFB,\n0,1,2\n").error, "line 1: column 3 has no variable name");
}

namespace {

// The obvious way to read the rows: getline, split at commas, trim, strtod. Values per column, time first.
std::vector<std::vector<double>> referenceRows(const std::string& text, std::size_t skipLines) {
    std::vector<std::vector<double>> columns;
    std::istringstream in(text);
    std::size_t index = 0;
    for (std::string line; std::getline(in, line); ++index) {
        if (index < skipLines) continue;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        if (line.find_first_not_of(" \t,") == std::string::npos) continue;
        std::istringstream fields(line + ",");
        std::size_t c = 0;
        for (std::string field; std::getline(fields, field, ','); ++c) {
            const auto first = field.find_first_not_of(" \t\"");
            const auto last = field.find_last_not_of(" \t\"");
            field = field.substr(first, last - first + 1);
            char* end = nullptr;
            const double v = std::strtod(field.c_str(), &end);
            EXPECT_EQ(*end, '\0') << "the generator wrote \"" << field << "\"";
            if (columns.size() <= c) columns.resize(c + 1);
            columns[c].push_back(v);
        }
    }
    return columns;
}

// A .CSV as spreadsheets and ServoDesk write them: negative numbers, exponents in both cases, a '+',
// quotes and blanks around fields, CR LF and LF, blank rows. Seeded.
std::string generatedCsv(std::size_t rows) {
    std::mt19937 random(1866);
    std::uniform_real_distribution<double> magnitude(-12, 12);
    std::uniform_int_distribution<int> style(0, 9);
    std::string text = "RECORD," + std::to_string(rows) + ",0.5,VCMD,VFB,ICMD,PE\r\n";
    text += "Time (s),VCMD (VEL),VFB (VEL),ICMD (I),PE (POS)\r\n";
    char buffer[64];
    for (std::size_t i = 0; i < rows; ++i) {
        const auto end = std::to_chars(buffer, buffer + sizeof buffer, double(i) * 0.0005).ptr;
        text.append(buffer, end);
        for (int c = 0; c < 4; ++c) {
            const double v = (random() % 2 ? -1 : 1) * std::pow(10.0, magnitude(random)) * (1 + random() % 1000) / 7;
            switch (style(random)) {
            case 0: std::snprintf(buffer, sizeof buffer, ",%.17g", v); break;
            case 1: std::snprintf(buffer, sizeof buffer, ",%.6e", v); break;
            case 2: std::snprintf(buffer, sizeof buffer, ",%.4E", v); break;
            case 3: std::snprintf(buffer, sizeof buffer, ",+%g", std::abs(v)); break;
            case 4: std::snprintf(buffer, sizeof buffer, ",\"%g\"", v); break;
            case 5: std::snprintf(buffer, sizeof buffer, ", %d ", int(random() % 20001) - 10000); break;
            default: {
                buffer[0] = ',';
                *std::to_chars(buffer + 1, buffer + sizeof buffer - 1, v).ptr = '\0';
            }
            }
            text += buffer;
        }
        text += i % 7 == 3 ? "\n" : "\r\n";
        if (i % 1000 == 500) text += ",,,,\r\n"; // a blank row: skipped
    }
    return text;
}

// Line number (1-based) of the generated file's data row `row` (blank rows counted).
std::size_t lineOfRow(const std::string& text, std::size_t row) {
    std::size_t line = 1;
    std::size_t rows = 0;
    for (std::size_t at = 0; at < text.size(); at = text.find('\n', at) + 1, ++line) {
        if (line <= 2 || text.compare(at, 5, ",,,,\r") == 0) continue;
        if (rows++ == row) return line;
    }
    return 0;
}

} // namespace

TEST(CaptureCsv, ReadsEveryValueAsAPlainReferenceParseDoes) {
    const std::string text = generatedCsv(20'000);
    const auto r = readCsv(text);
    ASSERT_TRUE(r.capture) << r.error;
    const auto want = referenceRows(text, 2);
    ASSERT_EQ(want.size(), 5u);
    ASSERT_EQ(r.capture->channels.size(), 4u);
    EXPECT_EQ(r.capture->channels[2].unit, "I");
    EXPECT_DOUBLE_EQ(r.capture->interval_s, 0.0005);
    for (std::size_t c = 0; c < 4; ++c) EXPECT_EQ(r.capture->channels[c].values, want[c + 1]) << "column " << c;
}

TEST(CaptureCsv, AMalformedRowDeepInAFileIsNamedByItsLine) {
    const std::string text = generatedCsv(5'000);
    const std::size_t line = lineOfRow(text, 3'210);
    ASSERT_GT(line, 3'210u);
    // The row's third value loses its exponent's digits: "2.5e".
    std::size_t at = 0;
    for (std::size_t l = 1; l < line; ++l) at = text.find('\n', at) + 1;
    const std::size_t rowEnd = text.find('\n', at);
    std::string row = text.substr(at, rowEnd - at);
    std::size_t comma = 0;
    for (int k = 0; k < 3; ++k) comma = row.find(',', comma) + 1;
    std::string broken = text;
    broken.replace(at + comma, row.find(',', comma) - comma, "2.5e");
    EXPECT_EQ(readCsv(broken).error, "line " + std::to_string(line) + ": \"2.5e\" is not a number");
    // The same row with a value missing: the count is named, not the number.
    broken = text;
    broken.replace(at + comma - 1, row.find(',', comma) - comma + 1, "");
    EXPECT_EQ(readCsv(broken).error, "line " + std::to_string(line) + ": 4 values, expected 5");
}

TEST(CaptureCsv, ReadsNegativeNumbersExponentsAndDecoratedFields) {
    const auto r = readCsv("Time (s),A,B\r\n0,-1.5e-3,\"+2E+4\"\r\n0.125,  -0 ,1e308\n\n0.25,-7,+.5\n");
    ASSERT_TRUE(r.capture) << r.error;
    EXPECT_DOUBLE_EQ(r.capture->interval_s, 0.125);
    EXPECT_EQ(r.capture->channels[0].values, (std::vector<double>{-0.0015, -0.0, -7}));
    EXPECT_EQ(r.capture->channels[1].values, (std::vector<double>{20000, 1e308, 0.5}));
    EXPECT_EQ(readCsv("Time (s),A\n0,1e999\n").error, "line 2: \"1e999\" is not a number"); // out of range
    EXPECT_EQ(readCsv("Time (s),A\n0,1 2\n").error, "line 2: \"1 2\" is not a number");
    EXPECT_EQ(readCsv("Time (s),A\r\n0,1\r\n,\r\n1,\r\n").error, "line 4: \"\" is not a number");
}

// Only the first two times set the interval, but every row's time must still be a number.
TEST(CaptureCsv, EveryRowsTimeIsCheckedNotJustTheFirstTwo) {
    EXPECT_EQ(readCsv("Time (s),A\n0,1\n1,2\n2x,3\n").error, "line 4: \"2x\" is not a number");
    EXPECT_EQ(readCsv("Time (s),A\n0,1\n1,2\n2,3\n-,4\n").error, "line 5: \"-\" is not a number");
    EXPECT_EQ(readCsv("Time (s),A\n0,1\n1,2\n1e999,3\n").error, "line 4: \"1e999\" is not a number");
    const auto r = readCsv("Time (s),A\n0,1\n1,2\n0.0000000000000000000000000000000001,3\n2.,4\n-.5,5\n3e0,6\n");
    ASSERT_TRUE(r.capture) << r.error;
    EXPECT_EQ(r.capture->channels[0].values, (std::vector<double>{1, 2, 3, 4, 5, 6}));
}
