// RFC 2217: the Telnet framing and the server's answers.
#include "rfc2217.h"

#include <algorithm>

namespace serialport::rfc2217 {

std::string escape(std::string_view data) {
    std::string out;
    out.reserve(data.size());
    for (const char c : data) {
        out += c;
        if (static_cast<unsigned char>(c) == kIac) out += c;
    }
    return out;
}

std::string option(unsigned char verb, unsigned char opt) {
    return {char(kIac), char(verb), char(opt)};
}

std::string subnegotiation(unsigned char command, std::string_view value) {
    std::string out{char(kIac), char(kSb), char(kComPortOption), char(command)};
    out += escape(value);
    out += char(kIac);
    out += char(kSe);
    return out;
}

std::string u32(std::uint32_t value) {
    return {char(value >> 24), char(value >> 16), char(value >> 8), char(value)};
}

std::uint32_t u32(std::string_view bytes) {
    std::uint32_t value = 0;
    for (std::size_t i = 0; i < 4 && i < bytes.size(); ++i) value = value << 8 | static_cast<unsigned char>(bytes[i]);
    return value;
}

std::string Decoder::feed(std::string_view bytes, std::vector<Command>& commands) {
    std::string data;
    for (const char c : bytes) {
        const auto b = static_cast<unsigned char>(c);
        switch (m_state) {
        case State::Data:
            if (b == kIac) m_state = State::Iac;
            else data += c;
            break;
        case State::Iac:
            if (b == kIac) { // a doubled IAC is one 0xFF of data
                data += c;
                m_state = State::Data;
            } else if (b == kWill || b == kWont || b == kDo || b == kDont) {
                m_verb = b;
                m_state = State::Verb;
            } else if (b == kSb) {
                m_sub.clear();
                m_state = State::Sub;
            } else {
                m_state = State::Data; // NOP, GA, AYT ...: nothing for a serial line
            }
            break;
        case State::Verb:
            commands.push_back({m_verb, b, {}});
            m_state = State::Data;
            break;
        case State::Sub:
            if (b == kIac) m_state = State::SubIac;
            else m_sub += c;
            break;
        case State::SubIac:
            if (b == kIac) {
                m_sub += c;
                m_state = State::Sub;
            } else { // SE (or a broken stream): the subnegotiation ends
                if (!m_sub.empty())
                    commands.push_back({kSb, static_cast<unsigned char>(m_sub[0]), m_sub.substr(1)});
                m_state = State::Data;
            }
            break;
        }
    }
    return data;
}

std::string Server::feed(std::string_view bytes, std::string& reply) {
    std::vector<Decoder::Command> commands;
    std::string data = m_decoder.feed(bytes, commands);
    for (const auto& command : commands) answer(command, reply);
    return data;
}

void Server::answer(const Decoder::Command& c, std::string& reply) {
    const bool known = c.option == kBinary || c.option == kSuppressGoAhead || c.option == kComPortOption;
    const auto agreed = [](std::vector<unsigned char>& list, unsigned char opt) {
        if (std::find(list.begin(), list.end(), opt) != list.end()) return true; // already on: no answer (RFC 854)
        list.push_back(opt);
        return false;
    };
    if (c.verb == kDo) {
        if (!known) reply += option(kWont, c.option);
        else if (!agreed(m_will, c.option)) reply += option(kWill, c.option);
        return;
    }
    if (c.verb == kWill) {
        if (!known) reply += option(kDont, c.option);
        else if (!agreed(m_do, c.option)) reply += option(kDo, c.option);
        return;
    }
    if (c.verb == kDont || c.verb == kWont) {
        auto& list = c.verb == kDont ? m_will : m_do;
        list.erase(std::remove(list.begin(), list.end(), c.option), list.end());
        return;
    }
    if (c.verb != kSb || c.option != kComPortOption || c.value.empty()) return;
    // A com-port subnegotiation. The simulated line takes any setting (it has no baud rate mismatch to
    // garble); a value of 0 asks for the present one.
    const auto command = static_cast<unsigned char>(c.value[0]);
    std::string value = c.value.substr(1);
    switch (command) {
    case kSetBaudRate:
        if (u32(value) != 0) m_baudRate = u32(value);
        value = u32(m_baudRate);
        break;
    case kSetDataSize:
        if (!value.empty() && value[0] != 0) m_dataSize = static_cast<unsigned char>(value[0]);
        value = std::string(1, char(m_dataSize));
        break;
    case kSetParity:
        if (!value.empty() && value[0] != 0) m_parity = static_cast<unsigned char>(value[0]);
        value = std::string(1, char(m_parity));
        break;
    case kSetStopSize:
        if (!value.empty() && value[0] != 0) m_stopSize = static_cast<unsigned char>(value[0]);
        value = std::string(1, char(m_stopSize));
        break;
    default: break; // control, purge, masks: acknowledged as asked
    }
    if (command < kServerOffset) reply += subnegotiation(static_cast<unsigned char>(command + kServerOffset), value);
}

} // namespace serialport::rfc2217
