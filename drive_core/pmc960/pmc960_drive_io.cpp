// The PMC-960's machine I/O: IN15'..IN00', OUT15'..OUT00', and the lines of the break matrix (ESTOP',
// FAULT', BREAK', DRVRDY', 5.3.5 L845-851) with START'+ADDR and EXEC' (5.9, L476).
#include "pmc960_drive.h"

namespace drive_core::pmc960 {

void Pmc960Drive::setInput(int number, bool on) {
    if (number < 1 || number > 16) return;
    const int bit = 1 << (number - 1);
    m_state.inputs = on ? (m_state.inputs | bit) : (m_state.inputs & ~bit);
}

bool Pmc960Drive::input(int number) const {
    return number >= 1 && number <= 16 && (m_state.inputs & (1 << (number - 1))) != 0;
}

bool Pmc960Drive::output(int number) const {
    return number >= 1 && number <= 16 && (m_state.reg.outputs & (1 << (number - 1))) != 0;
}

// The break matrix (5.3.5, L845-851).
void Pmc960Drive::setLine(Pmc960Line line, bool asserted) {
    Pmc960Lines& lines = m_state.lines;
    const bool running = m_interpreter.running();
    switch (line) {
    case Pmc960Line::Estop: {
        const bool edge = asserted && !lines.estop;
        lines.estop = asserted;
        if (!edge) return;
        if (m_state.motion.moving()) {
            emergencyStop();
            m_estopStopping = true; // IDLE once stopped
            raise(0xE0);
        } else {
            m_state.motion.setMode(0);
            if (running) {
                m_interpreter.abort();
                prompt();
            }
        }
        return;
    }
    case Pmc960Line::Fault: {
        const bool edge = asserted && !lines.fault;
        lines.fault = asserted;
        if (!edge) return;
        if (m_state.motion.moving()) emergencyStop();
        raise(0xE3);
        return;
    }
    case Pmc960Line::Break: {
        const bool edge = asserted && !lines.breakLine;
        lines.breakLine = asserted;
        if (edge && running) raise(0xC7);
        return;
    }
    case Pmc960Line::DriveReady: {
        const bool lost = !asserted && lines.driveReady;
        lines.driveReady = asserted;
        if (!lost) return;
        m_state.motion.setMode(0);
        if (running) {
            m_interpreter.abort();
            prompt();
        }
        return;
    }
    case Pmc960Line::Sensor: // acts on its assertion (L516: within 2 counts; 8 us minimum pulse)
        if (asserted && !lines.sensor) m_state.motion.sensor();
        lines.sensor = asserted;
        return;
    case Pmc960Line::Exec: // EXEC' high-to-low runs the TLV routine (L476)
        if (asserted && m_interpreter.idle() && m_mode == Mode::Command) {
            const char label = char(m_state.table.inUse("TLV"));
            if (label != 0 && !m_interpreter.start(label)) raise(0xC2);
        }
        return;
    case Pmc960Line::Start: // START' runs label 40H + ADDR (5.9, L932-976)
        if (asserted && m_interpreter.idle() && m_mode == Mode::Command && !m_interpreter.start(char(0x40 + m_address)))
            raise(0xC2);
        return;
    }
}

} // namespace drive_core::pmc960
