// Test bench for the SC750: compiles a program, loads it into a simulated drive, steps simulated time in
// 1 ms increments and collects what the drive transmits. Time is simulated, never read.
#pragma once

#include "drive_core/sc750/sc750_compiler.h"
#include "drive_core/sc750/sc750_drive.h"

#include <gtest/gtest.h>

#include <functional>
#include <string>

namespace sc750_test {

using namespace drive_core::sc750;

struct Bench {
    Sc750Drive drive;
    std::string out;    // the program's own output
    std::string frames; // protocol frames the drive sent (events), SOH … CR

    explicit Bench(const std::string& source, bool start = true) {
        drive.setLineRateLimited(false);
        const CompileResult result = compile(source);
        if (!result.ok()) {
            ADD_FAILURE() << result.error->text();
            return;
        }
        std::string why;
        EXPECT_TRUE(drive.loadProgram(result.bin, &why)) << why;
        if (start) drive.vm().start();
    }
    void collect() {
        for (char c : drive.takeTransmitted()) {
            if (c == 0x01) m_inFrame = true;
            (m_inFrame ? frames : out) += c;
            if (c == '\r' && m_inFrame) m_inFrame = false;
        }
    }
    void run(double seconds) {
        for (long i = 0, n = long(seconds * 1000); i < n; ++i) {
            drive.step(drive_core::Microseconds(1000));
            collect();
        }
    }
    // Steps until done() or the limit; returns whether done() came true.
    bool runUntil(const std::function<bool()>& done, double limit_s) {
        for (long i = 0, n = long(limit_s * 1000); i < n; ++i) {
            if (done()) return true;
            drive.step(drive_core::Microseconds(1000));
            collect();
        }
        return done();
    }
    double value(const char* name) { return toDouble(*drive.readNamed(name)); }
    Value user(const char* name, int element = 0) {
        return *drive.vm().variable(drive.vm().findVariable(name), element);
    }
    void type(const std::string& text) { drive.receive(text); }

private:
    bool m_inFrame = false;
};

// An enabled drive with no program, its variables set by name first (the servo tests).
struct ServoBench {
    Bench b{"END\n", false};

    explicit ServoBench(std::initializer_list<std::pair<const char*, std::string>> settings = {}) {
        for (const auto& [name, value] : settings) EXPECT_EQ(b.drive.writeNamed(name, value), "") << name;
        EXPECT_EQ(b.drive.writeNamed("ENABLE", "1"), "");
    }
    double value(const char* name) { return b.value(name); }
    void set(const char* name, const std::string& value) { EXPECT_EQ(b.drive.writeNamed(name, value), "") << name; }
};

} // namespace sc750_test
