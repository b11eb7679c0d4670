// Frames of the Motion Dialogue <-> SC750 protocol (PROTOCOL.md): SOH, a command letter, a printable
// payload, two hex digits of checksum, CR. Shared by the simulated drive and the host session.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace drive_core::sc750 {

inline constexpr char kSoh = 0x01;
inline constexpr char kFrameEnd = '\r';
inline constexpr char kStopByte = 0x03; // Ctrl C (L1493, L2704)

struct Frame {
    char letter = 0;
    std::string payload;
};

// SOH letter payload checksum CR; the checksum is the sum of letter and payload bytes mod 256, "%02X".
std::string encodeFrame(char letter, std::string_view payload);
// The bytes between SOH and CR; nullopt if too short or the checksum does not match.
std::optional<Frame> decodeFrame(std::string_view body);

std::string toHex(std::string_view bytes);
std::optional<std::string> fromHex(std::string_view hex);

} // namespace drive_core::sc750
