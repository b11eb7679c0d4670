// How fast the simulated PMC-960 runs with its servo loops on the motor (physics on): simulated seconds per
// wall-clock and per CPU second on one core while an MPL routine indexes back and forth with both loops
// and their integrators on (PLCOMP, VLCOMP, feedforward). Goal (issue 18): at least 2000x. Prints figures;
// asserts nothing about time.
// Run: build/tests/bench/pmc960_servo_bench
#include "drive_core/pmc960/pmc960_drive.h"
#include "median_of.h"

#include <chrono>
#include <cstdio>
#include <ctime>
#include <string>

namespace {

using namespace std::chrono_literals;

void type(drive_core::pmc960::Pmc960Drive& drive, std::string_view bytes) {
    drive.receive(bytes);
    for (int i = 0; i < 20; ++i) drive.step(1ms);
    drive.takeTransmitted();
}

// Runs `seconds` of simulated time in 1 ms steps; prints the ratios to wall time and to the process's CPU
// time (the one-core figure: on a loaded machine the wall clock also counts other processes' turns).
double measure(const char* what, drive_core::pmc960::Pmc960Drive& drive, int seconds) {
    std::size_t bytes = 0;
    const auto start = std::chrono::steady_clock::now();
    const std::clock_t cpuStart = std::clock();
    for (int i = 0; i < seconds * 1000; ++i) {
        drive.step(1ms);
        bytes += drive.takeTransmitted().size();
    }
    const double cpu = double(std::clock() - cpuStart) / CLOCKS_PER_SEC;
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("%-46s %3d s simulated: wall %6.3f s = %6.0fx, CPU %6.3f s = %6.0fx real time (%zu bytes sent)\n", what,
                seconds, wall, seconds / wall, cpu, seconds / cpu, bytes);
    return seconds / cpu;
}

} // namespace

int main() {
    {
        drive_core::pmc960::Pmc960Drive drive;
        drive.setLineRateLimited(false);
        drive.powerUp();
        measure("idle (SM0; motor and loops still run):", drive, 120);
    }
    drive_core::pmc960::Pmc960Drive drive;
    drive.setLineRateLimited(false);
    drive.powerUp();
    type(drive, "SW1\r");
    type(drive, "TGE20\r"); // PLCOMP and VLCOMP on: both integrators run
    type(drive, "TGB40\r");
    type(drive, "TGF40\r");
    type(drive, "SM2\r");
    type(drive, "P{}");
    type(drive, "P\r");
    type(drive, "@A\rV200\rA500\r@B\rI40960+,\rD10\rI40960-,\rD10\rBB\r");
    type(drive, "\x1b");
    type(drive, "BA\r");
    const double ratio =
        medianOf(5, [&drive](int) { return measure("program: I back and forth, both loops on:", drive, 300); });
    const bool running = drive.interpreter().running();
    std::printf("pmc960 servo, physics on: %.0f x real time (CPU, one core, median of 5; goal >= 2000x)%s\n", ratio,
                running ? "" : " [the routine had stopped]");
    return 0;
}
