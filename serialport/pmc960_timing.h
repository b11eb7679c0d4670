// Pmc960Timing: how long the PMC-960 may take to answer — the request and its answer crossing the wire at
// the link's baud rate (10 bits a character) plus the controller's own command time (digest §2.4, §4.3:
// most commands < 1 ms, "many ms" while it computes motion; a dwell or a motion wait as long as it lasts).
// The time-outs of Pmc960Session and Pmc960Download come from here, as the BDS5's and SC750's do from theirs.
#pragma once

#include <QByteArray>

namespace serialport {

struct Pmc960Timing {
    // Chosen margins: a quarter second over the controller's "many ms" covers a USB adapter's latency and a
    // busy host; a motion wait (',' ';' in the command) is allowed this long for the move to end.
    static constexpr int kCommandMs = 250;
    static constexpr int kMotionWaitMs = 30000;
    static constexpr int kAnswerChars = 64; // the longest display answer of one command (a status line)
    static constexpr int kPollAnswerChars = 16;

    // The controller's command time for command (as written, e.g. "A3500\r", "D300\r", "I+,"), in ms.
    static int commandMs(const QByteArray& command);
    // Wire time in ms of chars characters at baudRate (0: not limited, no wire time).
    static int wireMs(int chars, int baudRate);
    // A command answered by its echo, up to kAnswerChars and a prompt (CR LF ID }).
    static int commandTimeoutMs(const QByteArray& command, int baudRate);
    // An <attn> poll: two characters out, up to kPollAnswerChars and CR back.
    static int pollTimeoutMs(int baudRate);
    // Bytes whose answer is expect (a line's echo in the P editor).
    static int expectTimeoutMs(const QByteArray& bytes, const QByteArray& expect, int baudRate);
};

} // namespace serialport
