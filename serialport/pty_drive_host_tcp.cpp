// The simulated drive on a TCP port: a serial device server's raw socket or RFC 2217 (issue 21).
#include "pty_drive_host.h"

#include <arpa/inet.h>
#include <cerrno>
#include <cstring>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <sys/socket.h>
#include <unistd.h>

#include <utility>

namespace serialport {

bool PtyDriveHost::listenTcp(const std::string& address, int port) {
    sockaddr_in where{};
    where.sin_family = AF_INET;
    where.sin_port = htons(static_cast<std::uint16_t>(port));
    if (port < 0 || port > 65535 || ::inet_pton(AF_INET, address.c_str(), &where.sin_addr) != 1) {
        m_error = "not an IPv4 address and port: " + address + ":" + std::to_string(port);
        return false;
    }
    m_tcpListenFd = ::socket(AF_INET, SOCK_STREAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
    const int on = 1;
    if (m_tcpListenFd >= 0) ::setsockopt(m_tcpListenFd, SOL_SOCKET, SO_REUSEADDR, &on, sizeof on);
    socklen_t length = sizeof where;
    if (m_tcpListenFd < 0 || ::bind(m_tcpListenFd, reinterpret_cast<sockaddr*>(&where), sizeof where) != 0 ||
        ::listen(m_tcpListenFd, 4) != 0 ||
        ::getsockname(m_tcpListenFd, reinterpret_cast<sockaddr*>(&where), &length) != 0) {
        m_error = "cannot listen on " + address + ":" + std::to_string(port) + ": " + std::strerror(errno);
        if (m_tcpListenFd >= 0) ::close(m_tcpListenFd);
        m_tcpListenFd = -1;
        return false;
    }
    m_tcpPort = ntohs(where.sin_port);
    return true;
}

// Between two drive steps: the first client in takes the line; a second is closed at once.
void PtyDriveHost::serveTcp() {
    if (m_tcpListenFd < 0) return;
    for (int fd; (fd = ::accept4(m_tcpListenFd, nullptr, nullptr, SOCK_NONBLOCK | SOCK_CLOEXEC)) >= 0;) {
        if (m_tcpClientFd >= 0) {
            ::close(fd);
            continue;
        }
        const int on = 1;
        ::setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &on, sizeof on); // a typed character goes at once
        m_tcpClientFd = m_inFd = m_outFd = fd;
        m_tcpFresh = true;
        m_telnet = false;
        m_telnetServer = rfc2217::Server{};
        m_backlog.clear();
    }
}

std::string PtyDriveHost::fromTcp(std::string_view bytes) {
    if (std::exchange(m_tcpFresh, false)) m_telnet = static_cast<unsigned char>(bytes.front()) == rfc2217::kIac;
    if (!m_telnet) return std::string(bytes);
    std::string reply;
    std::string data = m_telnetServer.feed(bytes, reply);
    m_backlog += reply;
    return data;
}

void PtyDriveHost::dropTcpClient() {
    ::close(m_tcpClientFd);
    m_tcpClientFd = m_inFd = m_outFd = -1;
    m_backlog.clear();
}

} // namespace serialport
