// RFC 2217 (Telnet Com Port Control) over RFC 854 Telnet: only what a serial device server and its client
// need (issue 21) — BINARY (RFC 856), SUPPRESS-GO-AHEAD (RFC 858) and COM-PORT-OPTION (44) negotiated, the
// com-port subnegotiations (set baud rate, data size, parity, stop size, control, purge) and IAC doubled in
// the data. Every other option is refused. Plain C++: servodesk-sim's TCP server (POSIX) and the IDE's
// NetworkLink (Qt) share it.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace serialport::rfc2217 {

inline constexpr unsigned char kIac = 255, kDont = 254, kDo = 253, kWont = 252, kWill = 251, kSb = 250, kSe = 240;
inline constexpr unsigned char kBinary = 0, kSuppressGoAhead = 3, kComPortOption = 44;
// Client-to-server subnegotiation commands; the server answers each with the command + kServerOffset.
inline constexpr unsigned char kSetBaudRate = 1, kSetDataSize = 2, kSetParity = 3, kSetStopSize = 4;
inline constexpr unsigned char kServerOffset = 100;
inline constexpr unsigned char kParityNone = 1, kStopOne = 1;

// data with every IAC doubled, as Telnet carries it.
std::string escape(std::string_view data);
// IAC verb option.
std::string option(unsigned char verb, unsigned char option);
// IAC SB COM-PORT-OPTION command value IAC SE (value escaped).
std::string subnegotiation(unsigned char command, std::string_view value);
std::string u32(std::uint32_t value); // network order, as SET-BAUDRATE carries it
std::uint32_t u32(std::string_view bytes);

// Splits a Telnet stream into its data and its commands, across reads.
class Decoder {
public:
    struct Command {
        unsigned char verb = 0;   // kWill, kWont, kDo, kDont, or kSb for a subnegotiation
        unsigned char option = 0; // the Telnet option
        std::string value;        // kSb: the bytes after the option, IAC undoubled (COM-PORT-OPTION: the
                                  // command, then its value)
    };
    // The data in bytes; the commands completed in bytes are appended to commands.
    std::string feed(std::string_view bytes, std::vector<Command>& commands);

private:
    enum class State { Data, Iac, Verb, Sub, SubIac };
    State m_state = State::Data;
    unsigned char m_verb = 0;
    std::string m_sub;
};

// The server end (a serial device server): accepts BINARY, SGA and COM-PORT-OPTION in both directions,
// refuses the rest, and answers every com-port subnegotiation with its value (a query, value 0, with the
// present setting).
class Server {
public:
    // The data the client sent; what the server must send back is appended to reply.
    std::string feed(std::string_view bytes, std::string& reply);
    std::uint32_t baudRate() const { return m_baudRate; }

private:
    void answer(const Decoder::Command& command, std::string& reply);

    Decoder m_decoder;
    std::vector<unsigned char> m_will; // options we said WILL to
    std::vector<unsigned char> m_do;   // options we said DO to
    std::uint32_t m_baudRate = 9600;
    unsigned char m_dataSize = 8, m_parity = kParityNone, m_stopSize = kStopOne;
};

} // namespace serialport::rfc2217
