// libFuzzer entry for the ServoBASIC Plus compiler and VM: any bytes are compiled; a program that compiles
// is loaded into a simulated SC750 and run for 50 ms of simulated time with its .BIN also re-read.
// Nothing may crash, hang or trip a sanitizer. Built as a replay over the manual's examples everywhere.
#include "drive_core/sc750/sc750_bin.h"
#include "drive_core/sc750/sc750_compiler.h"
#include "drive_core/sc750/sc750_drive.h"

#include <cstdint>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace drive_core::sc750;
    const std::string_view source(reinterpret_cast<const char*>(data), size);
    const CompileResult result = compile(source, CompileOptions{size % 2 == 1});
    if (!result.ok()) return 0;
    if (readBin(result.bin).status != BinStatus::Ok) __builtin_trap();
    Sc750Drive drive;
    drive.setLineRateLimited(false);
    std::string why;
    if (!drive.loadProgram(result.bin, &why)) __builtin_trap();
    drive.receive("ENABLE\r1\r");
    drive.vm().start();
    for (int i = 0; i < 50; ++i) {
        drive.step(drive_core::Microseconds(1000));
        drive.takeTransmitted();
    }
    return 0;
}
