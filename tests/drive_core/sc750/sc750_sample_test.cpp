// The SC750 sample program the IDE opens with (resources/samples/hello.bas, servodesk --drive sc750) compiles
// with the project's compiler and, run on the simulated controller, prints what its comments promise.
#include "sc750_bench.h"

#include <filesystem>
#include <fstream>
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
    EXPECT_EQ(b.out, "Hello, world\r\n"
                     "Turn 1 done, position 4096 \r\n"
                     "Turn 2 done, position 8192 \r\n"
                     "Turn 3 done, position 12288 \r\n"
                     "Done\r\n");
    EXPECT_NEAR(b.drive.status().position_rev, 3.0, 0.01);
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
