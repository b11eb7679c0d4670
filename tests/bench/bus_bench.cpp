// How fast a whole multidrop line of simulated BDS5s runs (issue 21): 32 axes on one MultidropBus, each
// running the servo bench's program (MI back and forth with KF, LPF and the integrating velocity loop on),
// stepped together in 1 ms steps on one core. Prints simulated seconds of the whole bus per CPU second
// (goal >= 50x) and per wall second; asserts nothing about time.
// Run: build/tests/bench/bus_bench
#include "drive_core/bds5/bds5_drive.h"
#include "drive_core/multidrop_bus.h"
#include "median_of.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <string>
#include <vector>

namespace {

using namespace std::chrono_literals;
using drive_core::MultidropBus;

void feed(MultidropBus& bus, const std::string& bytes) {
    bus.receive(bytes);
    for (int i = 0; i < 30; ++i) bus.step(1ms); // the woken axis answers within a few characters' time
    bus.takeTransmitted();
}

double measure(MultidropBus& bus, int seconds) {
    std::size_t bytes = 0;
    const auto start = std::chrono::steady_clock::now();
    const std::clock_t cpuStart = std::clock();
    for (int i = 0; i < seconds * 1000; ++i) {
        bus.step(1ms);
        bytes += bus.takeTransmitted().size();
    }
    const double cpu = double(std::clock() - cpuStart) / CLOCKS_PER_SEC;
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("%zu axes, %d s simulated: wall %6.3f s = %5.1fx, CPU %6.3f s = %5.1fx real time (%zu bytes on "
                "the line)\n",
                bus.axisCount(), seconds, wall, seconds / wall, cpu, seconds / cpu, bytes);
    return seconds / cpu;
}

} // namespace

int main() {
    std::vector<std::string> ids;
    for (char c = '0'; c <= '9'; ++c) ids.emplace_back(1, c);
    for (char c = 'A'; ids.size() < MultidropBus::kMaxAxes; ++c) ids.emplace_back(1, c);
    std::string why;
    auto bus = MultidropBus::make(drive_core::DriveFamily::Bds5, ids, why);
    if (!bus) {
        std::fprintf(stderr, "bus bench: %s\n", why.c_str());
        return 1;
    }
    bus->setLineRateLimited(false);
    bus->powerUp();
    const std::vector<std::string> program{"1$", "PLIM OFF", "EN", "KF=8000", "LPF ON", "LPFHZ=300", "ACC=20000",
                                           "DEC=20000", "2$", "MI 40960 2000", "W 0", "X1=X1+1", "MI -40960 2000",
                                           "W 0", "GOTO 2"};
    for (const std::string& id : ids) { // each axis woken in turn, its program downloaded and started
        feed(*bus, "\\" + id);
        feed(*bus, ">BDS\r");
        for (const std::string& line : program) feed(*bus, line + "\r");
        feed(*bus, "\x1b");
        feed(*bus, "RUN 1\r");
    }
    feed(*bus, "\\\\"); // all asleep: the programs run on, the line is quiet
    const double ratio = medianOf(3, [&bus](int) { return measure(*bus, 20); });
    // A run that did not happen adds no result: each axis counted its moves in X1 (one every ~0.5 s).
    for (std::size_t axis : {std::size_t(0), bus->axisCount() - 1}) {
        const auto& drive = dynamic_cast<const drive_core::bds5::Bds5Drive&>(bus->axis(axis));
        const long moves = drive.state().variables.read("X1").value_or(0);
        std::printf("axis %s made %ld moves\n", bus->id(axis).c_str(), moves);
        if (moves < 60) {
            std::fprintf(stderr, "bus bench: axis %s did not run its program\n", bus->id(axis).c_str());
            return 1;
        }
    }
    std::printf("bus bench: %zu BDS5 axes, each running a program with motion: %.1fx real time for the whole bus "
                "(CPU, one core, median of 3; goal >= 50x)\n",
                bus->axisCount(), ratio);
    return 0;
}
