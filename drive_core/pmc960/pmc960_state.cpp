// The PMC-960 snapshot register.
#include "pmc960_state.h"

namespace drive_core::pmc960 {

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
