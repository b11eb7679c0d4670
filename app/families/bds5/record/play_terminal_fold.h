// PlayTerminalFold: keeps a recording's PLAY listings (250-300 sample lines per Scope record or tuning run)
// out of the terminal. Each listing shows as one line, "PLAY: 250 samples → Scope", between the PLAY echo
// and the prompt; an ERR line in the answer still shows. Only the terminal's view is folded: the session's
// bytes, the capture and the samples the scope reads stay whole. Lives as long as its transfer (a child of
// it). GUI thread only.
#pragma once

#include <QObject>
#include <QPointer>
#include <QString>

namespace serialport {
class Bds5RecordPlay;
}

namespace app {

class TerminalWidget;

class PlayTerminalFold final : public QObject {
    Q_OBJECT
public:
    // Folds every PLAY that record sends; destination names where the samples go ("Scope").
    PlayTerminalFold(serialport::Bds5RecordPlay& record, TerminalWidget& terminal, QString destination);
    ~PlayTerminalFold() override; // a fold still open (the transfer deleted mid-PLAY) ends, saying so

    // The lines of a PLAY listing: the "RECORD <n> <t> <vars>" header, a row of sample values, a blank line.
    static bool isHeaderLine(const QString& line);
    static bool isSampleLine(const QString& line);

private:
    void begin(int reading);
    void end(bool answered);

    QPointer<TerminalWidget> m_terminal;
    QString m_destination;
    int m_reading = 0;
    int m_samples = 0; // sample lines left out of the PLAY being read
    int m_folded = 0;  // every line left out: the samples, the header, blank lines
    int m_fold = 0;    // the terminal's number for the fold open, 0 when none is
};

} // namespace app
