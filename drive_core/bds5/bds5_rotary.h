// The BDS5's rotary mode (ROTARY, PROTARY, L5248-5286): PFB, PCMD and PFNL roll over by PROTARY when PFB
// leaves 0..PROTARY. PROTARY is exact in user units and may be a fraction of a count, so the roll-over
// carries the fraction and no error accumulates however many turns the axis makes.
#pragma once

#include "bds5_variable_store.h"

#include <cstdint>

namespace drive_core::bds5 {

class Bds5Rotary {
public:
    // Called every servo period with the PFB just sampled (counts). Returns the counts to add to PFB,
    // PCMD and PFNL: -PROTARY when PFB (in user units) is above PROTARY, +PROTARY when it is below 0,
    // else 0 (also with ROTARY off). The fraction of a count left over is kept for the next roll-over.
    std::int64_t rollover(std::int64_t pfb_counts, const Bds5VariableStore& vars);
    void reset() { m_remainder = 0; }

private:
    // PROTARY x PNUM not yet a whole count, in 1/PDEN counts (0 <= remainder < PDEN).
    std::int64_t m_remainder = 0;
};

} // namespace drive_core::bds5
