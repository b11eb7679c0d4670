// What the ServoBASIC Plus VM needs from the controller around it: predefined variables, motion, the
// serial port, WHEN sampling, timers. Sc750Drive implements it; tests can fake it.
#pragma once

#include "sc750_value.h"

#include <optional>
#include <string>
#include <string_view>

namespace drive_core::sc750 {

class VmHost {
public:
    virtual ~VmHost() = default;

    // Predefined variables by catalog index. writeVariable gets a value already of the variable's type;
    // it returns an error text when the drive refuses it (out of range), "" when accepted.
    virtual Value readVariable(int catalogIndex) = 0;
    virtual std::string writeVariable(int catalogIndex, const Value& value) = 0;
    // GO.VEL … UPD.MOVE, by MotionKind number (1..6).
    virtual void motion(int kind) = 0;
    // The serial port: program output, a complete input line (CR removed; nullopt until one came), INKEY$.
    virtual void write(std::string_view text) = 0;
    virtual std::optional<std::string> takeLine() = 0;
    virtual std::string takeChar() = 0;
    // Characters written but not yet on the line. A PRINT that leaves more than kTransmitBuffer waiting
    // holds the program until the line has carried them (DECISIONS.md 38): output never runs ahead of the
    // serial line, so protocol answers are not queued behind seconds of PRINT output.
    static constexpr std::size_t kTransmitBuffer = 256;
    virtual std::size_t outputBacklog() const { return 0; }
    // WHEN: the present value of a condition source (1..16 INPn, 17 POS.COMMAND, 18 POSITION, 19 ENCPOS,
    // 20 ANALOG.IN); latch the WHEN.* variables; perform the action.
    virtual double whenSample(int source) = 0;
    virtual void whenLatch() = 0;
    virtual void whenAction(int action, int argument, float value) = 0;
    // TMRSET(n, …): packed as the Tmrset instruction's argument.
    virtual void tmrset(int timer, float delay_s, int packed) = 0;
    // The highest-priority enabled and asserted interrupt source (catalog index), clearing its enable;
    // -1 when none. anyInterruptEnabled() lets the VM skip the check entirely (one flag per instruction).
    virtual int takeInterrupt() = 0;
    virtual bool anyInterruptEnabled() const = 0;
    virtual int axis() const = 0;
    virtual double pauseTime_s() = 0;
};

} // namespace drive_core::sc750
