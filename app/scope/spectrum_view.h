// SpectrumView: Scope > Spectrum — the magnitude (dB) of one channel of the shown capture against a log or
// linear frequency axis, under a chosen window, with the peak marked and read out and the frequency resolution
// said in words. The capture shown before it stays as an overlay (as the time plot keeps the previous run), so
// a change between runs — a low-pass filter set against a resonance — shows as the peak dropping. The numbers
// are scope::computeSpectrum's; this view only chooses, plots and words them. GUI thread only.
#pragma once

#include "scope/capture.h"
#include "scope/spectrum.h"

#include <QDialog>

#include <functional>
#include <optional>

class QCPGraph;
class QCPItemText;
class QCPItemTracer;
class QCheckBox;
class QComboBox;
class QSpinBox;
class QCustomPlot;
class QLabel;

namespace app {

class SpectrumView final : public QDialog {
    Q_OBJECT
public:
    explicit SpectrumView(QWidget* parent = nullptr);

    // A new capture to analyse; the one shown so far becomes the overlay. The channel stays if the new capture
    // has one of that name, else the feedback (VFB, PFB) or the first. Replots only while visible.
    void showCapture(const scope::Capture& capture);
    // The channels offered besides the captured ones (the Scope's math channels): applied to this capture and
    // to the previous one whenever either is analysed; refresh() after the math channels change.
    void setDerivedChannels(std::function<scope::Capture(const scope::Capture&)> derive);
    void refresh();
    void setChannel(const QString& name);
    void setWindow(scope::SpectrumWindow window);
    void setLogFrequency(bool log);
    // Where the peak is searched from (Hz). 0, "auto" (the default): scope::findProminentPeak, the peak that
    // stands out of its surroundings, so a resonance is found without knowing the loop's bandwidth.
    void setPeakFrom(int from_hz);

    const scope::Spectrum& spectrum() const { return m_spectrum; }
    // The peak marked and read out (by the "Peak above" field, as setPeakFrom says); unset when there is none.
    const std::optional<scope::SpectrumPeak>& peak() const { return m_peakShown; }
    // The previous capture's spectrum of the same channel under the same window; unset when there is none.
    const std::optional<scope::Spectrum>& overlay() const { return m_overlay; }
    // What the line under the plot says: the peak, the resolution, the overlay's peak and this capture's level
    // at that frequency (how far a filter pulled it down).
    QString readout() const;
    QComboBox* channelBox() const { return m_channel; }
    QComboBox* windowBox() const { return m_window; }
    QCheckBox* logFrequencyBox() const { return m_logFrequency; }
    QSpinBox* peakFromBox() const { return m_peakFrom; }
    QCustomPlot* plot() const { return m_plot; }

protected:
    void showEvent(QShowEvent* event) override;

private:
    void fillChannels();
    void recompute();
    void replot();
    void plotSpectrum(QCPGraph* graph, const scope::Spectrum& s) const;
    void markPeaks();
    QString describe() const;

    std::optional<scope::Capture> m_raw, m_previousRaw; // as captured
    std::optional<scope::Capture> m_capture;             // with the derived channels: what is analysed
    std::optional<scope::Capture> m_previous;
    std::function<scope::Capture(const scope::Capture&)> m_derive;
    scope::Spectrum m_spectrum;
    std::optional<scope::Spectrum> m_overlay;
    std::optional<scope::SpectrumPeak> m_peakShown;
    std::optional<scope::SpectrumPeak> m_overlayPeak;
    QComboBox* m_channel;
    QComboBox* m_window;
    QCheckBox* m_logFrequency;
    QSpinBox* m_peakFrom;
    QCustomPlot* m_plot;
    QCPGraph* m_current;
    QCPGraph* m_previousGraph;
    QCPItemTracer* m_peak;
    QCPItemText* m_peakLabel;
    QCPItemTracer* m_previousPeak;
    QCPItemText* m_previousPeakLabel;
    QLabel* m_readout;
};

} // namespace app
