// MultidropBus: one line, many drives.
#include "multidrop_bus.h"

#include "bds5/bds5_drive.h"
#include "drive_factory.h"

#include <algorithm>

namespace drive_core {

namespace {
bool bds5Id(const std::string& id) {
    return id.size() == 1 && ((id[0] >= '0' && id[0] <= '9') || (id[0] >= 'A' && id[0] <= 'Z'));
}
} // namespace

std::unique_ptr<MultidropBus> MultidropBus::make(DriveFamily family, const std::vector<std::string>& ids,
                                                 std::string& why) {
    if (family != DriveFamily::Bds5) {
        why = std::string("a multidrop bus of ") + std::string(familyTitle(family)) + " drives is not simulated yet";
        return nullptr;
    }
    if (ids.empty() || ids.size() > kMaxAxes) {
        why = "a bus has 1 to 32 axes, not " + std::to_string(ids.size());
        return nullptr;
    }
    std::vector<std::unique_ptr<Drive>> axes;
    for (std::size_t i = 0; i < ids.size(); ++i) {
        if (!bds5Id(ids[i])) {
            why = "\"" + ids[i] + "\" is not a BDS5 axis ID (one of 0-9 and A-Z, L5416-5424)";
            return nullptr;
        }
        if (std::find(ids.begin(), ids.begin() + std::ptrdiff_t(i), ids[i]) != ids.begin() + std::ptrdiff_t(i)) {
            why = "axis ID " + ids[i] + " is on the bus twice: both drives would answer at once";
            return nullptr;
        }
        auto drive = std::make_unique<bds5::Bds5Drive>();
        drive->setAddress(ids[i][0]);
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
