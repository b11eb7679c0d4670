// The Motion Dialogue <-> SC750 protocol on the wire (PROTOCOL.md): exact frame bytes, download with its
// integrity check, run/stop/continue/reset, breakpoints, variables, real-time calls, multidrop logon.
#include "sc750_bench.h"

#include "drive_core/drive_factory.h"
#include "drive_core/sc750/sc750_bin.h"
#include "drive_core/sc750/sc750_frame.h"

namespace sc750_test {
namespace {

// Sends one command and steps until a reply frame (any letter) arrives; returns "letter payload".
struct Wire {
    explicit Wire(Sc750Drive& d) : drive(d) {}
    Sc750Drive& drive;
    std::string program; // bytes outside frames (the program's own output)
    std::vector<std::string> events;

    std::string command(char letter, const std::string& payload) {
        drive.receive(encodeFrame(letter, payload));
        return awaitFrame(0.5);
    }
    std::string awaitFrame(double limit_s) {
        for (int i = 0; i < int(limit_s * 1000); ++i) {
            drive.step(drive_core::Microseconds(1000));
            for (char c : drive.takeTransmitted()) {
                if (c == kSoh) {
                    m_inFrame = true;
                    m_frame.clear();
                } else if (m_inFrame && c == '\r') {
                    m_inFrame = false;
                    const auto f = decodeFrame(m_frame);
                    EXPECT_TRUE(f.has_value()) << m_frame;
                    if (f) m_frames.push_back(std::string(1, f->letter) + f->payload);
                } else if (m_inFrame) {
                    m_frame += c;
                } else {
                    program += c;
                }
            }
            if (!m_frames.empty()) {
                std::string first = m_frames.front();
                m_frames.erase(m_frames.begin());
                return first;
            }
        }
        return "";
    }
    void download(const std::vector<std::uint8_t>& bin) {
        ASSERT_EQ(command('D', std::to_string(bin.size()) + "," + hex8(crc32(bin))), "D0");
        for (std::size_t at = 0; at < bin.size(); at += 64) {
            const std::size_t n = std::min<std::size_t>(64, bin.size() - at);
            const std::string chunk(bin.begin() + long(at), bin.begin() + long(at + n));
            ASSERT_EQ(command('W', std::to_string(at) + "," + toHex(chunk)), "W" + std::to_string(at + n));
        }
        ASSERT_EQ(command('Z', "").substr(0, 1), "Z");
    }
    static std::string hex8(std::uint32_t v) {
        char b[9];
        std::snprintf(b, sizeof b, "%08X", v);
        return b;
    }

private:
    bool m_inFrame = false;
    std::string m_frame;
    std::vector<std::string> m_frames;
};

TEST(Sc750Protocol, StatusFrameBytesOnTheWire) {
    Sc750Drive drive;
    drive.setLineRateLimited(false);
    EXPECT_EQ(encodeFrame('?', ""), std::string("\x01?3F\r"));
    drive.receive("\x01?3F\r");
    drive.step(drive_core::Microseconds(1000));
    EXPECT_EQ(drive.takeTransmitted(), std::string("\x01SN,0,0,0,112\r")); // no program, line 0, fault 0, dp off
}

TEST(Sc750Protocol, ABadChecksumIsRefused) {
    Sc750Drive drive;
    drive.setLineRateLimited(false);
    Wire wire{drive};
    drive.receive("\x01?00\r");
    EXPECT_EQ(wire.awaitFrame(0.01), "!01 BAD FRAME");
    EXPECT_EQ(wire.command('Q', ""), "!04 NO TRANSFER");
    EXPECT_EQ(wire.command('J', ""), "!01 UNKNOWN COMMAND");
}

TEST(Sc750Protocol, RepliesLeaveAtNineThousandSixHundredBaud) {
    Sc750Drive drive; // line rate limited by default: ten bits a character
    drive.receive(encodeFrame('V', ""));
    drive.step(drive_core::Microseconds(1000));
    const std::string first = drive.takeTransmitted();
    EXPECT_LE(first.size(), 1u);
    drive.step(drive_core::Microseconds(20000));
    EXPECT_EQ(first + drive.takeTransmitted(), encodeFrame('V', "752,2.8,1,255"));
}

TEST(Sc750Protocol, APrintLoopRunsAtTheLinesPaceAndAnswersStillComeSoon) {
    Sc750Drive drive; // 9600 baud: ~960 characters a second
    Wire wire{drive};
    drive.setLineRateLimited(false);
    wire.download(compile("DIM n AS INTEGER\nFOR n = 1 TO 1000000\n  PRINT \"line\"; n\nNEXT n\nEND\n").bin);
    drive.setLineRateLimited(true);
    ASSERT_EQ(wire.command('R', "").substr(0, 1), "R");
    wire.awaitFrame(2.0); // two seconds of printing (no frame comes: the program never ends)
    // The program waited for the line: about 1,920 characters went out, not the millions it could print.
    EXPECT_GT(wire.program.size(), 1500u);
    EXPECT_LT(wire.program.size(), 2400u);
    // A status request waits behind at most the 256-character buffer (~0.27 s), not seconds of output.
    drive.receive(encodeFrame('?', ""));
    const std::string before = wire.program;
    const std::string status = wire.awaitFrame(0.5);
    EXPECT_EQ(status.substr(0, 1), "S") << "no status within 0.5 s";
    EXPECT_LE(wire.program.size() - before.size(), 300u);
}

TEST(Sc750Protocol, DownloadRunBreakpointVariablesContinue) {
    Sc750Drive drive;
    drive.setLineRateLimited(false);
    Wire wire{drive};
    const CompileResult program = compile("DIM n AS INTEGER\nFOR n = 1 TO 3\n  PRINT \"pass\"; n\nNEXT n\nEND\n");
    ASSERT_TRUE(program.ok());
    wire.download(program.bin);
    EXPECT_EQ(wire.command('?', ""), "SL,2,0,0,1"); // loaded, at the first executable line
    EXPECT_EQ(wire.command('B', "+3"), "B3");
    EXPECT_EQ(wire.command('B', "+1"), "!07 NO STATEMENT ON LINE");
    EXPECT_EQ(wire.command('R', ""), "R");
    EXPECT_EQ(wire.awaitFrame(0.1), "b3"); // breakpoint hit, before line 3 runs
    EXPECT_EQ(wire.command('G', "N"), "GN=1");
    EXPECT_EQ(wire.command('P', "N=2"), "PN=2");
    EXPECT_EQ(wire.command('G', "RUN.SPEED"), "GRUN.SPEED=1000");
    EXPECT_EQ(wire.command('C', ""), "C");
    EXPECT_EQ(wire.awaitFrame(0.1), "b3");
    EXPECT_EQ(wire.program, "pass 2 \r\n");
    EXPECT_EQ(wire.command('B', "*"), "B");
    EXPECT_EQ(wire.command('C', ""), "C");
    EXPECT_EQ(wire.awaitFrame(0.1), "e5");
    EXPECT_EQ(wire.program, "pass 2 \r\npass 3 \r\n");
    EXPECT_EQ(wire.command('?', ""), "SE,5,0,0,1");
}

TEST(Sc750Protocol, CtrlCStopsARunningProgramAndXResets) {
    Sc750Drive drive;
    drive.setLineRateLimited(false);
    Wire wire{drive};
    wire.download(compile("Again:\nGOTO Again\n").bin);
    EXPECT_EQ(wire.command('R', ""), "R");
    EXPECT_EQ(wire.command('?', ""), "SR,2,0,1,1"); // running: the decimal point is lit
    EXPECT_EQ(wire.command('P', "RUN.SPEED=5"), "!03 PROGRAM RUNNING");
    drive.receive(std::string(1, kStopByte));
    EXPECT_EQ(wire.awaitFrame(0.01).substr(0, 1), "H");
    EXPECT_EQ(wire.command('?', "").substr(0, 2), "SS");
    EXPECT_EQ(wire.command('X', ""), "X");
    EXPECT_EQ(wire.command('?', ""), "SL,2,0,0,1");
}

TEST(Sc750Protocol, DamagedDownloadIsRefusedAndTheOldProgramKept) {
    Sc750Drive drive;
    drive.setLineRateLimited(false);
    Wire wire{drive};
    const auto bin = compile("PRINT 1\n").bin;
    ASSERT_EQ(wire.command('D', std::to_string(bin.size()) + "," + Wire::hex8(crc32(bin) ^ 1)), "D0");
    const std::string all(bin.begin(), bin.end());
    for (std::size_t at = 0; at < all.size(); at += 64)
        wire.command('W', std::to_string(at) + "," + toHex(all.substr(at, 64)));
    EXPECT_EQ(wire.command('Z', ""), "!05 CHECKSUM");
    EXPECT_EQ(wire.command('?', "").substr(0, 2), "SN");
    EXPECT_EQ(wire.command('W', "0,00"), "!04 NO TRANSFER");
}

TEST(Sc750Protocol, ProgramOutputAndInputPassThrough) {
    Sc750Drive drive;
    drive.setLineRateLimited(false);
    Wire wire{drive};
    wire.download(compile("DIM s AS STRING\nINPUT \"Name\"; s\nPRINT \"Hello \"; s\n").bin);
    wire.command('R', "");
    wire.awaitFrame(0.02);
    EXPECT_EQ(wire.program, "Name? ");
    drive.receive("Ann\r");
    EXPECT_EQ(wire.awaitFrame(0.05), "e3");
    EXPECT_EQ(wire.program, "Name? Ann\r\nHello Ann\r\n");
}

TEST(Sc750Protocol, RealTimeFunctionCallsMoveTheMotor) {
    Sc750Drive drive;
    drive.setLineRateLimited(false);
    Wire wire{drive};
    EXPECT_EQ(wire.command('P', "ENABLE=1"), "PENABLE=1");
    EXPECT_EQ(wire.command('P', "INDEX.DIST=8192"), "PINDEX.DIST=8192");
    EXPECT_EQ(wire.command('P', "POSITION=1"), "!14 READ ONLY");
    EXPECT_EQ(wire.command('F', "GO.INCR"), "FGO.INCR");
    wire.awaitFrame(0.5);
    EXPECT_EQ(wire.command('G', "POSITION"), "GPOSITION=8192");
    EXPECT_EQ(wire.command('F', "SEEK.HOME"), "!10 UNKNOWN FUNCTION");
}

TEST(Sc750Protocol, SourceStoreDownloadAndUpload) {
    Sc750Drive drive;
    drive.setLineRateLimited(false);
    Wire wire{drive};
    const std::string source = "PRINT \"stored\"\r\n";
    const std::vector<std::uint8_t> bytes(source.begin(), source.end());
    EXPECT_EQ(wire.command('T', std::to_string(source.size()) + "," + Wire::hex8(crc32(bytes))), "T0");
    EXPECT_EQ(wire.command('t', "0," + toHex(source)), "t16");
    EXPECT_EQ(wire.command('Q', ""), "Q16");
    EXPECT_EQ(wire.command('u', "0"), "u0," + toHex(source));
    EXPECT_EQ(wire.command('u', "16"), "u16,");
}

TEST(Sc750Protocol, UnconfiguredControllerWillNotEnable) {
    Sc750Drive drive;
    drive.setLineRateLimited(false);
    Wire wire{drive};
    EXPECT_EQ(wire.command('K', "0"), "K0");
    wire.command('P', "ENABLE=1");
    EXPECT_EQ(wire.command('G', "ENABLED"), "GENABLED=0");
    EXPECT_EQ(wire.command('?', ""), "SN,0,0,0,0");
}

TEST(Sc750Protocol, MultidropLogonSelectsTheAxis) {
    Sc750Drive drive;
    drive.setAxisAddress(5);
    drive.powerUp();
    drive.setLineRateLimited(false);
    Wire wire{drive};
    EXPECT_EQ(wire.command('?', ""), ""); // not logged on: silent
    drive.receive("/5,");
    EXPECT_EQ(wire.command('V', ""), "V752,2.8,1,5");
    drive.receive("/006");
    EXPECT_EQ(wire.command('?', ""), "");
    drive.receive("/005");
    EXPECT_EQ(wire.command('G', "LOGGEDON"), "GLOGGEDON=1");
}

TEST(Sc750Protocol, FactoryMakesAnSc750) {
    auto drive = drive_core::makeDrive(drive_core::DriveFamily::Sc750);
    ASSERT_NE(drive, nullptr);
    EXPECT_EQ(drive->family(), drive_core::DriveFamily::Sc750);
    EXPECT_EQ(drive->inputCount(), 16);
    EXPECT_EQ(drive->outputCount(), 12);
}

} // namespace
} // namespace sc750_test
