// .BIN writer and reader (BIN_FORMAT.md), and the Program helpers that need no VM.
#include "sc750_bin.h"

#include <algorithm>
#include <bit>
#include <cstring>

namespace drive_core::sc750 {

namespace {

constexpr char kMagic[8] = {'S', 'C', '7', '5', '0', 'B', 'I', 'N'};

struct Writer {
    std::vector<std::uint8_t> out;
    void u8(unsigned v) { out.push_back(std::uint8_t(v)); }
    void u16(unsigned v) {
        u8(v & 0xff);
        u8(v >> 8 & 0xff);
    }
    void u32(std::uint32_t v) {
        u16(v & 0xffff);
        u16(v >> 16);
    }
    void bytes(std::string_view s) { out.insert(out.end(), s.begin(), s.end()); }
};

struct Reader {
    std::span<const std::uint8_t> in;
    std::size_t pos = 0;
    bool ok = true;
    unsigned u8() {
        if (pos >= in.size()) {
            ok = false;
            return 0;
        }
        return in[pos++];
    }
    unsigned u16() {
        const unsigned lo = u8();
        return lo | u8() << 8;
    }
    std::uint32_t u32() {
        const std::uint32_t lo = u16();
        return lo | std::uint32_t(u16()) << 16;
    }
    std::string text(std::size_t n) {
        if (pos + n > in.size()) {
            ok = false;
            return {};
        }
        std::string s(reinterpret_cast<const char*>(in.data() + pos), n);
        pos += n;
        return s;
    }
};

// Every operand names something that exists, so a damaged image cannot make the VM index out of range.
bool operandsValid(const Program& p) {
    const auto code = std::int32_t(p.code.size());
    const auto vars = std::int32_t(p.variables.size());
    const auto strings = std::int32_t(p.strings.size());
    const auto catalogSize = std::int32_t(catalog::sc750::variables().size());
    const auto functions = catalog::sc750::functions();
    auto address = [code](std::int32_t a) { return a >= 0 && a <= code; };
    for (std::int32_t a : p.interrupts)
        if (a != -1 && !address(a)) return false;
    for (const LineEntry& l : p.lines)
        if (!address(l.address)) return false;
    for (const ProgramVariable& v : p.variables)
        if (v.count < 1 || v.count > 4096) return false;
    for (const Instruction& i : p.code) {
        const std::int32_t a = i.arg;
        switch (i.op) {
        case Op::PushS:
            if (a < 0 || a >= strings) return false;
            break;
        case Op::LoadV:
        case Op::StoreV:
        case Op::LoadA:
        case Op::StoreA:
            if (a < 0 || a >= vars) return false;
            break;
        case Op::LoadP:
        case Op::StoreP:
        case Op::RemoteRead:
            if (a < 0 || a >= catalogSize) return false;
            break;
        case Op::Jump:
        case Op::JumpIfZero:
        case Op::Gosub:
        case Op::Restart:
            if (!address(a)) return false;
            break;
        case Op::CallFunction: {
            const std::size_t f = std::size_t(a & 0xff);
            const int argc = a >> 8;
            if (f >= functions.size() || argc < functions[f].minArgs || argc > functions[f].maxArgs) return false;
            break;
        }
        case Op::InputPrompt:
            if (a >= 0 && (a >> 1) >= strings) return false;
            break;
        case Op::Input:
            if (a < 0 || a > 2) return false;
            break;
        case Op::CompareI:
        case Op::CompareF:
        case Op::CompareS:
            if (a < 0 || a > 5) return false;
            break;
        default: break;
        }
    }
    return true;
}

} // namespace

std::uint32_t crc32(std::span<const std::uint8_t> bytes) {
    std::uint32_t crc = 0xFFFFFFFFu;
    for (std::uint8_t b : bytes) {
        crc ^= b;
        for (int k = 0; k < 8; ++k) crc = crc & 1 ? (crc >> 1) ^ 0xEDB88320u : crc >> 1;
    }
    return crc ^ 0xFFFFFFFFu;
}

std::vector<std::uint8_t> writeBin(const Program& p) {
    Writer w;
    w.bytes(std::string_view(kMagic, 8));
    w.u16(kBinVersion);
    w.u16(p.turbo ? 1 : 0);
    w.u32(std::uint32_t(p.code.size()));
    w.u32(std::uint32_t(p.dataBytes()));
    w.u16(unsigned(p.params.size()));
    w.u16(unsigned(p.variables.size()));
    w.u16(unsigned(p.strings.size()));
    w.u16(unsigned(p.interrupts.size()));
    w.u32(std::uint32_t(p.lines.size()));
    for (const ProgramParam& param : p.params) {
        w.u16(unsigned(param.variable));
        w.u32(std::bit_cast<std::uint32_t>(float(param.value)));
    }
    for (const ProgramVariable& v : p.variables) {
        w.u8(unsigned(v.type));
        w.u8((v.array ? 1u : 0u) | (v.nonVolatile ? 2u : 0u));
        w.u16(unsigned(v.count));
        w.u8(unsigned(v.name.size()));
        w.bytes(v.name);
    }
    for (const std::string& s : p.strings) {
        w.u8(unsigned(s.size()));
        w.bytes(s);
    }
    for (std::int32_t a : p.interrupts) w.u32(std::uint32_t(a));
    for (const LineEntry& l : p.lines) {
        w.u32(std::uint32_t(l.address));
        w.u32(std::uint32_t(l.line));
    }
    for (const Instruction& i : p.code) {
        w.u8(unsigned(i.op));
        w.u32(std::uint32_t(i.arg));
    }
    w.u32(crc32(w.out));
    return std::move(w.out);
}

BinReadResult readBin(std::span<const std::uint8_t> bytes) {
    BinReadResult result;
    auto failWith = [&result](BinStatus status, std::string message) {
        result.status = status;
        result.message = std::move(message);
        return result;
    };
    if (bytes.size() < 36) return failWith(BinStatus::TooShort, "file too short for a .BIN");
    if (std::memcmp(bytes.data(), kMagic, 8) != 0) return failWith(BinStatus::BadMagic, "not an SC750 .BIN file");
    Reader r{bytes};
    r.pos = 8;
    const unsigned version = r.u16();
    if (version != kBinVersion)
        return failWith(BinStatus::BadVersion, "incompatible .BIN version " + std::to_string(version));
    const std::size_t body = bytes.size() - 4;
    Reader tail{bytes};
    tail.pos = body;
    if (crc32(bytes.first(body)) != tail.u32()) return failWith(BinStatus::BadChecksum, "checksum mismatch");
    Program p;
    p.turbo = (r.u16() & 1) != 0;
    const std::uint32_t codeCount = r.u32();
    r.u32(); // data bytes: recomputed from the layout
    const unsigned params = r.u16(), vars = r.u16(), strings = r.u16(), vectors = r.u16();
    const std::uint32_t lines = r.u32();
    if (codeCount > 1000000 || lines > 1000000) return failWith(BinStatus::Malformed, "implausible sizes");
    const auto catalogSize = catalog::sc750::variables().size();
    for (unsigned i = 0; i < params && r.ok; ++i) {
        ProgramParam param;
        param.variable = int(r.u16());
        param.value = std::bit_cast<float>(r.u32());
        if (std::size_t(param.variable) >= catalogSize) return failWith(BinStatus::Malformed, "bad parameter");
        p.params.push_back(param);
    }
    for (unsigned i = 0; i < vars && r.ok; ++i) {
        ProgramVariable v;
        const unsigned type = r.u8();
        const unsigned flags = r.u8();
        v.count = int(r.u16());
        v.name = r.text(r.u8());
        if (type > 2 || v.count < 1) return failWith(BinStatus::Malformed, "bad variable");
        v.type = ValueType(type);
        v.array = (flags & 1) != 0;
        v.nonVolatile = (flags & 2) != 0;
        p.variables.push_back(std::move(v));
    }
    for (unsigned i = 0; i < strings && r.ok; ++i) p.strings.push_back(r.text(r.u8()));
    for (unsigned i = 0; i < vectors && r.ok; ++i) p.interrupts.push_back(std::int32_t(r.u32()));
    for (std::uint32_t i = 0; i < lines && r.ok; ++i) {
        LineEntry l;
        l.address = std::int32_t(r.u32());
        l.line = std::int32_t(r.u32());
        p.lines.push_back(l);
    }
    for (std::uint32_t i = 0; i < codeCount && r.ok; ++i) {
        Instruction ins;
        const unsigned op = r.u8();
        ins.arg = std::int32_t(r.u32());
        if (op >= unsigned(Op::Count)) return failWith(BinStatus::Malformed, "bad opcode");
        ins.op = Op(op);
        p.code.push_back(ins);
    }
    if (!r.ok || r.pos != body) return failWith(BinStatus::Malformed, "sections do not match the header");
    if (p.interrupts.size() != catalog::sc750::interruptSources().size())
        return failWith(BinStatus::Malformed, "wrong interrupt vector count");
    if (!operandsValid(p)) return failWith(BinStatus::Malformed, "instruction operand out of range");
    result.status = BinStatus::Ok;
    result.program = std::move(p);
    return result;
}

int Program::dataBytes() const {
    int bytes = 0;
    for (const ProgramVariable& v : variables) bytes += v.count * (v.type == ValueType::String ? kStringBytes : 4);
    for (const std::string& s : strings) bytes += int(s.size()) + 1;
    return bytes;
}

int Program::lineAt(std::int32_t address) const {
    auto it = std::upper_bound(lines.begin(), lines.end(), address,
                               [](std::int32_t a, const LineEntry& l) { return a < l.address; });
    return it == lines.begin() ? 0 : std::prev(it)->line;
}

std::int32_t Program::addressOfLine(int line) const {
    std::int32_t best = -1;
    for (const LineEntry& l : lines)
        if (l.line == line && (best < 0 || l.address < best)) best = l.address;
    return best;
}

} // namespace drive_core::sc750
