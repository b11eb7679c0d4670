// The VM's read-only loop skip (Vm::tick): a loop that only reads the drive's values, such as the manual's
// WHILE MOVING : WEND, ends each tick at exactly the instruction it would have reached running every
// instruction. Checked against the same program fed one instruction per call (a budget of 1 never sees a
// whole pass inside one call, so nothing is skipped), tick by tick, while the drive's MOVING changes.
#include "drive_core/catalog/sc750_catalog.h"
#include "drive_core/sc750/sc750_bin.h"
#include "drive_core/sc750/sc750_compiler.h"
#include "drive_core/sc750/sc750_vm.h"
#include "drive_core/sc750/sc750_vm_host.h"

#include <gtest/gtest.h>

namespace {

using namespace drive_core::sc750;

// A drive whose MOVING follows a schedule of ticks; everything else is inert and counted.
struct Host final : VmHost {
    int moving = 0;
    int reads = 0;
    std::string out;
    Value readVariable(int index) override {
        ++reads;
        if (index == drive_core::catalog::sc750::variableIndex("MOVING")) return Value(std::int32_t(moving));
        return Value(std::int32_t(0));
    }
    std::string writeVariable(int, const Value&) override { return {}; }
    void motion(int) override {}
    void write(std::string_view text) override { out += text; }
    std::optional<std::string> takeLine() override { return std::nullopt; }
    std::string takeChar() override { return {}; }
    double whenSample(int) override { return 0; }
    void whenLatch() override {}
    void whenAction(int, int, float) override {}
    void tmrset(int, float, int) override {}
    int takeInterrupt() override { return -1; }
    bool anyInterruptEnabled() const override { return false; }
    int axis() const override { return 255; }
    double pauseTime_s() override { return 0; }
};

Program compiled(const std::string& source) {
    const CompileResult result = compile(source);
    EXPECT_TRUE(result.ok());
    BinReadResult read = readBin(result.bin);
    EXPECT_TRUE(read.program.has_value());
    return std::move(*read.program);
}

TEST(Sc750VmIdle, AReadOnlyLoopEndsEachTickWhereEveryInstructionWouldHave) {
    const std::string source = "DIM n, x AS INTEGER\n"
                               "again:\n"
                               "WHILE MOVING AND (x + 1 > 0) : WEND\n" // a pass of several instructions
                               "n = n + 1\n"
                               "PRINT n;\n"
                               "WHILE MOVING = 0 : WEND\n"
                               "IF n < 6 THEN GOTO again\n";
    Host skipHost, stepHost;
    Vm skipping(skipHost), stepping(stepHost);
    skipping.load(compiled(source));
    stepping.load(compiled(source));
    skipping.start();
    stepping.start();
    constexpr int kBudget = 40;
    for (std::int64_t tick = 1; tick <= 400; ++tick) {
        const int moving = (tick / 7 + tick / 13) % 2; // changes at uneven ticks
        skipHost.moving = stepHost.moving = moving;
        skipping.tick(tick, kBudget);
        for (int i = 0; i < kBudget; ++i) stepping.tick(tick, 1);
        ASSERT_EQ(skipping.pc(), stepping.pc()) << "tick " << tick;
        ASSERT_EQ(skipping.stackDepth(), stepping.stackDepth()) << "tick " << tick;
        ASSERT_EQ(skipHost.out, stepHost.out) << "tick " << tick;
    }
    EXPECT_EQ(skipHost.out, " 1  2  3  4  5  6 ");
    EXPECT_EQ(skipping.state(), Vm::State::Ended);
    // The skip is what makes waiting cheap: far fewer reads of the drive than instructions budgeted.
    EXPECT_LT(skipHost.reads * 2, stepHost.reads);
}

} // namespace
