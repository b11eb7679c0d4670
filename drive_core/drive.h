// The contract every simulated drive fulfils: a UART (bytes in, bytes out), I/O pins, and step(dt).
// A drive never reads the wall clock; whoever owns it injects time through step().
#pragma once

#include <chrono>
#include <cstdint>
#include <string>
#include <string_view>

#include "simulator_controls.h"

namespace drive_core {

enum class DriveFamily { Bds5, Sc750, Pmc960 };

using Microseconds = std::chrono::microseconds;

class Drive {
public:
    virtual ~Drive() = default;

    virtual DriveFamily family() const = 0;

    // Power the drive up (or cycle its power): resets volatile state, sends the sign-on.
    virtual void powerUp() = 0;

    // UART, host -> drive. Bytes are queued and acted on during the next step().
    virtual void receive(std::string_view bytes) = 0;
    // UART, drive -> host. Returns and clears everything the drive has transmitted so far.
    virtual std::string takeTransmitted() = 0;

    // Advance the drive's time by dt. The servo and command processors run inside; step(0) handles what
    // was received without letting time pass.
    virtual void step(Microseconds dt) = 0;
    // Total simulated time since power-up.
    virtual Microseconds now() const = 0;

    // The serial line's pace: limited (the default), bytes leave at the drive's baud rate as on a real
    // port; unlimited, at once — for an in-process link with no wire, and for tests that want speed.
    virtual void setLineRateLimited(bool limited) = 0;

    // Discrete I/O pins, numbered from 1 as the drive's manual numbers them.
    virtual int inputCount() const = 0;
    virtual int outputCount() const = 0;
    virtual void setInput(int number, bool on) = 0;
    virtual bool input(int number) const = 0;
    virtual bool output(int number) const = 0;

    // The bench around a simulated drive (inputs, load, motor, power); nullptr until a family offers it.
    virtual SimulatorControls* controls() { return nullptr; }
};

} // namespace drive_core
