// PlayTerminalFold: which lines of a PLAY listing are folded, and the line that stands for them.
#include "play_terminal_fold.h"

#include "drive/terminal_widget.h"

#include "serialport/bds5_record_play.h"

#include <QRegularExpression>

#include <utility>

namespace app {

PlayTerminalFold::PlayTerminalFold(serialport::Bds5RecordPlay& record, TerminalWidget& terminal, QString destination)
    : QObject(&record), m_terminal(&terminal), m_destination(std::move(destination)) {
    connect(&record, &serialport::Bds5RecordPlay::playSent, this, &PlayTerminalFold::begin);
    connect(&record, &serialport::Bds5RecordPlay::playEnded, this, &PlayTerminalFold::end);
}

PlayTerminalFold::~PlayTerminalFold() {
    end(false); // the transfer went away mid-PLAY (its connection was replaced)
}

bool PlayTerminalFold::isHeaderLine(const QString& line) {
    return line.trimmed().startsWith(QLatin1String("RECORD "), Qt::CaseInsensitive);
}

bool PlayTerminalFold::isSampleLine(const QString& line) {
    // One 12-column value per variable (drive_core/bds5/bds5_recorder.h); read as loosely as scope::parsePlay.
    static const QRegularExpression row(
        QStringLiteral("^\\s*[-+]?(\\d+\\.?\\d*|\\.\\d+)(\\s+[-+]?(\\d+\\.?\\d*|\\.\\d+))*\\s*$"));
    return row.match(line).hasMatch();
}

void PlayTerminalFold::begin(int reading) {
    if (!m_terminal) return;
    m_reading = reading;
    m_samples = 0;
    m_folded = 0;
    m_fold = m_terminal->beginFold([this](const QString& line) {
        const bool sample = isSampleLine(line);
        const bool fold = sample || isHeaderLine(line) || line.trimmed().isEmpty();
        m_samples += sample ? 1 : 0;
        m_folded += fold ? 1 : 0;
        return fold;
    });
}

void PlayTerminalFold::end(bool answered) {
    if (m_fold == 0 || !m_terminal) return;
    const int fold = std::exchange(m_fold, 0);
    const QString samples = m_samples == 1 ? tr("1 sample") : tr("%1 samples").arg(m_samples);
    const auto* record = qobject_cast<const serialport::Bds5RecordPlay*>(parent());
    QString summary;
    if (m_folded == 0)
        summary.clear(); // no listing (ERR 65 RECORD NOT READY): the answer showed as it came
    else if (!answered)
        summary = tr("PLAY: %1, then the answer was lost").arg(samples);
    else if (record && record->isCancelling())
        summary = tr("PLAY: stopped after %1").arg(samples);
    else if (m_reading > 1)
        summary = tr("PLAY (reading %1, to check the samples): %2").arg(m_reading).arg(samples);
    else
        summary = tr("PLAY: %1 \u2192 %2").arg(samples, m_destination);
    m_terminal->endFold(fold, summary);
}

} // namespace app
