// The ServoBASIC Plus VM's instruction set: one case per opcode (sc750_program.h). Run-time errors stop
// the program with FAULTCODE 244 (L2285); arithmetic follows QuickBASIC (overflow and division by zero).
#include "sc750_vm.h"

#include <bit>
#include <cmath>

namespace drive_core::sc750 {

namespace cat = catalog::sc750;

namespace {
constexpr std::size_t kMaxGosubDepth = 64;  // chosen
constexpr std::size_t kMaxStackDepth = 256; // chosen

template <typename T> bool compare(Relation r, const T& a, const T& b) {
    switch (r) {
    case Relation::Equal: return a == b;
    case Relation::NotEqual: return a != b;
    case Relation::Less: return a < b;
    case Relation::Greater: return a > b;
    case Relation::LessEqual: return a <= b;
    case Relation::GreaterEqual: return a >= b;
    }
    return false;
}
} // namespace

void Vm::execute(const Instruction& ins) {
    if (m_stack.size() > kMaxStackDepth) return runtimeError("STACK OVERFLOW");
    switch (ins.op) {
    case Op::Nop: break;
    case Op::PushI: m_stack.push_back(ins.arg); break;
    case Op::PushF: m_stack.push_back(std::bit_cast<float>(ins.arg)); break;
    case Op::PushS: m_stack.push_back(m_program->strings[std::size_t(ins.arg)]); break;
    case Op::LoadV: m_stack.push_back(m_vars[std::size_t(ins.arg)][0]); break;
    case Op::StoreV: m_vars[std::size_t(ins.arg)][0] = pop(); break;
    case Op::LoadA:
    case Op::StoreA: {
        Value value;
        if (ins.op == Op::StoreA) value = pop();
        const std::int32_t index = popInt();
        auto& array = m_vars[std::size_t(ins.arg)];
        if (index < 0 || std::size_t(index) >= array.size())
            return runtimeError("SUBSCRIPT OUT OF RANGE " + m_program->variables[std::size_t(ins.arg)].name + "(" +
                                std::to_string(index) + ")");
        if (ins.op == Op::LoadA)
            m_stack.push_back(array[std::size_t(index)]);
        else
            array[std::size_t(index)] = std::move(value);
        break;
    }
    case Op::LoadP: m_stack.push_back(m_host.readVariable(ins.arg)); break;
    case Op::StoreP: {
        const auto& info = cat::variables()[std::size_t(ins.arg)];
        const auto v = convert(pop(), info.type);
        if (!v) return runtimeError("OVERFLOW assigning " + std::string(info.name));
        const std::string refused = m_host.writeVariable(ins.arg, *v);
        if (!refused.empty()) return runtimeError(refused);
        updateAttention();
        break;
    }
    case Op::RemoteRead: {
        const std::int32_t axis = popInt();
        if (axis != m_host.axis()) return runtimeError("AXIS " + std::to_string(axis) + " NOT ON PACLAN");
        m_stack.push_back(m_host.readVariable(ins.arg));
        break;
    }
    case Op::RemoteStatus: m_stack.push_back(std::int32_t(popInt() == m_host.axis() ? 1 : 0)); break;
    case Op::LanRead:
    case Op::LanWrite: {
        Value value;
        if (ins.op == Op::LanWrite) value = pop();
        const std::int32_t axis = popInt();
        const std::int32_t n = popInt();
        if (axis != m_host.axis()) return runtimeError("AXIS " + std::to_string(axis) + " NOT ON PACLAN");
        if (n < 1 || n > 32) return runtimeError("LAN INDEX OUT OF RANGE");
        if (ins.op == Op::LanRead) {
            if (ins.arg == 0)
                m_stack.push_back(m_lanInt[n]);
            else
                m_stack.push_back(m_lanFloat[n]);
        } else if (ins.arg == 0) {
            m_lanInt[n] = toInteger(toDouble(value)).value_or(0);
        } else {
            m_lanFloat[n] = float(toDouble(value));
        }
        break;
    }
    case Op::IntToFloat: m_stack.push_back(float(popInt())); break;
    case Op::FloatToInt: {
        const auto i = toInteger(popFloat());
        if (!i) return runtimeError("OVERFLOW");
        m_stack.push_back(*i);
        break;
    }
    case Op::AddI:
    case Op::SubI:
    case Op::MulI:
    case Op::ModI: {
        const std::int64_t b = popInt();
        const std::int64_t a = popInt();
        if (ins.op == Op::ModI && b == 0) return runtimeError("DIVISION BY ZERO");
        pushInt(ins.op == Op::AddI ? a + b : ins.op == Op::SubI ? a - b : ins.op == Op::MulI ? a * b : a % b);
        break;
    }
    case Op::NegI: pushInt(-std::int64_t(popInt())); break;
    case Op::AddF:
    case Op::SubF:
    case Op::MulF:
    case Op::DivF:
    case Op::PowF: {
        const float b = popFloat();
        const float a = popFloat();
        if (ins.op == Op::DivF && b == 0) return runtimeError("DIVISION BY ZERO");
        const float r = ins.op == Op::AddF   ? a + b
                        : ins.op == Op::SubF ? a - b
                        : ins.op == Op::MulF ? a * b
                        : ins.op == Op::DivF ? a / b
                                             : std::pow(a, b);
        if (!std::isfinite(r)) return runtimeError("OVERFLOW");
        m_stack.push_back(r);
        break;
    }
    case Op::NegF: m_stack.push_back(-popFloat()); break;
    case Op::Concat: {
        std::string b = popString();
        std::string a = popString();
        a += b;
        if (a.size() > std::size_t(kMaxStringLength)) return runtimeError("STRING TOO LONG");
        m_stack.push_back(std::move(a));
        break;
    }
    case Op::CompareI: {
        const std::int32_t b = popInt(), a = popInt();
        m_stack.push_back(std::int32_t(compare(Relation(ins.arg), a, b) ? -1 : 0));
        break;
    }
    case Op::CompareF: {
        const float b = popFloat(), a = popFloat();
        m_stack.push_back(std::int32_t(compare(Relation(ins.arg), a, b) ? -1 : 0));
        break;
    }
    case Op::CompareS: {
        const std::string b = popString(), a = popString();
        m_stack.push_back(std::int32_t(compare(Relation(ins.arg), a, b) ? -1 : 0));
        break;
    }
    case Op::And: {
        const std::int32_t b = popInt(), a = popInt();
        m_stack.push_back(a & b);
        break;
    }
    case Op::Or: {
        const std::int32_t b = popInt(), a = popInt();
        m_stack.push_back(a | b);
        break;
    }
    case Op::Xor: {
        const std::int32_t b = popInt(), a = popInt();
        m_stack.push_back(a ^ b);
        break;
    }
    case Op::Not: m_stack.push_back(std::int32_t(~popInt())); break;
    case Op::CallFunction: {
        Value v = callFunction(ins.arg & 0xff, ins.arg >> 8);
        if (m_state == State::Error) return;
        m_stack.push_back(std::move(v));
        break;
    }
    case Op::Jump: m_pc = ins.arg; break;
    case Op::JumpIfZero:
        if (popInt() == 0) m_pc = ins.arg;
        break;
    case Op::Gosub:
        if (m_gosub.size() >= kMaxGosubDepth) return runtimeError("OUT OF STACK SPACE");
        m_gosub.push_back(m_pc);
        m_pc = ins.arg;
        break;
    case Op::Return:
        if (m_gosub.size() <= (m_interrupt ? m_interrupt->gosubDepth : 0)) return runtimeError("RETURN WITHOUT GOSUB");
        m_pc = m_gosub.back();
        m_gosub.pop_back();
        break;
    case Op::ForCheck: {
        const double step = toDouble(pop()), limit = toDouble(pop()), value = toDouble(pop());
        m_stack.push_back(std::int32_t((step >= 0 ? value <= limit : value >= limit) ? -1 : 0));
        break;
    }
    case Op::PrintValue: print(printText(pop())); break;
    case Op::PrintZone: print(std::string(std::size_t(14 - m_column % 14), ' ')); break;
    case Op::PrintNewline: print("\r\n"); break;
    case Op::InputPrompt:
        m_prompt = ins.arg < 0 ? "" : m_program->strings[std::size_t(ins.arg >> 1)];
        m_promptQuestion = (ins.arg & 1) != 0;
        printPrompt();
        break;
    case Op::Input:
        m_inputType = ValueType(ins.arg);
        m_wait = Wait::Input;
        break;
    case Op::Motion: m_host.motion(ins.arg); break;
    case Op::Pause:
        m_pauseUntil = m_tick + std::int64_t(std::llround(std::max(0.0, m_host.pauseTime_s()) / kTick_s));
        m_wait = Wait::Pause;
        break;
    case Op::When:
        m_whenActionValue = popFloat();
        m_whenValue = popFloat();
        m_whenSource = ins.arg & 0xff;
        m_whenRelation = ins.arg >> 8 & 0xf;
        m_whenAction = ins.arg >> 12 & 0xf;
        m_whenArg = ins.arg >> 16 & 0xff;
        m_wait = Wait::When;
        break;
    case Op::Tmrset: {
        const float delay = popFloat();
        const std::int32_t timer = popInt();
        if (timer < 1 || timer > 6) return runtimeError("TIMER NUMBER OUT OF RANGE");
        m_host.tmrset(timer, delay, ins.arg);
        break;
    }
    case Op::End:
        --m_pc; // stays on END: the host shows the line the program ended at
        m_state = State::Ended;
        break;
    case Op::Stop: m_state = State::Stopped; break;
    case Op::Cls: // "scrolls data off screen" (L2191): a screenful of new lines
        for (int i = 0; i < 24; ++i) print("\r\n");
        break;
    case Op::Beep: m_host.write("\x07"); break;
    case Op::Restart:
        m_stack.clear();
        m_gosub.clear();
        m_interrupt.reset();
        m_wait = Wait::None;
        m_pc = ins.arg;
        break;
    case Op::EndInterrupt:
        if (!m_interrupt) return runtimeError("END INTERRUPT outside an interrupt");
        m_pc = m_interrupt->pc;
        m_wait = m_interrupt->wait;
        m_pauseUntil = m_interrupt->pauseUntil;
        m_stack.resize(m_interrupt->stackSize);
        m_gosub.resize(m_interrupt->gosubDepth);
        m_interrupt.reset();
        break;
    case Op::LanInterrupt: {
        const std::int32_t axis = popInt();
        if (axis != m_host.axis()) return runtimeError("AXIS " + std::to_string(axis) + " NOT ON PACLAN");
        break;
    }
    case Op::Count: return runtimeError("BAD INSTRUCTION");
    }
}

} // namespace drive_core::sc750
