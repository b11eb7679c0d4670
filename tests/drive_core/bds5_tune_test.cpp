// TUNE bw stab on the simulated motor: at every allowed bandwidth the velocity loop it leaves behind
// measures at that bandwidth; it finds a heavier load by itself; a TUNE 30 2 step rises in the time a
// 30 Hz critically damped loop takes; and it answers ERR 20 / 83 where the manual says it fails.
#include "bds5_loop_probe.h"
#include "bds5_test_drive.h"

#include <gtest/gtest.h>

#include <cctype>
#include <cstdio>
#include <sstream>

using namespace bds5_test;

namespace {
std::string value(TestDrive& t, const std::string& name) {
    const std::string out = t.type("P " + name + "\r");
    const auto start = out.find_first_not_of(' ', out.find("\r\n") + 2);
    return out.substr(start, out.find("\r\n", start) - start);
}
LoopGains gainsOf(TestDrive& t) {
    return {std::stod(value(t, "KV")), std::stod(value(t, "KVI")), std::stod(value(t, "KP"))};
}
} // namespace

TEST(Bds5Tune, EachAllowedBandwidthIsReached) { // L6284: 5, 10, 15, 20, 25, 30, 40, 50 Hz
    for (const int bandwidth : {5, 10, 15, 20, 25, 30, 40, 50}) {
        TestDrive t;
        EXPECT_EQ(t.type("TUNE " + std::to_string(bandwidth) + " 2\r"),
                  "TUNE " + std::to_string(bandwidth) + " 2\r\n-->");
        const double measured = velocityBandwidth_Hz(gainsOf(t));
        EXPECT_NEAR(measured, bandwidth, 0.15 * bandwidth) << "TUNE " << bandwidth << " 2";
        EXPECT_EQ(value(t, "KP"), std::to_string(100 * bandwidth)) << "KP_max of Table 6.4";
    }
}

TEST(Bds5Tune, FindsAHeavierLoadByShakingIt) {
    TestDrive t;
    drive_core::physics::LoadParameters load;
    load.inertia_kgm2 = 1.2e-3; // eight times the rotor
    t.drive.controls()->setLoadInertia_kgm2(load.inertia_kgm2);
    t.type("TUNE 20 2\r");
    const LoopGains heavy = gainsOf(t);
    TestDrive light;
    light.type("TUNE 20 2\r");
    EXPECT_NEAR(heavy.kv / gainsOf(light).kv, (1.5e-4 + 1.2e-3) / 3e-4, 0.3) << "KV grows with the inertia";
    EXPECT_NEAR(velocityBandwidth_Hz(heavy, load), 20, 3);
}

TEST(Bds5Tune, StabilityChoosesTheDamping) { // Table 6.2
    double overshoot[4] = {};
    for (const int stab : {1, 2, 3}) {
        TestDrive t;
        t.type("TUNE 20 " + std::to_string(stab) + "\r");
        const double peak = velocityGain(gainsOf(t), 12);
        overshoot[stab] = peak;
    }
    EXPECT_LT(overshoot[1], overshoot[2]);
    EXPECT_LT(overshoot[2], overshoot[3]) << "slightly underdamped peaks most";
}

// A TUNE 30 2 velocity step rises (10 % to 90 %) in 3.36 / wn for critical damping, wn = 2 pi 30 / 0.6436.
TEST(Bds5Tune, Tune30StepRiseTimeImpliesThirtyHertz) {
    TestDrive t;
    t.type("PLIM OFF\r"); // soft limits PMAX/PMIN are +-100 counts at first (L1548)
    t.type("TUNE 30 2\r");
    t.type("PL OFF\r");
    t.type("AMAX=1000000\r"); // ACC may not exceed AMAX (L2186): a 100 RPM step within 0.1 ms
    t.type("ACC=1000000\r");
    t.type("EN\r");
    t.type("RECORD 60 1 VFB\r");
    t.type("J 100\r", 100ms);
    const std::string play = t.type("PLAY\r");
    std::vector<double> vfb; // PLAY: a header line, then one value a line, right-justified (bds5_recorder.h)
    std::istringstream lines(play);
    for (std::string line; std::getline(lines, line);) {
        const auto first = line.find_first_not_of(' ');
        if (first != std::string::npos && (std::isdigit(static_cast<unsigned char>(line[first])) ||
                                           (line.compare(first, 2, "--") != 0 && line[first] == '-')))
            vfb.push_back(std::stod(line.substr(first)));
    }
    ASSERT_GE(vfb.size(), 50u) << play;
    int t10 = -1, t90 = -1;
    for (int i = 0; i < int(vfb.size()); ++i) {
        if (t10 < 0 && vfb[i] >= 10) t10 = i;
        if (t90 < 0 && vfb[i] >= 90) t90 = i;
    }
    ASSERT_GE(t90, 0);
    const double rise_s = (t90 - t10) * 1e-3;
    const double implied_Hz = 3.36 / rise_s * 0.6436 / (2 * std::numbers::pi);
    std::printf("TUNE 30 2: velocity step rises 10-90 %% in %.0f ms -> %.1f Hz\n", rise_s * 1000, implied_Hz);
    EXPECT_NEAR(implied_Hz, 30, 6) << "rise " << rise_s * 1000 << " ms";
}

TEST(Bds5Tune, FailsWithTooMuchInertiaALowFilterOrAResonance) { // ERR 20 (L7207, L6288-6300)
    {
        TestDrive t;
        t.drive.controls()->setLoadInertia_kgm2(0.01);
        EXPECT_NE(t.type("TUNE 50 2\r").find("\aERR 20"), std::string::npos) << "KV beyond 32767";
        EXPECT_EQ(t.type("TUNE 5 2\r"), "TUNE 5 2\r\n-->") << "a low bandwidth still works";
    }
    {
        TestDrive t;
        t.type("LPF ON\r");
        t.type("LPFHZ=100\r");
        EXPECT_NE(t.type("TUNE 30 2\r").find("\aERR 20"), std::string::npos);
    }
    {
        TestDrive t;
        t.type("REMOTE\r");
        t.drive.controls()->setEnableInput(false);
        EXPECT_NE(t.type("TUNE 30 2\r").find("\aERR 20"), std::string::npos) << "REMOTE off";
    }
}

TEST(Bds5Tune, RejectsBandwidthsAndStabilitiesTheManualDoesNotList) {
    TestDrive t;
    EXPECT_NE(t.type("TUNE 35 2\r").find("\aERR 83 '35'"), std::string::npos);
    EXPECT_NE(t.type("TUNE 30 4\r").find("\aERR 83 '4'"), std::string::npos);
    EXPECT_NE(t.type("TUNE 30\r").find("\aERR 82"), std::string::npos);
}
