// servodesk-sim: a simulated drive on a new pseudo-terminal (--pty), on stdin/stdout (--stdio) or on a TCP port (--tcp),
// running in real time until killed. Any serial program (picocom, pyserial, the IDE) can talk to it;
// --control adds a Unix-domain socket for the bench (inputs, limits, load, motor, power).
#include "drive_core/drive_factory.h"
#include "drive_core/multidrop_bus.h"
#include "drive_core/pmc960/pmc960_drive.h"
#include "serialport/pty_drive_host.h"

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>
#include <unistd.h>

namespace {

std::atomic<bool> g_stop{false};

void onSignal(int) {
    g_stop.store(true);
}

int usage(int code) {
    std::fprintf(code ? stderr : stdout,
                 "usage: servodesk-sim [--drive bds5|sc750|pmc960] (--pty | --stdio | --tcp [ADDR:]PORT) [--speed F]\n"
                 "                     [--axes ID,ID,...] [--control PATH] [--link PATH] [--overrun]\n"
                 "  --pty           create a pseudo-terminal; its path is printed first as \"PTY /dev/pts/N\"\n"
                 "  --stdio         talk on stdin/stdout (a lone LF counts as CR); stops at end of input\n"
                 "  --tcp [ADDR:]PORT  serve the drive as a serial device server does, on ADDR (default\n"
                 "                  127.0.0.1) and PORT (0: any free one), printed first as \"TCP ADDR:PORT\";\n"
                 "                  one client at a time; a client that opens with Telnet negotiation speaks\n"
                 "                  RFC 2217 (rfc2217://), any other gets the raw bytes (tcp://)\n"
                 "  --speed F       run simulated time F times faster than the wall clock (default 1)\n"
                 "  --axes ID,...   a multidrop bus of up to 32 drives on the one line; only the axis selected\n"
                 "                  answers. --control reaches the first axis until \"axis ID\" picks another.\n"
                 "                  bds5: ADDR = ID (0-9, A-Z), all asleep at power-up: \\ + ID wakes one,\n"
                 "                  \\ alone puts all to sleep, \\* broadcasts\n"
                 "                  sc750: S1 address = ID (0-254, e.g. 1,2,17), all logged off at power-up:\n"
                 "                  /nnn logs one on and every other one off\n"
                 "                  pmc960: THI = ID (one of 21H-5AH, e.g. A,B), all listeners at power-up:\n"
                 "                  <attn> (1DH) + ID makes one the talker; then a CR gets its prompt\n"
                 "  --link PATH     with --pty: also make PATH a symbolic link to the pty, replacing a stale\n"
                 "                  one, so a client can reconnect by name after a restart\n"
                 "  --overrun       one pmc960 only (not --axes): the controller's one-character receive\n"
                 "                  buffer overruns as the real one does: bytes cross at the baud rate, and one\n"
                 "                  arriving while the firmware is busy (5 ms after a + or - trigger, or while\n"
                 "                  a program runs) overwrites the one before. A pty has no CTS line, so a host\n"
                 "                  must pace itself (what RTS/CTS does on a real port)\n"
                 "  --control PATH  listen on a Unix-domain socket at PATH for bench commands, one a line,\n"
                 "                  each answered with one line (OK, ERROR <reason>, or the status):\n"
                 "                    input N on|off   enable on|off   motion on|off   home on|off\n"
                 "                    home-at REV   limits on|off on|off (positive, negative)\n"
                 "                    load-torque NM   load-inertia KGM2   master-hz HZ   motor NAME\n"
                 "                    load-coupling NM_PER_RAD NMS_PER_RAD (a compliant coupling: a two-mass\n"
                 "                    load with a resonance; bds5 only)   load-coupling off (rigid again)\n"
                 "                    master-wave sine|square|triangle AMP_HZ FREQ_HZ   master-wave off\n"
                 "                    analog-in V (the SC750's analog input, volts)\n"
                 "                    feedback on|off   power-cycle   status\n"
                 "                    with --axes: axis ID (the axis the others reach)   line-shaft MASTER\n"
                 "                    FOLLOWER (MASTER's encoder output, 4096 counts a rev, drives FOLLOWER's\n"
                 "                    master input: an electronic line shaft)   line-shaft off\n"
                 "                  With --pty, \"CONTROL PATH\" is printed after the PTY line.\n");
    return code;
}

} // namespace

