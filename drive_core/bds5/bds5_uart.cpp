// BDS5 transmitter timing.
#include "bds5_uart.h"

#include <algorithm>

namespace drive_core::bds5 {

bool Bds5Uart::validBaud(int baud) {
    for (const int valid : {300, 600, 1200, 2400, 4800, 9600, 19200})
        if (baud == valid) return true;
    return false;
}

void Bds5Uart::reset(int baud) {
    m_fifo.clear();
    m_silent.clear();
    m_head = 0;
    m_credit = 0;
    m_baud = baud;
    m_atLineStart = true;
}

void Bds5Uart::write(std::string_view bytes) {
    if (bytes.empty()) return;
    m_atLineStart = bytes.back() == '\n';
    if (m_unlimited && !busy()) {
        if (!m_muted && !m_writeMuted) m_sent.append(bytes);
        return;
    }
    if (m_writeMuted || !m_silent.empty()) {
        m_silent.resize(m_fifo.size(), '0'); // the first silent byte: those queued before it were not
        m_silent.append(bytes.size(), m_writeMuted ? '1' : '0');
    }
    m_fifo.append(bytes);
}

void Bds5Uart::advance(Microseconds dt) {
    m_credit += double(dt.count()) * m_baud / 10.0 / 1e6;
    const std::size_t n = std::min(m_fifo.size() - m_head, std::size_t(m_credit));
    if (!m_muted && m_silent.empty())
        m_sent.append(m_fifo, m_head, n);
    else if (!m_muted)
        for (std::size_t i = m_head; i < m_head + n; ++i)
            if (m_silent[i] == '0') m_sent.push_back(m_fifo[i]);
    m_head += n;
    m_credit -= double(n);
    if (m_head == m_fifo.size()) { // an idle line banks no credit for later
        m_fifo.clear();
        m_silent.clear();
        m_head = 0;
        m_credit = std::min(m_credit, 1.0);
    } else if (m_head > 4096) {
        m_fifo.erase(0, m_head);
        if (!m_silent.empty()) m_silent.erase(0, m_head);
        m_head = 0;
    }
}

void Bds5Uart::discard() {
    m_fifo.clear();
    m_silent.clear();
    m_head = 0;
    m_atLineStart = m_sent.empty() || m_sent.back() == '\n';
}

// A copy, so m_sent keeps its room: the drive is read after every step, and a buffer handed out each time
// grew again from nothing (issue 20).
std::string Bds5Uart::takeSent() {
    std::string sent = m_sent;
    m_sent.clear();
    return sent;
}

} // namespace drive_core::bds5
