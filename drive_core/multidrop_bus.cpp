// MultidropBus: one line, many drives.
#include "multidrop_bus.h"

#include "bds5/bds5_drive.h"
#include "drive_factory.h"
#include "pmc960/pmc960_drive.h"
#include "sc750/sc750_drive.h"

#include <algorithm>

namespace drive_core {

namespace {
// One axis of each family, its address set as the manual has a machine builder set it once (kept over a power
// cycle), or nullptr with why: what is wrong with the ID, and the manual's lines that say so.
std::unique_ptr<Drive> bds5Axis(const std::string& id, std::string& why) {
    if (id.size() != 1 || !((id[0] >= '0' && id[0] <= '9') || (id[0] >= 'A' && id[0] <= 'Z'))) {
        why = "\"" + id + "\" is not a BDS5 axis ID (one of 0-9 and A-Z, L5416-5424)";
        return nullptr;
    }
    auto drive = std::make_unique<bds5::Bds5Drive>();
    drive->setAddress(id[0]);
    return drive;
}

// The S1 switch: 0-254 on a multidrop line, 255 is RS-232 (App. C L3682, L3708-3710). The ID is the number
// as written ("7", not "07"), so that two spellings of one address cannot both be on the line.
std::unique_ptr<Drive> sc750Axis(const std::string& id, std::string& why) {
    const bool digits =
        !id.empty() && id.size() <= 3 && std::all_of(id.begin(), id.end(), [](char c) { return c >= '0' && c <= '9'; });
    const int address = digits ? std::stoi(id) : -1;
    if (address < 0 || address > 254 || std::to_string(address) != id) {
        why = "\"" + id +
              "\" is not an SC750 multidrop address (a decimal number 0-254 without leading zeros, App. C "
              "L3682, L3708; 255 is RS-232 and no multidrop, L3710)";
        return nullptr;
    }
    auto drive = std::make_unique<sc750::Sc750Drive>();
    drive->setAxisAddress(address);
    return drive;
}

// THI's axis ID: one character 21H-5AH (L1918, digest 11.2 #19), so never a lower-case poll letter (L2547).
std::unique_ptr<Drive> pmc960Axis(const std::string& id, std::string& why) {
    if (id.size() != 1 || id[0] < 0x21 || id[0] > 0x5A) {
        why = "\"" + id +
              "\" is not a PMC-960 axis ID (one character 21H-5AH as THI takes it, such as A-Z or 0-9, "
              "L1918; a lower-case letter after <attn> is a status poll, L2543-2551)";
        return nullptr;
    }
    auto drive = std::make_unique<pmc960::Pmc960Drive>();
    drive->joinBus(id[0]);
    return drive;
}

std::unique_ptr<Drive> makeAxis(DriveFamily family, const std::string& id, std::string& why) {
    switch (family) {
    case DriveFamily::Bds5: return bds5Axis(id, why);
    case DriveFamily::Sc750: return sc750Axis(id, why);
    case DriveFamily::Pmc960: return pmc960Axis(id, why);
    }
    why = "a multidrop bus of " + std::string(familyTitle(family)) + " drives is not simulated";
    return nullptr;
}
} // namespace

std::unique_ptr<MultidropBus> MultidropBus::make(DriveFamily family, const std::vector<std::string>& ids,
                                                 std::string& why) {
    if (ids.empty() || ids.size() > kMaxAxes) {
        why = "a bus has 1 to 32 axes, not " + std::to_string(ids.size());
        return nullptr;
    }
    std::vector<std::unique_ptr<Drive>> axes;
    for (std::size_t i = 0; i < ids.size(); ++i) {
        auto drive = makeAxis(family, ids[i], why);
        if (!drive) return nullptr;
        if (std::find(ids.begin(), ids.begin() + std::ptrdiff_t(i), ids[i]) != ids.begin() + std::ptrdiff_t(i)) {
            why = "axis ID " + ids[i] + " is on the bus twice: both drives would answer at once";
            return nullptr;
        }
        axes.push_back(std::move(drive));
    }
    return std::unique_ptr<MultidropBus>(new MultidropBus(family, ids, std::move(axes)));
}

MultidropBus::MultidropBus(DriveFamily family, std::vector<std::string> ids, std::vector<std::unique_ptr<Drive>> axes)
    : m_family(family), m_ids(std::move(ids)), m_axes(std::move(axes)) {}

void MultidropBus::powerUp() {
    for (auto& a : m_axes) a->powerUp();
}

void MultidropBus::receive(std::string_view bytes) {
    for (auto& a : m_axes) a->receive(bytes);
}

// Only an addressed axis drives the line; what each one sent since the last call, in axis order.
std::string MultidropBus::takeTransmitted() {
    std::string sent;
    for (auto& a : m_axes) sent += a->takeTransmitted();
    return sent;
}

void MultidropBus::step(Microseconds dt) {
    for (auto& a : m_axes) a->step(dt);
    if (m_shafts.empty() || dt.count() <= 0) return;
    const double dt_s = double(dt.count()) * 1e-6;
    for (LineShaft& shaft : m_shafts) {
        const double position_rev = m_axes[shaft.master]->controls()->status().position_rev;
        const double counts = (position_rev - shaft.lastPosition_rev) * kLineShaftCountsPerRev;
        shaft.lastPosition_rev = position_rev;
        m_axes[shaft.follower]->controls()->setMasterFrequency_Hz(counts / dt_s);
    }
}

bool MultidropBus::setLineShaft(const std::string& master, const std::string& follower, std::string& why) {
    const auto index = [this](const std::string& id) { return std::size_t(std::find(m_ids.begin(), m_ids.end(), id) - m_ids.begin()); };
    const std::size_t m = index(master), f = index(follower);
    if (m == m_ids.size() || f == m_ids.size()) {
        why = "no axis " + (m == m_ids.size() ? master : follower) + " on this line";
        return false;
    }
    if (m == f) {
        why = "an axis cannot follow itself";
        return false;
    }
    if (!m_axes[m]->controls() || !m_axes[f]->controls()) {
        why = "these drives have no bench to wire";
        return false;
    }
    std::erase_if(m_shafts, [f](const LineShaft& s) { return s.follower == f; }); // one master a follower
    m_shafts.push_back({m, f, m_axes[m]->controls()->status().position_rev});
    return true;
}

void MultidropBus::clearLineShafts() {
    for (const LineShaft& s : m_shafts) m_axes[s.follower]->controls()->setMasterFrequency_Hz(0);
    m_shafts.clear();
}

Microseconds MultidropBus::now() const {
    return m_axes.front()->now();
}

void MultidropBus::setLineRateLimited(bool limited) {
    for (auto& a : m_axes) a->setLineRateLimited(limited);
}

bool MultidropBus::setBenchAxis(const std::string& id) {
    const auto it = std::find(m_ids.begin(), m_ids.end(), id);
    if (it == m_ids.end()) return false;
    m_bench = std::size_t(it - m_ids.begin());
    return true;
}

} // namespace drive_core
