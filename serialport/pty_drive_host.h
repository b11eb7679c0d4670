// Puts a simulated drive on a pseudo-terminal (or on a pair of file descriptors such as stdin/stdout)
// and runs it in real time, with an optional control socket for the bench (SimulatorControls' text
// form). Plain POSIX, no Qt: this is the engine of servodesk-sim.
#pragma once

#include "rfc2217.h"

#include "drive_core/drive.h"

#include <atomic>
#include <memory>
#include <string>
#include <vector>

namespace serialport {

class PtyDriveHost {
public:
    struct Options {
        double speedFactor = 1.0; // simulated seconds per wall-clock second
        bool lfIsCr = false;      // treat a lone LF from the host as CR (for line-buffered terminals)
    };

    PtyDriveHost(std::unique_ptr<drive_core::Drive> drive, Options options);
    ~PtyDriveHost();

    // Creates a new pseudo-terminal in raw mode and returns its slave path ("/dev/pts/5"); "" on failure
    // with errorText() set. The host keeps the slave open itself so the drive survives clients that
    // come and go.
    std::string openPty();
    // Uses the given descriptors instead of a pty (servodesk-sim --stdio).
    void useDescriptors(int inFd, int outFd);

    // Listens on a Unix-domain stream socket at path for the bench's text commands (one a line, answered
    // with one line: runSimulatorCommand()); any number of clients. A stale socket file is replaced.
    // False with errorText() set on failure. The socket file is removed when the host is destroyed.
    bool listenControl(const std::string& path);

    // Serves the drive on a TCP port, as a serial device server does (servodesk-sim --tcp): one client at a
    // time (a serial line has one host; a second connection is closed at once). A client whose first byte is
    // Telnet's IAC speaks RFC 2217 (the baud rate and framing are negotiated and the data is escaped); any
    // other gets the raw byte stream. address "127.0.0.1" keeps the drive off the plant's network. False
    // with errorText() set when the port cannot be bound; the port bound (port 0: one the system chose) is
    // tcpPort().
    bool listenTcp(const std::string& address, int port);
    int tcpPort() const { return m_tcpPort; }

    // Powers the drive up and runs it until stop becomes true or the input reaches end of file
    // (stdio only). Returns 0, or 1 on an I/O error (errorText() says which).
    int run(const std::atomic<bool>& stop);

    const std::string& errorText() const { return m_error; }

private:
    void flushOutput();
    void serveControl(); // accepts clients, runs their complete lines (between drive steps)
    void serveTcp();     // accepts the TCP client (pty_drive_host_tcp.cpp)
    std::string fromTcp(std::string_view bytes); // the drive's bytes in what the client sent
    void dropTcpClient();

    struct ControlClient {
        int fd = -1;
        std::string pending; // received, not yet a complete line
    };

    std::unique_ptr<drive_core::Drive> m_drive;
    Options m_options;
    int m_inFd = -1;
    int m_outFd = -1;
    int m_masterFd = -1;
    int m_slaveFd = -1;
    std::string m_backlog; // sent by the drive, not yet accepted by the pty (its client is slow)
    bool m_lastWasCr = false;
    std::string m_error;
    int m_controlFd = -1;
    std::string m_controlPath;
    std::vector<ControlClient> m_controlClients;
    int m_tcpListenFd = -1;
    int m_tcpPort = 0;
    int m_tcpClientFd = -1;
    bool m_tcpFresh = false; // the client has sent nothing yet: raw or RFC 2217 is still open
    bool m_telnet = false;   // the client speaks RFC 2217
    rfc2217::Server m_telnetServer;
};

} // namespace serialport
