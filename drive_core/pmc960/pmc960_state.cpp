// The PMC-960 status bits, and the table's servo settings handed to the loops.
#include "pmc960_state.h"

#include <algorithm>

namespace drive_core::pmc960 {

void Pmc960State::applyTable() {
    Pmc960Servo::Gains g;
    g.positionGain = int(table.inUse("TGP"));
    g.velocityGain = int(table.inUse("TGV"));
    g.tachGain = int(table.inUse("TGT"));
    g.positionComp = int(table.inUse("TGE"));
    g.velocityComp = int(table.inUse("TGB"));
    g.lockGain = int(table.inUse("TGL"));
    const std::int64_t tha = table.inUse("THA");
    g.countsPerRev = tha > 0 ? double(tha) : 4096.0; // an encoder (THA 0): 4,096 as the bench shows it
    g.rangeTop_cps = units().topSpeed_cps();
    const bool slave = (table.inUse("THR") & 0x40) != 0;
    // FFGAIN as TF scales it for the range in use (7.18.1; DECISIONS.md TF): the feedforward D/A's full scale
    // is the range's top speed, so the gain keeps the same share of the speed in every range.
    const int ff = int(table.inUse("TGF"));
    if (slave)
        g.feedForwardGain = ff;
    else if (g.rangeTop_cps <= 48000)
        g.feedForwardGain = ff / 4;
    else if (g.rangeTop_cps > 192000)
        g.feedForwardGain = std::min(2 * ff, 255);
    else
        g.feedForwardGain = ff;
    motion.setLoop(g);
    motion.setSlave(slave);
    softwareLimits = table.inUse("THS") != 0;
}

int Pmc960State::motionBits() const {
    int bits = 0;
    if (motion.enabled()) bits |= 0x80;
    if (motion.atPositiveStop()) bits |= 0x40;
    if (motion.camHold()) bits |= 0x10;
    if (motion.moving()) bits |= 0x08;
    if (motion.atTopSpeed()) bits |= 0x04;
    if (motion.forward()) bits |= 0x02;
    return bits;
}

} // namespace drive_core::pmc960
