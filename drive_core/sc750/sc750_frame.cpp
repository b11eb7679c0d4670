// Protocol frames and the hex encoding of binary data inside them.
#include "sc750_frame.h"

namespace drive_core::sc750 {

namespace {
constexpr char kDigits[] = "0123456789ABCDEF";
int hexValue(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    return -1;
}
unsigned checksum(char letter, std::string_view payload) {
    unsigned sum = static_cast<unsigned char>(letter);
    for (char c : payload) sum += static_cast<unsigned char>(c);
    return sum & 0xff;
}
} // namespace

std::string encodeFrame(char letter, std::string_view payload) {
    const unsigned sum = checksum(letter, payload);
    std::string out;
    out.reserve(payload.size() + 5);
    out += kSoh;
    out += letter;
    out += payload;
    out += kDigits[sum >> 4];
    out += kDigits[sum & 0xf];
    out += kFrameEnd;
    return out;
}

std::optional<Frame> decodeFrame(std::string_view body) {
    if (body.size() < 3) return std::nullopt;
    const int hi = hexValue(body[body.size() - 2]);
    const int lo = hexValue(body[body.size() - 1]);
    if (hi < 0 || lo < 0) return std::nullopt;
    Frame f{body[0], std::string(body.substr(1, body.size() - 3))};
    if (checksum(f.letter, f.payload) != unsigned(hi * 16 + lo)) return std::nullopt;
    return f;
}

std::string toHex(std::string_view bytes) {
    std::string out;
    out.reserve(bytes.size() * 2);
    for (char c : bytes) {
        const auto b = static_cast<unsigned char>(c);
        out += kDigits[b >> 4];
        out += kDigits[b & 0xf];
    }
    return out;
}

std::optional<std::string> fromHex(std::string_view hex) {
    if (hex.size() % 2 != 0) return std::nullopt;
    std::string out;
    for (std::size_t i = 0; i < hex.size(); i += 2) {
        const int hi = hexValue(hex[i]), lo = hexValue(hex[i + 1]);
        if (hi < 0 || lo < 0) return std::nullopt;
        out += char(hi * 16 + lo);
    }
    return out;
}

} // namespace drive_core::sc750
