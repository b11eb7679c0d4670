// The BDS5's serial transmitter: what the processor writes leaves at the BAUD rate, ten bits a
// character (8N1, L10118-10147). Knows whether it is busy (the SERIAL switch, print idling).
#pragma once

#include "drive_core/drive.h"

#include <string>
#include <string_view>

namespace drive_core::bds5 {

class Bds5Uart {
public:
    // Valid rates (L7562, digest §2.1); anything else is not a BAUD the drive can use.
    static bool validBaud(int baud);

    void reset(int baud);
    // Unlimited, every byte leaves at once (an in-process link with no wire to pace it).
    void setUnlimited(bool unlimited) { m_unlimited = unlimited; }
    void write(std::string_view bytes);
    // Lets dt of line time pass: moves what the line carried in that time to the sent buffer.
    void advance(Microseconds dt);
    // Muted, bytes still take their time on the line but reach no one; applies to what is queued too.
    void setMuted(bool muted) { m_muted = muted; }
    // Muted from now on: what is written while muted takes its time on the line but reaches no one, what
    // was queued before keeps its fate (a multidrop axis falling asleep after its echo, or woken while
    // what it printed asleep still waits: that stays unsent, L5428).
    void setMutedFromNow(bool muted) { m_writeMuted = muted; }
    // Drops whatever has not been sent yet (Esc stopping a <BDS or DUMP listing).
    void discard();
    // Returns and clears what has left the drive.
    std::string takeSent();

    bool busy() const { return m_head < m_fifo.size(); }
    std::size_t backlog() const { return m_fifo.size() - m_head; } // written, not yet on the line
    bool atLineStart() const { return m_atLineStart; }
    int baud() const { return m_baud; }

private:
    std::string m_fifo; // written, from m_head on not yet sent
    // Per byte of m_fifo: '1' if written muted from now on (setMutedFromNow); empty while none queued is.
    std::string m_silent;
    std::size_t m_head = 0;
    std::string m_sent;
    double m_credit = 0; // characters the line may carry now
    int m_baud = 9600;
    bool m_atLineStart = true;
    bool m_muted = false;
    bool m_writeMuted = false;
    bool m_unlimited = false;
};

} // namespace drive_core::bds5
