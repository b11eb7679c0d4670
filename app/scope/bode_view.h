// BodeView: Scope > Frequency Response — magnitude (dB) and phase (deg) against log frequency in two
// stacked axis rects, the -3 dB bandwidth marked and labelled, the phase margin (or why there is none)
// below. Estimated by scope::estimateFrequencyResponse from a capture holding VCMD and VFB. GUI thread only.
#pragma once

#include "scope/capture.h"
#include "scope/frequency_response.h"

#include <QDialog>

class QCPAxisRect;
class QCustomPlot;
class QLabel;

namespace app {

class BodeView final : public QDialog {
    Q_OBJECT
public:
    explicit BodeView(QWidget* parent = nullptr);

    // Estimates input -> output (VCMD -> VFB, the BDS5's) of the capture and plots it; false (with the reason
    // shown) if it has no such pair or they do not excite the loop.
    bool showCapture(const scope::Capture& capture, const QString& input = QStringLiteral("VCMD"),
                     const QString& output = QStringLiteral("VFB"));
    void showNothing(const QString& why);

    const scope::FrequencyResponse& response() const { return m_response; }
    QCustomPlot* plot() const { return m_plot; }
    QString summary() const;

private:
    void plotResponse(const QString& title, const QString& pair);

    scope::FrequencyResponse m_response;
    QCustomPlot* m_plot;
    QCPAxisRect* m_magnitude;
    QCPAxisRect* m_phase;
    QLabel* m_summary;
};

} // namespace app
