// The PMC-960 sample program the IDE opens with (resources/samples/hello.mpl, servodesk --drive pmc960),
// downloaded as MPL > Download Program sends it (no spaces, no empty lines, CR line ends), runs from the
// labels its comments name: BH three turns forward, BR back to the start, each showing the position.
#include "pmc960_test_drive.h"

#include <filesystem>
#include <fstream>
#include <sstream>

namespace pmc960_test {
namespace {

// The program buffer's text: the file's lines without spaces or tabs (L1412), empty lines dropped.
std::string sampleAsStored() {
    std::ifstream in(std::filesystem::path(SERVODESK_SAMPLES_DIR) / "hello.mpl", std::ios::binary);
    std::string stored;
    for (std::string line; std::getline(in, line);) {
        std::erase_if(line, [](char c) { return c == ' ' || c == '\t' || c == '\r'; });
        if (!line.empty()) stored += line + '\r';
    }
    return stored;
}

TEST(Pmc960Sample, HelloMplFitsTheProgramBuffer) {
    const std::string stored = sampleAsStored();
    ASSERT_FALSE(stored.empty()) << SERVODESK_SAMPLES_DIR "/hello.mpl is missing";
    TestDrive t;
    t.load(stored);
    EXPECT_EQ(t.drive.state().program.text(), stored);
}

TEST(Pmc960Sample, BhTurnsThreeTimesForwardAndBrComesBack) {
    TestDrive t;
    t.load(sampleAsStored());
    EXPECT_EQ(t.type("BH\r", 2000ms), prompted("BH12288")); // 3 x 4096 counts, shown by G!
    EXPECT_EQ(t.type("SM?"), prompted("SM?2"));             // the sample turned the drive on itself
    EXPECT_EQ(t.type("BR\r", 2000ms), prompted("BR0"));
    EXPECT_EQ(t.type("G!"), prompted("G!0"));
}

} // namespace
} // namespace pmc960_test
