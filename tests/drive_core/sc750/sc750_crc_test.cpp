// Known answers for the CRC a .BIN download carries (D<size>,<crc>, PROTOCOL.md; BIN_FORMAT.md §7). The SC750
// manual defines no checksum, so ServoDesk chose CRC-32 as in IEEE 802.3 — in the CRC catalogue
// (reveng.sourceforge.io) CRC-32/ISO-HDLC: width 32, poly 0x04C11DB7 (0xEDB88320 reflected), init 0xFFFFFFFF,
// refin and refout true, xorout 0xFFFFFFFF, check 0xCBF43926, residue 0xDEBB20E3. The values below are the
// catalogue's, or were computed with Python's zlib.crc32, which implements that same CRC independently:
//   python3 -c "import zlib; print(hex(zlib.crc32(bytes(range(256)))))"            -> 0x29058c73
//   python3 -c "import zlib; print(hex(zlib.crc32(b'\xff' * 4)))"                  -> 0xffffffff
//   python3 -c "import zlib; print(hex(zlib.crc32(b'123456789' + bytes.fromhex('2639f4cb'))))" -> 0x2144df1c
#include "drive_core/sc750/sc750_bin.h"
#include "drive_core/sc750/sc750_compiler.h"

#include <gtest/gtest.h>

#include <numeric>
#include <string_view>
#include <vector>

namespace {

using drive_core::sc750::crc32;

std::uint32_t crcOf(std::string_view text) {
    const std::vector<std::uint8_t> bytes(text.begin(), text.end());
    return crc32(bytes);
}

// A CRC-32/ISO-HDLC over data followed by its own CRC (little-endian, as the .BIN stores it) always gives
// this constant: the catalogue's residue 0xDEBB20E3 with xorout applied (0xDEBB20E3 ^ 0xFFFFFFFF).
constexpr std::uint32_t kCrcOfDataAndItsCrc = 0x2144DF1C;

} // namespace

TEST(Sc750Crc, CatalogueCheckValueOf123456789) {
    EXPECT_EQ(crcOf("123456789"), 0xCBF43926u);
}

TEST(Sc750Crc, IndependentVectorsFromPythonZlib) {
    std::vector<std::uint8_t> all(256);
    std::iota(all.begin(), all.end(), std::uint8_t{0});
    EXPECT_EQ(crc32(all), 0x29058C73u);
    EXPECT_EQ(crc32(std::vector<std::uint8_t>(4, 0xFF)), 0xFFFFFFFFu);
    EXPECT_EQ(crc32(std::vector<std::uint8_t>{}), 0x00000000u) << "init and xorout cancel on no data";
}

TEST(Sc750Crc, DataFollowedByItsCrcGivesTheResidue) {
    std::vector<std::uint8_t> bytes{'1', '2', '3', '4', '5', '6', '7', '8', '9', 0x26, 0x39, 0xF4, 0xCB};
    EXPECT_EQ(crc32(bytes), kCrcOfDataAndItsCrc);
}

// A compiled .BIN ends with the CRC of everything before it (BIN_FORMAT.md §7), so the whole file, as the
// host downloads it, has the residue too: the host's CRC and the drive's check agree on the standard CRC.
TEST(Sc750Crc, AWholeBinHasTheResidue) {
    const auto r = drive_core::sc750::compile("DIM a AS INTEGER\na = 5\nPRINT a\nEND\n");
    ASSERT_TRUE(r.ok());
    ASSERT_GT(r.bin.size(), 4u);
    EXPECT_EQ(crc32(r.bin), kCrcOfDataAndItsCrc);
}
