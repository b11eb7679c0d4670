// The .BIN file: a compiled Program serialised for download (format in BIN_FORMAT.md), and its reader,
// which refuses a damaged image (CRC-32) or one from an incompatible compiler (version).
#pragma once

#include "sc750_program.h"

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace drive_core::sc750 {

std::vector<std::uint8_t> writeBin(const Program& program);

enum class BinStatus { Ok, TooShort, BadMagic, BadVersion, BadChecksum, Malformed };

struct BinReadResult {
    BinStatus status = BinStatus::Malformed;
    std::optional<Program> program;
    std::string message;
};

BinReadResult readBin(std::span<const std::uint8_t> bytes);

// CRC-32 (IEEE 802.3: reflected, polynomial 0xEDB88320, initial and final value 0xFFFFFFFF).
std::uint32_t crc32(std::span<const std::uint8_t> bytes);

} // namespace drive_core::sc750
