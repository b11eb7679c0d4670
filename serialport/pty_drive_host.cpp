// Real-time pty host for a simulated drive.
#include "pty_drive_host.h"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <fcntl.h>
#include <optional>
#include <poll.h>
#include <stdlib.h>
#include <termios.h>
#include <unistd.h>
#include <utility>

namespace serialport {

namespace {
constexpr auto kTick = std::chrono::microseconds(1000);
constexpr int kMaxTicksPerWake = 200;
constexpr auto kDrainAfterEof = std::chrono::milliseconds(300); // let the drive answer the last line
} // namespace

PtyDriveHost::PtyDriveHost(std::unique_ptr<drive_core::Drive> drive, Options options)
    : m_drive(std::move(drive)), m_options(options) {}

PtyDriveHost::~PtyDriveHost() {
    if (m_slaveFd >= 0) ::close(m_slaveFd);
    if (m_masterFd >= 0) ::close(m_masterFd);
}

std::string PtyDriveHost::openPty() {
    m_masterFd = ::posix_openpt(O_RDWR | O_NOCTTY | O_NONBLOCK);
    if (m_masterFd < 0 || ::grantpt(m_masterFd) != 0 || ::unlockpt(m_masterFd) != 0) {
        m_error = std::string("cannot create a pseudo-terminal: ") + std::strerror(errno);
        return {};
    }
    const char* name = ::ptsname(m_masterFd);
    if (!name) {
        m_error = std::string("ptsname failed: ") + std::strerror(errno);
        return {};
    }
    std::string path(name);
    // Holding the slave open keeps the master readable between clients (no EIO when none is attached).
    m_slaveFd = ::open(path.c_str(), O_RDWR | O_NOCTTY);
    termios tio{};
    if (m_slaveFd < 0 || ::tcgetattr(m_slaveFd, &tio) != 0) {
        m_error = std::string("cannot open ") + path + ": " + std::strerror(errno);
        return {};
    }
    // Raw: no echo by the line discipline, no CR/LF translation — the drive does its own echo.
    ::cfmakeraw(&tio);
    ::cfsetispeed(&tio, B9600);
    ::cfsetospeed(&tio, B9600);
    ::tcsetattr(m_slaveFd, TCSANOW, &tio);
    m_inFd = m_outFd = m_masterFd;
    return path;
}

void PtyDriveHost::useDescriptors(int inFd, int outFd) {
    m_inFd = inFd;
    m_outFd = outFd;
}

int PtyDriveHost::run(const std::atomic<bool>& stop) {
    using Clock = std::chrono::steady_clock;
    m_drive->powerUp();
    const auto start = Clock::now();
    auto lastWall = start;
    double simulatedUs = 0;
    std::optional<Clock::time_point> eofAt;
    char buffer[4096];
    while (!stop.load()) {
        pollfd fd{m_inFd, POLLIN, 0};
        const int ready = eofAt ? 0 : ::poll(&fd, 1, 1);
        if (ready > 0 && (fd.revents & (POLLIN | POLLHUP))) {
            const ssize_t n = ::read(m_inFd, buffer, sizeof buffer);
            if (n > 0) {
                std::string bytes(buffer, std::size_t(n));
                if (m_options.lfIsCr) {
                    for (char& c : bytes) {
                        const bool wasCr = std::exchange(m_lastWasCr, c == '\r');
                        if (c == '\n' && !wasCr) c = '\r';
                    }
                }
                m_drive->receive(bytes);
            } else if (n == 0 || (errno != EAGAIN && errno != EINTR && errno != EIO)) {
                eofAt = Clock::now(); // stdin closed: answer what was sent, then stop
            }
        } else if (eofAt) {
            ::usleep(1000);
        }
        const auto now = Clock::now();
        const double wallDeltaS = std::chrono::duration<double>(now - lastWall).count();
        lastWall = now;
        simulatedUs += wallDeltaS * 1e6 * m_options.speedFactor;
        int ticks = 0;
        while (double(m_drive->now().count() + kTick.count()) <= simulatedUs && ticks < kMaxTicksPerWake) {
            m_drive->step(kTick);
            ++ticks;
        }
        if (ticks == kMaxTicksPerWake) simulatedUs = double(m_drive->now().count());
        m_backlog += m_drive->takeTransmitted(); // the drive's UART already paces at its BAUD rate
        flushOutput();
        if (eofAt && now - *eofAt > kDrainAfterEof) return 0;
    }
    return 0;
}

void PtyDriveHost::flushOutput() {
    if (m_backlog.empty()) return;
    const ssize_t written = ::write(m_outFd, m_backlog.data(), m_backlog.size());
    if (written > 0) m_backlog.erase(0, std::size_t(written));
    // EAGAIN: the client is not reading; keep the bytes (a real port would drop them, a pty just fills).
}

} // namespace serialport
