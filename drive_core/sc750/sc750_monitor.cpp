// The SC750's protocol command processor (PROTOCOL.md describes every command and reply).
#include "sc750_monitor.h"

#include "sc750_bin.h"
#include "sc750_drive.h"
#include "sc750_frame.h"

#include <charconv>
#include <cstdio>

namespace drive_core::sc750 {

namespace cat = catalog::sc750;

namespace {
constexpr std::size_t kMaxFrame = 300;
constexpr std::size_t kMaxChunk = 64; // data bytes per W/t/u frame
constexpr std::size_t kMaxImage = 200000;

std::optional<long> number(std::string_view text) {
    long v = 0;
    const auto r = std::from_chars(text.data(), text.data() + text.size(), v);
    if (r.ec != std::errc() || r.ptr != text.data() + text.size()) return std::nullopt;
    return v;
}

char stateLetter(Vm::State s) {
    switch (s) {
    case Vm::State::NoProgram: return 'N';
    case Vm::State::Loaded: return 'L';
    case Vm::State::Running: return 'R';
    case Vm::State::Stopped: return 'S';
    case Vm::State::AtBreakpoint: return 'B';
    case Vm::State::Ended: return 'E';
    case Vm::State::Error: return 'F';
    }
    return 'N';
}

std::string valueText(const Value& v) {
    if (const auto* s = std::get_if<std::string>(&v)) return "\"" + *s + "\"";
    return formatNumber(v);
}
} // namespace

void Sc750Monitor::reset() {
    m_inFrame = false;
    m_frame.clear();
    m_downloading = false;
    m_download.clear();
}

void Sc750Monitor::feed(char c) {
    if (c == kStopByte && !m_inFrame) {
        stopProgram();
        return;
    }
    if (c == kSoh) { // a new frame starts; an unfinished one is dropped
        m_inFrame = true;
        m_frame.clear();
        return;
    }
    if (!m_inFrame) return;
    if (c == kFrameEnd) {
        m_inFrame = false;
        const auto frame = decodeFrame(m_frame);
        if (!frame) return error(1, "BAD FRAME");
        execute(frame->letter, frame->payload);
        return;
    }
    if (m_frame.size() >= kMaxFrame) {
        m_inFrame = false;
        return error(1, "FRAME TOO LONG");
    }
    m_frame += c;
}

void Sc750Monitor::reply(char letter, const std::string& payload) {
    m_drive.send(encodeFrame(letter, payload));
}

void Sc750Monitor::error(int code, const std::string& text) {
    char head[8];
    std::snprintf(head, sizeof head, "%02d ", code);
    reply('!', head + text);
}

std::string Sc750Monitor::statusText() const {
    const Vm& vm = m_drive.vm();
    return std::string(1, stateLetter(vm.state())) + "," + std::to_string(vm.currentLine()) + "," +
           std::to_string(m_drive.faultCode()) + "," + (m_drive.decimalPoint() ? "1" : "0") + "," +
           (m_drive.configured() ? "1" : "0");
}

void Sc750Monitor::stopProgram() {
    Vm& vm = m_drive.vm();
    vm.stop();
    m_drive.realTimeCall(5); // a single Ctrl C also stops motion during development (L1493)
    reply('H', std::to_string(vm.currentLine()));
}

void Sc750Monitor::programHalted(Vm::State state) {
    const Vm& vm = m_drive.vm();
    const std::string line = std::to_string(vm.currentLine());
    if (state == Vm::State::AtBreakpoint)
        reply('b', line);
    else if (state == Vm::State::Ended)
        reply('e', line);
    else if (state == Vm::State::Stopped)
        reply('h', line);
    else if (state == Vm::State::Error)
        reply('f', std::to_string(m_drive.faultCode()) + "," + line + "," + vm.errorText());
}

void Sc750Monitor::execute(char letter, const std::string& payload) {
    Vm& vm = m_drive.vm();
    const bool running = vm.running();
    switch (letter) {
    case '?': return reply('S', statusText());
    case 'V':
        return reply('V', formatNumber(*m_drive.readNamed("MODEL")) + "," + formatNumber(*m_drive.readNamed("FWV")) +
                              "," + std::to_string(kBinVersion) + "," + std::to_string(m_drive.axis()));
    case 'R':
        if (!vm.program()) return error(2, "NO PROGRAM");
        if (running) return error(3, "PROGRAM RUNNING");
        m_drive.clearRunTimeFault();
        vm.start();
        return reply('R', "");
    case 'C':
        if (vm.state() != Vm::State::Stopped && vm.state() != Vm::State::AtBreakpoint) return error(9, "NOT STOPPED");
        vm.resume();
        return reply('C', "");
    case 'H': return stopProgram();
    case 'X':
        vm.reset();
        m_drive.clearRunTimeFault();
        return reply('X', "");
    case 'B': return breakpoint(payload);
    case 'G': return readVariable(payload);
    case 'P':
        if (running) return error(3, "PROGRAM RUNNING");
        return writeVariable(payload);
    case 'F': {
        static const char* kCalls[] = {"GO.VEL", "GO.INCR", "GO.ABS", "GO.HOME", "ABORT.MOTION", "UPD.MOVE", "PAUSE"};
        if (running) return error(3, "PROGRAM RUNNING");
        for (int k = 0; k < 7; ++k)
            if (payload == kCalls[k]) {
                if (k < 6) m_drive.realTimeCall(k + 1);
                return reply('F', payload);
            }
        return error(10, "UNKNOWN FUNCTION");
    }
    case 'K':
        if (payload != "0" && payload != "1") return error(11, "BAD ARGUMENT");
        m_drive.setConfigured(payload == "1");
        return reply('K', payload);
    case 'D':
    case 'W':
    case 'Z':
    case 'T':
    case 't':
    case 'Q':
    case 'u': return transfer(letter, payload);
    default: return error(1, "UNKNOWN COMMAND");
    }
}

void Sc750Monitor::breakpoint(const std::string& payload) {
    Vm& vm = m_drive.vm();
    if (payload == "*") {
        vm.clearBreakpoints();
        return reply('B', "");
    }
    if (payload != "?") {
        if (payload.size() < 2 || (payload[0] != '+' && payload[0] != '-')) return error(11, "BAD ARGUMENT");
        const auto line = number(std::string_view(payload).substr(1));
        if (!line) return error(11, "BAD ARGUMENT");
        if (payload[0] == '+') {
            if (!vm.program() || vm.program()->addressOfLine(int(*line)) < 0) return error(7, "NO STATEMENT ON LINE");
            if (!vm.addBreakpoint(int(*line))) return error(8, "TOO MANY BREAKPOINTS");
        } else {
            vm.removeBreakpoint(int(*line));
        }
    }
    std::string list;
    for (int line : vm.breakpointLines()) list += (list.empty() ? "" : ",") + std::to_string(line);
    reply('B', list);
}

// NAME, NAME(i) (user arrays): user variables first, then the predefined ones.
void Sc750Monitor::readVariable(const std::string& name, char letter) {
    std::string base = name;
    int element = 0;
    const auto paren = name.find('(');
    if (paren != std::string::npos && name.back() == ')') {
        const auto i = number(std::string_view(name).substr(paren + 1, name.size() - paren - 2));
        if (!i) return error(11, "BAD ARGUMENT");
        element = int(*i);
        base = name.substr(0, paren);
    }
    for (char& c : base) c = char(std::toupper(static_cast<unsigned char>(c)));
    const Vm& vm = m_drive.vm();
    const int user = vm.findVariable(base);
    if (user >= 0) {
        const auto v = vm.variable(user, element);
        if (!v) return error(12, "SUBSCRIPT OUT OF RANGE");
        return reply(letter, name + "=" + valueText(*v));
    }
    const auto v = m_drive.readNamed(base);
    if (!v) return error(13, "UNKNOWN VARIABLE");
    reply(letter, name + "=" + valueText(*v));
}

void Sc750Monitor::writeVariable(const std::string& assignment) {
    const auto eq = assignment.find('=');
    if (eq == std::string::npos) return error(11, "BAD ARGUMENT");
    std::string name = assignment.substr(0, eq);
    std::string text = assignment.substr(eq + 1);
    std::string base = name;
    int element = 0;
    const auto paren = name.find('(');
    if (paren != std::string::npos && name.back() == ')') {
        const auto i = number(std::string_view(name).substr(paren + 1, name.size() - paren - 2));
        if (!i) return error(11, "BAD ARGUMENT");
        element = int(*i);
        base = name.substr(0, paren);
    }
    for (char& c : base) c = char(std::toupper(static_cast<unsigned char>(c)));
    Vm& vm = m_drive.vm();
    const int user = vm.findVariable(base);
    if (user >= 0) {
        const ValueType type = vm.program()->variables[std::size_t(user)].type;
        if (type == ValueType::String && text.size() >= 2 && text.front() == '"' && text.back() == '"')
            text = text.substr(1, text.size() - 2);
        const auto v = parseValue(text, type);
        if (!v || !vm.setVariable(user, element, *v)) return error(14, "BAD VALUE");
    } else {
        const std::string refused = m_drive.writeNamed(base, text);
        if (!refused.empty()) return error(refused == "UNKNOWN VARIABLE" ? 13 : 14, refused);
    }
    readVariable(name, 'P');
}

// D/W/Z: .BIN download; T/t/Q: source download; u: source upload (PROTOCOL.md §4).
void Sc750Monitor::transfer(char letter, const std::string& payload) {
    Vm& vm = m_drive.vm();
    if (letter == 'D' || letter == 'T') {
        if (vm.running()) return error(3, "PROGRAM RUNNING");
        const auto comma = payload.find(',');
        const auto size = number(std::string_view(payload).substr(0, comma));
        if (comma == std::string::npos || !size || *size < 0 || std::size_t(*size) > kMaxImage)
            return error(11, "BAD ARGUMENT");
        m_expected = std::size_t(*size);
        m_expectedCrc = std::uint32_t(std::strtoul(payload.c_str() + comma + 1, nullptr, 16));
        m_download.clear();
        m_downloading = true;
        m_source = letter == 'T';
        return reply(letter, "0");
    }
    if (letter == 'W' || letter == 't') {
        if (!m_downloading || m_source != (letter == 't')) return error(4, "NO TRANSFER");
        const auto comma = payload.find(',');
        const auto offset = number(std::string_view(payload).substr(0, comma));
        if (comma == std::string::npos || !offset) return error(11, "BAD ARGUMENT");
        if (std::size_t(*offset) != m_download.size()) return error(4, "OFFSET " + std::to_string(m_download.size()));
        const auto data = fromHex(std::string_view(payload).substr(comma + 1));
        if (!data || data->size() > kMaxChunk || m_download.size() + data->size() > m_expected)
            return error(11, "BAD ARGUMENT");
        m_download += *data;
        return reply(letter, std::to_string(m_download.size()));
    }
    if (letter == 'Z' || letter == 'Q') {
        if (!m_downloading || m_source != (letter == 'Q')) return error(4, "NO TRANSFER");
        m_downloading = false;
        std::vector<std::uint8_t> bytes(m_download.begin(), m_download.end());
        if (bytes.size() != m_expected || crc32(bytes) != m_expectedCrc) return error(5, "CHECKSUM");
        if (letter == 'Q') {
            m_drive.sourceStore() = std::move(bytes);
            return reply('Q', std::to_string(m_expected));
        }
        std::string why;
        if (!m_drive.loadProgram(std::move(bytes), &why)) return error(why.rfind("incompatible", 0) == 0 ? 6 : 5, why);
        const Program& p = *vm.program();
        return reply('Z', std::to_string(p.codeBytes()) + "," + std::to_string(p.dataBytes()));
    }
    // u<offset>: up to 64 bytes of the stored source from offset; an empty chunk ends the upload
    const auto offset = number(payload);
    const auto& source = m_drive.sourceStore();
    if (!offset || *offset < 0 || std::size_t(*offset) > source.size()) return error(11, "BAD ARGUMENT");
    const std::size_t n = std::min(kMaxChunk, source.size() - std::size_t(*offset));
    const std::string chunk(source.begin() + *offset, source.begin() + *offset + long(n));
    reply('u', payload + "," + toHex(chunk));
}

} // namespace drive_core::sc750
