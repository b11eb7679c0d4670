// PMC-960 time-outs from the baud rate and the command time (see pmc960_timing.h).
#include "pmc960_timing.h"

#include <algorithm>

namespace serialport {

int Pmc960Timing::commandMs(const QByteArray& command) {
    int ms = kCommandMs;
    // D<time>: a dwell of up to 65,535 ms, 4 ms resolution (§7, L704-706).
    if (command.startsWith('D')) {
        qsizetype end = 1;
        while (end < command.size() && command.at(end) >= '0' && command.at(end) <= '9') ++end;
        ms += command.mid(1, end - 1).toInt() + 8;
    }
    // ',' and ';' wait for the motion to stop or reach its speed before the prompt (L2512, L2533).
    if (command.contains(',') || command.contains(';')) ms += kMotionWaitMs;
    return ms;
}

int Pmc960Timing::wireMs(int chars, int baudRate) {
    if (baudRate <= 0) return 0;
    return int((qint64(std::max(chars, 0)) * 10 * 1000 + baudRate - 1) / baudRate);
}

int Pmc960Timing::commandTimeoutMs(const QByteArray& command, int baudRate) {
    const int chars = int(command.size()) * 2 + kAnswerChars + 4; // out, echo back, answer, prompt
    return commandMs(command) + wireMs(chars, baudRate);
}

int Pmc960Timing::pollTimeoutMs(int baudRate) {
    return kCommandMs + wireMs(2 + kPollAnswerChars + 1, baudRate);
}

int Pmc960Timing::expectTimeoutMs(const QByteArray& bytes, const QByteArray& expect, int baudRate) {
    return kCommandMs + wireMs(int(bytes.size() + expect.size()) + 4, baudRate);
}

} // namespace serialport
