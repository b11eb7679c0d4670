// Real-time pty host for a simulated drive.
#include "pty_drive_host.h"

#include "drive_core/multidrop_bus.h"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <fcntl.h>
#include <optional>
#include <poll.h>
#include <stdlib.h>
#include <sys/socket.h>
#include <sys/un.h>
#include <termios.h>
#include <unistd.h>
#include <utility>

namespace serialport {

namespace {
constexpr auto kTick = std::chrono::microseconds(1000);
constexpr int kMaxTicksPerWake = 200;
constexpr auto kDrainAfterEof = std::chrono::milliseconds(300); // let the drive answer the last line

// The bench's "line-shaft MASTER FOLLOWER" and "line-shaft off" (MultidropBus::setLineShaft).
std::string lineShaft(drive_core::MultidropBus* bus, const std::string& args) {
    if (!bus) return "ERROR a line shaft joins two axes of a bus (--axes)";
    if (args == "off") {
        bus->clearLineShafts();
        return "OK";
    }
    const std::size_t space = args.find(' ');
    if (space == std::string::npos) return "ERROR line-shaft MASTER FOLLOWER, or line-shaft off";
    std::string why;
    return bus->setLineShaft(args.substr(0, space), args.substr(space + 1), why) ? "OK" : "ERROR " + why;
}
} // namespace

PtyDriveHost::PtyDriveHost(std::unique_ptr<drive_core::Drive> drive, Options options)
    : m_drive(std::move(drive)), m_options(options) {}

PtyDriveHost::~PtyDriveHost() {
    if (m_slaveFd >= 0) ::close(m_slaveFd);
    if (m_masterFd >= 0) ::close(m_masterFd);
    for (const ControlClient& c : m_controlClients) ::close(c.fd);
    if (m_tcpClientFd >= 0) ::close(m_tcpClientFd);
    if (m_tcpListenFd >= 0) ::close(m_tcpListenFd);
    if (m_controlFd >= 0) {
        ::close(m_controlFd);
        ::unlink(m_controlPath.c_str());
    }
}

bool PtyDriveHost::listenControl(const std::string& path) {
    sockaddr_un address{};
    if (path.empty() || path.size() >= sizeof address.sun_path) {
        m_error = "control socket path is empty or too long: " + path;
        return false;
    }
    address.sun_family = AF_UNIX;
    std::memcpy(address.sun_path, path.c_str(), path.size() + 1);
    m_controlFd = ::socket(AF_UNIX, SOCK_STREAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
    if (m_controlFd >= 0) ::unlink(path.c_str()); // a socket left by an earlier run
    if (m_controlFd < 0 || ::bind(m_controlFd, reinterpret_cast<sockaddr*>(&address), sizeof address) != 0 ||
        ::listen(m_controlFd, 4) != 0) {
        m_error = "cannot listen on " + path + ": " + std::strerror(errno);
        if (m_controlFd >= 0) ::close(m_controlFd);
        m_controlFd = -1;
        return false;
    }
    m_controlPath = path;
    return true;
}

// Between two drive steps: new clients, then every complete line of every client, answered in order.
void PtyDriveHost::serveControl() {
    if (m_controlFd < 0) return;
    for (int fd; (fd = ::accept4(m_controlFd, nullptr, nullptr, SOCK_NONBLOCK | SOCK_CLOEXEC)) >= 0;)
        m_controlClients.push_back({fd, {}});
    char buffer[1024];
    for (auto it = m_controlClients.begin(); it != m_controlClients.end();) {
        bool closed = false;
        for (;;) {
            const ssize_t n = ::read(it->fd, buffer, sizeof buffer);
            if (n > 0) {
                it->pending.append(buffer, std::size_t(n));
                continue;
            }
            closed = n == 0 || (errno != EAGAIN && errno != EINTR);
            break;
        }
        for (auto end = it->pending.find('\n'); end != std::string::npos; end = it->pending.find('\n')) {
            std::string line = it->pending.substr(0, end);
            it->pending.erase(0, end + 1);
            if (!line.empty() && line.back() == '\r') line.pop_back();
            std::string answer;
            auto* bus = dynamic_cast<drive_core::MultidropBus*>(m_drive.get());
            if (line.rfind("axis ", 0) == 0) { // which axis of a bus the bench reaches
                answer = bus && bus->setBenchAxis(line.substr(5)) ? std::string("OK")
                                                                  : "ERROR no axis " + line.substr(5) + " on this line";
            } else if (line.rfind("line-shaft ", 0) == 0) { // "line-shaft A B": A's encoder output drives B
                answer = lineShaft(bus, line.substr(11));
            } else {
                drive_core::SimulatorControls* controls = m_drive->controls();
                answer = controls ? drive_core::runSimulatorCommand(*controls, line)
                                  : std::string("ERROR this drive has no simulator controls");
            }
            answer += '\n';
            // Answers are short; a client that does not read them loses them rather than stalling the drive.
            [[maybe_unused]] const ssize_t written = ::send(it->fd, answer.data(), answer.size(), MSG_NOSIGNAL);
        }
        if (closed) {
            ::close(it->fd);
            it = m_controlClients.erase(it);
        } else {
            ++it;
        }
    }
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
        serveTcp();
        pollfd fd{m_inFd, POLLIN, 0};
        const int ready = eofAt ? 0 : ::poll(&fd, 1, 1);
        if (ready > 0 && (fd.revents & (POLLIN | POLLHUP))) {
            const ssize_t n = ::read(m_inFd, buffer, sizeof buffer);
            if (n > 0) {
                std::string bytes(buffer, std::size_t(n));
                if (m_inFd == m_tcpClientFd) bytes = fromTcp(bytes);
                if (m_options.lfIsCr) {
                    for (char& c : bytes) {
                        const bool wasCr = std::exchange(m_lastWasCr, c == '\r');
                        if (c == '\n' && !wasCr) c = '\r';
                    }
                }
                m_drive->receive(bytes);
            } else if (m_inFd >= 0 && m_inFd == m_tcpClientFd && (n == 0 || (errno != EAGAIN && errno != EINTR))) {
                dropTcpClient(); // the client went: the drive waits for the next one
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
        serveControl();
        // The drive's UART already paces at its BAUD rate; with no TCP client the line has no listener.
        const std::string sent = m_drive->takeTransmitted();
        if (m_tcpListenFd < 0) m_backlog += sent;
        else if (m_tcpClientFd >= 0) m_backlog += m_telnet ? rfc2217::escape(sent) : sent;
        flushOutput();
        if (eofAt && now - *eofAt > kDrainAfterEof) return 0;
    }
    return 0;
}

void PtyDriveHost::flushOutput() {
    if (m_backlog.empty() || m_outFd < 0) return;
    const ssize_t written = m_outFd == m_tcpClientFd ? ::send(m_outFd, m_backlog.data(), m_backlog.size(), MSG_NOSIGNAL)
                                                     : ::write(m_outFd, m_backlog.data(), m_backlog.size());
    if (written > 0) m_backlog.erase(0, std::size_t(written));
    // EAGAIN: the client is not reading; keep the bytes (a real port would drop them, a pty just fills).
}

} // namespace serialport
