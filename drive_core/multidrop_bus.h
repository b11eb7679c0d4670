// MultidropBus: up to 32 simulated drives of one family on one RS-485/RS-422 line (issue 21), itself a Drive,
// so a pty, a TCP port or the IDE's SimulatorLink carries a whole bus as it carries one drive. Every axis
// hears every byte; each decides by its own manual's addressing whether it is spoken to, and only an
// addressed axis transmits (the electrical rule of a multidrop line). Axes share the bus's time. The bench
// (inputs, load, motor) is one axis's at a time: benchAxis().
//
// Each axis's address is set as a machine builder sets it once, before the first power-up:
// BDS5 (L5416-5469, L10013-10038): ADDR = the ID ('0'-'9', 'A'-'Z'), so each powers up asleep; '\' + ID wakes
//   one, '\' alone puts all to sleep, '\*' broadcasts (all execute, none transmit).
// SC750 (App. C L3676-3734): the S1 switch = the ID, a decimal address 0-254 ("1", "17"); all power up logged
//   off; "/nnn" logs one on, and every other unit (the one logged on before too) turns its transmitter off.
// PMC-960 (L2537-2568): THI = the ID, one character 21H-5AH ("A"); all power up listeners (pmc960/DECISIONS.md);
//   <attn> ID makes one the talker, the rest listeners; polls <attn> + lower case reach the talker alone.
#pragma once

#include "drive.h"

#include <memory>
#include <string>
#include <vector>

namespace drive_core {

class MultidropBus final : public Drive {
public:
    static constexpr std::size_t kMaxAxes = 32;

    // A bus of one axis per ID, in order; nullptr with why set (naming the manual's lines) when an ID cannot
    // be on a bus: not the family's form of address (above), a repeat, or more than 32.
    static std::unique_ptr<MultidropBus> make(DriveFamily family, const std::vector<std::string>& ids, std::string& why);

    DriveFamily family() const override { return m_family; }
    void powerUp() override;
    void receive(std::string_view bytes) override;
    std::string takeTransmitted() override;
    void step(Microseconds dt) override;
    Microseconds now() const override;
    void setLineRateLimited(bool limited) override;

    // The bench axis's pins and controls.
    int inputCount() const override { return bench().inputCount(); }
    int outputCount() const override { return bench().outputCount(); }
    void setInput(int number, bool on) override { bench().setInput(number, on); }
    bool input(int number) const override { return bench().input(number); }
    bool output(int number) const override { return bench().output(number); }
    SimulatorControls* controls() override { return bench().controls(); }

    std::size_t axisCount() const { return m_axes.size(); }
    const std::string& id(std::size_t axis) const { return m_ids[axis]; }
    Drive& axis(std::size_t axis) { return *m_axes[axis]; }
    // Which axis the bench's pins and controls reach (the first at first); false for an unknown ID.
    bool setBenchAxis(const std::string& id);
    std::size_t benchAxis() const { return m_bench; }

    // The bench's electronic line shaft (issue 21): master's encoder output wired to follower's master
    // (external encoder) input, so a gearbox or cam follows a real moving axis. The encoder output gives
    // kLineShaftCountsPerRev quadrature counts a motor revolution (chosen: a 1024-line encoder emulation; the
    // follower's GEARI/GEARO, or its family's ratio, scales them). Counted exactly: what the master turned in
    // one step reaches the follower in the next. A follower has one master; false with why when an ID is
    // unknown, the two are one axis, or the family's drive has no master input.
    static constexpr double kLineShaftCountsPerRev = 4096;
    bool setLineShaft(const std::string& master, const std::string& follower, std::string& why);
    void clearLineShafts();

private:
    MultidropBus(DriveFamily family, std::vector<std::string> ids, std::vector<std::unique_ptr<Drive>> axes);
    Drive& bench() const { return *m_axes[m_bench]; }

    DriveFamily m_family;
    std::vector<std::string> m_ids;
    std::vector<std::unique_ptr<Drive>> m_axes;
    std::size_t m_bench = 0;
    struct LineShaft {
        std::size_t master = 0, follower = 0;
        double lastPosition_rev = 0;
    };
    std::vector<LineShaft> m_shafts;
};

} // namespace drive_core
