// How fast the simulated SC750 runs with its servo loops on the plant (issue 18): simulated seconds per
// wall-clock and per CPU second on one core, for an enabled drive holding position and for a program making
// moves back and forth (position loop, velocity PI, ARF filters, current loop, motor), with the analog
// monitor on. Goal: at least 2000x for the program. Prints figures; asserts nothing about time.
// Run: build/tests/bench/sc750_servo_bench
#include "drive_core/sc750/sc750_compiler.h"
#include "drive_core/sc750/sc750_drive.h"
#include "median_of.h"

#include <chrono>
#include <cstdio>
#include <ctime>
#include <string>

namespace {

using drive_core::sc750::Sc750Drive;

// Runs `seconds` of simulated time in 1 ms steps; prints the ratio to wall time and to the process's CPU
// time (the one-core figure: on a loaded machine the wall clock also counts other processes' turns).
double measure(const char* what, Sc750Drive& drive, int seconds) {
    std::size_t bytes = 0;
    const auto start = std::chrono::steady_clock::now();
    const std::clock_t cpuStart = std::clock();
    for (int i = 0; i < seconds * 1000; ++i) {
        drive.step(drive_core::Microseconds(1000));
        bytes += drive.takeTransmitted().size();
    }
    const double cpu = double(std::clock() - cpuStart) / CLOCKS_PER_SEC;
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("%-46s %3d s simulated: wall %6.3f s = %6.0fx, CPU %6.3f s = %6.0fx real time (%zu bytes sent)\n",
                what, seconds, wall, seconds / wall, cpu, seconds / cpu, bytes);
    return seconds / cpu;
}

} // namespace

int main() {
    {
        Sc750Drive drive;
        drive.setLineRateLimited(false);
        drive.writeNamed("ENABLE", "1");
        measure("enabled, holding position:", drive, 60);
    }
    Sc750Drive drive;
    drive.setLineRateLimited(false);
    const auto program = drive_core::sc750::compile("DIM n AS INTEGER\n"
                                                    "ENABLE = 1\nACCEL.RATE = 20000\nDECEL.RATE = 20000\n"
                                                    "RUN.SPEED = 2000\nKVFF = 50\nDACMAP = 3\n"
                                                    "again:\n"
                                                    "INDEX.DIST = 40960\nGO.INCR\nWHILE MOVING : WEND\n"
                                                    "INDEX.DIST = -40960\nGO.INCR\nWHILE MOVING : WEND\n"
                                                    "n = n + 1\nIF n MOD 10 = 0 THEN PRINT n; POS.ERROR\n"
                                                    "GOTO again\n");
    if (!program.ok()) {
        std::printf("compile failed: %s\n", program.error->text().c_str());
        return 1;
    }
    std::string why;
    if (!drive.loadProgram(program.bin, &why)) {
        std::printf("load failed: %s\n", why.c_str());
        return 1;
    }
    drive.vm().start();
    const double ratio = medianOf(5, [&drive](int) {
        return measure("program: GO.INCR back and forth, physics on:", drive, 300);
    });
    std::printf("sc750 servo, physics on: %.0f x real time (CPU, one core, median of 5; goal >= 2000x)\n", ratio);
    return 0;
}
