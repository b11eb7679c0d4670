// What a host on a MultidropBus's line sees: bytes sent, the bus run until the line is quiet, what came back.
#pragma once

#include "drive_core/multidrop_bus.h"

#include <gtest/gtest.h>

#include <chrono>
#include <string>
#include <string_view>

namespace multidrop_test {

// Sends bytes, lets the bus run until the line is quiet (at 9600 baud a character takes about 1 ms), and
// returns everything that went out on it, from every axis.
inline std::string type(drive_core::MultidropBus& bus, std::string_view bytes) {
    using namespace std::chrono_literals;
    bus.receive(bytes);
    std::string sent;
    for (int quiet = 0, i = 0; quiet < 30 && i < 5000; ++i) {
        bus.step(1ms);
        const std::string now = bus.takeTransmitted();
        quiet = now.empty() ? quiet + 1 : 0;
        sent += now;
    }
    return sent;
}

// A bus of family with these IDs, powered up and run 200 ms: nothing may be on the line yet.
inline std::unique_ptr<drive_core::MultidropBus> poweredUp(drive_core::DriveFamily family,
                                                           const std::vector<std::string>& ids) {
    using namespace std::chrono_literals;
    std::string why;
    auto bus = drive_core::MultidropBus::make(family, ids, why);
    EXPECT_TRUE(bus) << why;
    if (!bus) return bus;
    bus->powerUp();
    for (int i = 0; i < 200; ++i) bus->step(1ms);
    EXPECT_EQ(bus->takeTransmitted(), "") << "every axis of a bus powers up silent";
    return bus;
}

} // namespace multidrop_test
