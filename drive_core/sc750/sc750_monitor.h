// The SC750's side of the Motion Dialogue protocol (PROTOCOL.md): collects frames from the serial bytes,
// executes download, run/stop/continue/reset, breakpoints, variable access, real-time calls, source
// storage and configuration, and reports program events (breakpoint hit, end, run-time error).
#pragma once

#include "sc750_vm.h"

#include <cstdint>
#include <string>

namespace drive_core::sc750 {

class Sc750Drive;

class Sc750Monitor {
public:
    explicit Sc750Monitor(Sc750Drive& drive) : m_drive(drive) {}

    void reset();
    bool inFrame() const { return m_inFrame; }
    // A byte that belongs to the protocol: SOH starts a frame, CR ends it, Ctrl C stops the program.
    void feed(char c);
    // The program stopped running by itself (END, STOP, breakpoint, run-time error): tell the host.
    void programHalted(Vm::State state);

private:
    void execute(char letter, const std::string& payload);
    void reply(char letter, const std::string& payload);
    void error(int code, const std::string& text);
    void stopProgram();
    std::string statusText() const;
    void readVariable(const std::string& name, char letter = 'G');
    void writeVariable(const std::string& assignment);
    void breakpoint(const std::string& payload);
    void transfer(char letter, const std::string& payload);

    Sc750Drive& m_drive;
    bool m_inFrame = false;
    std::string m_frame;
    std::string m_download; // .BIN (or source) bytes received so far
    std::size_t m_expected = 0;
    std::uint32_t m_expectedCrc = 0;
    bool m_downloading = false;
    bool m_source = false; // the transfer in progress is source text, not a .BIN
};

} // namespace drive_core::sc750
