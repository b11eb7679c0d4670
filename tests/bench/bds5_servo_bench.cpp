// How fast the simulated BDS5 runs with its servo loops and motor: simulated seconds per wall-clock second
// on one core for (1) an idle, disabled drive, (2) an enabled drive holding position, and (3) a program
// making moves back and forth with all loops on (KF, LPF, integrating velocity loop, foldback). Goal
// (issue 4): at least 2000x for (3). Prints figures; asserts nothing about time.
// Run: build/tests/bench/bds5_servo_bench
#include "drive_core/bds5/bds5_drive.h"
#include "median_of.h"

#include <chrono>
#include <cstdio>
#include <ctime>
#include <string>
#include <vector>

namespace {

using namespace std::chrono_literals;

void feed(drive_core::bds5::Bds5Drive& drive, std::string_view bytes) {
    drive.receive(bytes);
    for (int i = 0; i < 100 || drive.transmitting(); ++i) drive.step(1ms);
    drive.takeTransmitted();
}

void download(drive_core::bds5::Bds5Drive& drive, const std::vector<std::string>& lines) {
    feed(drive, ">BDS\r");
    for (const std::string& line : lines) feed(drive, line + "\r");
    feed(drive, "\x1b");
}

// Runs `seconds` of simulated time in 1 ms steps and prints the ratio to wall time and to the process's
// CPU time (the one-core figure; on a loaded machine the wall clock also counts other processes' turns).
double measure(const char* what, drive_core::bds5::Bds5Drive& drive, int seconds) {
    std::size_t bytes = 0;
    const auto start = std::chrono::steady_clock::now();
    const std::clock_t cpuStart = std::clock();
    for (int i = 0; i < seconds * 1000; ++i) {
        drive.step(1ms);
        bytes += drive.takeTransmitted().size();
    }
    const double cpu = double(std::clock() - cpuStart) / CLOCKS_PER_SEC;
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("%-44s %3d s simulated: wall %6.3f s = %6.0fx, CPU %6.3f s = %6.0fx real time (%zu bytes sent)\n", what,
                seconds, wall, seconds / wall, cpu, seconds / cpu, bytes);
    return seconds / cpu;
}

} // namespace

int main() {
    {
        drive_core::bds5::Bds5Drive drive;
        drive.setLineRateLimited(false);
        drive.powerUp();
        feed(drive, "\r");
        measure("idle, disabled (motor and loops still run):", drive, 120);
    }
    {
        drive_core::bds5::Bds5Drive drive;
        drive.setLineRateLimited(false);
        drive.powerUp();
        feed(drive, "EN\r");
        measure("enabled, holding position:", drive, 120);
    }
    drive_core::bds5::Bds5Drive drive;
    drive.setLineRateLimited(false);
    drive.powerUp();
    download(drive, {"1$", "PLIM OFF", "EN", "KF=8000", "LPF ON", "LPFHZ=300", "ACC=20000", "DEC=20000", "2$",
                     "MI 40960 2000", "W 0", "X1=X1+1", "MI -40960 2000", "W 0", "? X1/10*10 EQ X1 P X1", "GOTO 2"});
    feed(drive, "RUN 1\r");
    const double ratio =
        medianOf(5, [&drive](int) { return measure("program: MI back and forth, all loops on:", drive, 300); });
    std::printf("servo bench: %.0fx real time (CPU, one core, median of 5) with motion and all loops (goal >= 2000x)\n",
                ratio);
    return 0;
}
