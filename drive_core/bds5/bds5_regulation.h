// BDS5 profile regulation (REG/REGKHZ, L3044-3113): with REG on, profiles run at the rate of the external
// input — as specified at f_ext = REGKHZ, slower below, never faster — from the counts accumulated on PEXT.
// Counting backward halts the profile until forward counts cancel it; more than 30000 is ERR 64.
#pragma once

#include "bds5_variable_store.h"

#include <cstdint>
#include <optional>

namespace drive_core::bds5 {

class Bds5Regulation {
public:
    struct Tick {
        double profileFraction = 1; // how much of the servo period the profile advances (0..1)
        int error = 0;              // 64 BACKWARD REGULATION
    };
    // One servo period of dt_ms, reading REG, REGKHZ and PEXT.
    Tick step(const Bds5VariableStore& vars, double dt_ms);

private:
    std::optional<std::int32_t> m_lastPext;
    std::int64_t m_backward_counts = 0; // counted back and not yet cancelled
};

} // namespace drive_core::bds5
