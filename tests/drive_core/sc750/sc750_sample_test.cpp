// The SC750 sample program the IDE opens with (resources/samples/hello.bas, servodesk --drive sc750) compiles
// with the project's compiler and, run on the simulated controller, prints what its comments promise.
#include "sc750_bench.h"

#include <filesystem>
#include <fstream>
#include <string>
#include <sstream>

namespace sc750_test {
namespace {

std::string sample() {
    std::ifstream in(std::filesystem::path(SERVODESK_SAMPLES_DIR) / "hello.bas", std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

TEST(Sc750Sample, HelloBasCompilesWithoutError) {
    const std::string source = sample();
    ASSERT_FALSE(source.empty()) << SERVODESK_SAMPLES_DIR "/hello.bas is missing";
    const CompileResult result = compile(source);
    ASSERT_TRUE(result.ok()) << result.error->text();
    EXPECT_FALSE(result.bin.empty());
}

TEST(Sc750Sample, HelloBasGreetsTurnsThreeTimesAndSaysDone) {
    Bench b(sample());
    ASSERT_TRUE(b.runUntil([&] { return b.drive.vm().state() == Vm::State::Ended; }, 10)) << b.out;
    // The program prints POSITION when the profile ends (WHILE MOVING): the shaft is then still a little
    // short of each turn by its following error (KVFF = 0), and lands on it a few ms later.
    ASSERT_EQ(b.out.substr(0, 14), "Hello, world\r\n");
    ASSERT_EQ(b.out.substr(b.out.size() - 6), "Done\r\n");
    for (int turn = 1; turn <= 3; ++turn) {
        const std::string head = "Turn " + std::to_string(turn) + " done, position ";
        const auto at = b.out.find(head);
        ASSERT_NE(at, std::string::npos) << b.out;
        const double position = std::stod(b.out.substr(at + head.size()));
        EXPECT_LE(position, 4096 * turn) << b.out;
        EXPECT_GT(position, 4096 * turn - 100) << b.out;
    }
    b.run(0.3);
    EXPECT_EQ(b.value("POSITION"), 3 * 4096);
    EXPECT_NEAR(b.drive.status().position_rev, 3.0, 0.001);
}

TEST(Sc750Sample, HelloBasSaysSoWhenTheDriveIsNotEnabled) {
    Bench b(sample(), false);
    b.drive.setEnableInput(false);
    b.drive.vm().start();
    ASSERT_TRUE(b.runUntil([&] { return b.drive.vm().state() == Vm::State::Ended; }, 10)) << b.out;
    EXPECT_EQ(b.out, "Hello, world\r\nThe drive is not enabled: check its ENABLE input\r\n");
    EXPECT_EQ(b.value("POSITION"), 0);
}

} // namespace
} // namespace sc750_test
