// Random byte streams into the simulated PMC-960 (fixed seeds): whatever a host or a noisy line sends, the
// controller neither crashes nor hangs, keeps its program buffer within 1,940 bytes, and a <cr> after an
// ESC always brings it back to the prompt.
#include "pmc960_test_drive.h"

#include <random>

namespace pmc960_test {
namespace {

std::string randomChunk(std::mt19937& rng) {
    static const std::string kAlphabet = "ABCDEFGHIJLNOPQRSTUVWXYZabcdefghijlnopqrstuv0123456789:+-*,;^?!%&@|{}."
                                         "\r\r\r\r\x1b\x1d\x1d\t\n\x08\x7f\x0b\x16\x19";
    std::uniform_int_distribution<int> length(1, 12);
    std::uniform_int_distribution<int> pick(0, int(kAlphabet.size()) - 1);
    std::uniform_int_distribution<int> raw(0, 255);
    std::uniform_int_distribution<int> percent(0, 99);
    std::string chunk;
    const int n = length(rng);
    for (int i = 0; i < n; ++i) chunk += percent(rng) < 5 ? char(raw(rng)) : kAlphabet[std::size_t(pick(rng))];
    return chunk;
}

class Pmc960RandomStream : public ::testing::TestWithParam<unsigned> {};

TEST_P(Pmc960RandomStream, NeverCrashesAndRecoversToThePrompt) {
    std::mt19937 rng(GetParam());
    TestDrive t;
    t.type("SW1\rSM2\r");
    std::uniform_int_distribution<int> ms(0, 3);
    std::size_t answered = 0;
    for (int i = 0; i < 4000; ++i) {
        t.drive.receive(randomChunk(rng));
        t.drive.step(std::chrono::milliseconds(ms(rng)));
        answered += t.drive.takeTransmitted().size();
        // A host on a bus selects its axis again when it has lost it (<attn><ID>).
        if (!t.drive.talker()) t.drive.receive(std::string("\x1d") + t.drive.state().axisId());
        ASSERT_LE(t.drive.state().program.size(), drive_core::pmc960::Pmc960Program::kCapacity);
    }
    EXPECT_GT(answered, 10000u); // it did talk back
    // Back to a known state: leave every mode, undo echo-off and foreign axis IDs.
    t.type(std::string("\x1d") + char(t.drive.state().axisId()));
    t.type("\x1b\x1b\r", 2000ms);
    t.type("\x1b", 10ms);
    t.drive.setLine(drive_core::pmc960::Pmc960Line::Break, true);
    t.drive.setLine(drive_core::pmc960::Pmc960Line::Break, false);
    const std::string out = t.type("\x1b\r", 10ms);
    EXPECT_NE(out.find('}'), std::string::npos) << "seed " << GetParam();
}

INSTANTIATE_TEST_SUITE_P(Seeds, Pmc960RandomStream, ::testing::Values(1u, 2u, 3u, 42u, 960u, 1985u));

} // namespace
} // namespace pmc960_test
