// ErrorStreamScanner: picks the errors a BDS5 reports by itself out of its byte stream (what the terminal
// shows): a line whose message starts with the bell, "<bell>ERR 83 LINE 2 '2'  BAD OR OUT OF RANGE" (L6036-6060).
// Listings such as ERR HIST carry no bell and are not taken for new errors. Pure; no I/O.
#pragma once

#include "serialport/bds5_protocol.h"

#include <QByteArray>
#include <QList>

namespace app {

class ErrorStreamScanner {
public:
    // Feeds received bytes; returns the error lines completed by them.
    QList<serialport::Bds5ErrorLine> feed(const QByteArray& bytes);
    // ERR HIST's answer (one "ERR n MESSAGE" a line, newest first), as error lines in the same order.
    static QList<serialport::Bds5ErrorLine> parseHistory(const QString& text);

private:
    QByteArray m_line;
};

} // namespace app