int main(int argc, char** argv) {
    std::string_view driveName = "bds5";
    bool pty = false;
    bool stdio = false;
    serialport::PtyDriveHost::Options options;
    std::string controlPath;
    std::string linkPath;
    bool overrun = false;
    std::string tcpAddress = "127.0.0.1";
    int tcpPort = -1;
    std::vector<std::string> axes;
    for (int i = 1; i < argc; ++i) {
        const std::string_view arg = argv[i];
        const bool hasValue = i + 1 < argc;
        if (arg == "--drive" && hasValue)
            driveName = argv[++i];
        else if (arg == "--pty")
            pty = true;
        else if (arg == "--stdio")
            stdio = true;
        else if (arg == "--speed" && hasValue)
            options.speedFactor = std::atof(argv[++i]);
        else if (arg == "--control" && hasValue)
            controlPath = argv[++i];
        else if (arg == "--link" && hasValue)
            linkPath = argv[++i];
        else if (arg == "--overrun")
            overrun = true;
        else if (arg == "--axes" && hasValue) {
            std::string list = argv[++i];
            for (std::size_t at = 0; at <= list.size();) {
                const std::size_t comma = std::min(list.find(',', at), list.size());
                axes.push_back(list.substr(at, comma - at));
                at = comma + 1;
            }
        }
        else if (arg == "--tcp" && hasValue) {
            const std::string value = argv[++i];
            const auto colon = value.rfind(':');
            if (colon != std::string::npos) tcpAddress = value.substr(0, colon);
            char* end = nullptr;
            const std::string port = colon == std::string::npos ? value : value.substr(colon + 1);
            tcpPort = int(std::strtol(port.c_str(), &end, 10));
            if (port.empty() || *end != '\0' || tcpPort < 0 || tcpPort > 65535) {
                std::fprintf(stderr, "servodesk-sim: --tcp %s is not [ADDR:]PORT\n", value.c_str());
                return usage(2);
            }
        }
        else if (arg == "--help" || arg == "-h")
            return usage(0);
        else {
            std::fprintf(stderr, "servodesk-sim: unknown argument \"%s\"\n", argv[i]);
            return usage(2);
        }
    }
    if (int(pty) + int(stdio) + int(tcpPort >= 0) != 1) {
        std::fprintf(stderr, "servodesk-sim: choose exactly one of --pty, --stdio and --tcp\n");
        return usage(2);
    }
    const auto family = drive_core::familyFromName(driveName);
    std::unique_ptr<drive_core::Drive> drive;
    if (family && !axes.empty()) {
        std::string why;
        drive = drive_core::MultidropBus::make(*family, axes, why);
        if (!drive) {
            std::fprintf(stderr, "servodesk-sim: --axes: %s\n", why.c_str());
            return 2;
        }
    } else if (family) {
        drive = drive_core::makeDrive(*family);
    }
    if (!drive) {
        std::fprintf(stderr, "servodesk-sim: no simulator for drive \"%.*s\" (available: bds5, sc750, pmc960)\n",
                     int(driveName.size()), driveName.data());
        return 2;
    }
    if (overrun) {
        auto* pmc = dynamic_cast<drive_core::pmc960::Pmc960Drive*>(drive.get());
        if (!pmc) {
            std::fprintf(stderr, "servodesk-sim: --overrun is for one --drive pmc960 only, not --axes\n");
            return 2;
        }
        pmc->setOverrunModel(true);
    }
    std::signal(SIGINT, onSignal);
    std::signal(SIGTERM, onSignal);
    std::signal(SIGPIPE, SIG_IGN);

    options.lfIsCr = stdio;
    serialport::PtyDriveHost host(std::move(drive), options);
    if (!controlPath.empty() && !host.listenControl(controlPath)) {
        std::fprintf(stderr, "servodesk-sim: %s\n", host.errorText().c_str());
        return 1;
    }
    if (tcpPort >= 0) {
        if (!host.listenTcp(tcpAddress, tcpPort)) {
            std::fprintf(stderr, "servodesk-sim: %s\n", host.errorText().c_str());
            return 1;
        }
        std::printf("TCP %s:%d\n", tcpAddress.c_str(), host.tcpPort());
        if (!controlPath.empty()) std::printf("CONTROL %s\n", controlPath.c_str());
        std::fflush(stdout);
    } else if (pty) {
        const std::string path = host.openPty();
        if (path.empty()) {
            std::fprintf(stderr, "servodesk-sim: %s\n", host.errorText().c_str());
            return 1;
        }
        if (!linkPath.empty()) {
            ::unlink(linkPath.c_str()); // a link left by a previous run that was killed
            if (::symlink(path.c_str(), linkPath.c_str()) != 0) {
                std::fprintf(stderr, "servodesk-sim: cannot link %s to %s: %s\n", linkPath.c_str(), path.c_str(),
                             std::strerror(errno));
                return 1;
            }
        }
        std::printf("PTY %s\n", path.c_str());
        if (!controlPath.empty()) std::printf("CONTROL %s\n", controlPath.c_str());
        std::fflush(stdout);
    } else {
        host.useDescriptors(STDIN_FILENO, STDOUT_FILENO);
    }
    const int rc = host.run(g_stop);
    if (rc != 0) std::fprintf(stderr, "servodesk-sim: %s\n", host.errorText().c_str());
    return rc;
}
