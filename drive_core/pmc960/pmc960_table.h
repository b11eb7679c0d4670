// The PMC-960 parameter table (T commands, 7.18): non-volatile values in the ZeroPower RAM, and the values
// in use. They differ only after a generic power-up with ESTOP' asserted (L1717, L875): the table survives
// power cycles, the in-use copy is reloaded from it (or from the generic values) at every power-up.
#pragma once

#include "drive_core/catalog/pmc960_catalog.h"

#include <cstdint>
#include <map>
#include <string>
#include <string_view>

namespace drive_core::pmc960 {

class Pmc960Table {
public:
    Pmc960Table(); // factory values

    // Power-up: in-use values from the table, or the generic ones (ESTOP' held at power-up).
    void load(bool generic);

    // name is "TGP", "THC", "TUS" ...; unknown names read 0 and ignore writes.
    std::int64_t stored(std::string_view name) const;
    std::int64_t inUse(std::string_view name) const;
    // Writes both the table and the value in use (the caller has checked SW and the range).
    void set(std::string_view name, std::int64_t value);

    // TF: feedforward gains for the 48 k, 192 k, 384 k and external ranges, computed when TGF was set.
    // chosen (digest §11.2 #30): proportional to the range's top speed, 192 kHz = TGF; Ext = TGF.
    struct FeedForward {
        int gain48 = 0, gain192 = 0, gain384 = 0, gainExt = 0;
    };
    FeedForward feedForward() const;
    // Whether TGF = value overflows another range (#9C).
    static bool feedForwardOverflows(std::int64_t value) { return value * 2 > 255; }

private:
    std::map<std::string, std::int64_t, std::less<>> m_stored;
    std::map<std::string, std::int64_t, std::less<>> m_inUse;
};

} // namespace drive_core::pmc960
