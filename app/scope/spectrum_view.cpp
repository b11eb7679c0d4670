// SpectrumView: the choices row, the plot (this capture over the previous one, the peak marked) and the readout.
#include "spectrum_view.h"

#include <qcustomplot.h>

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QShortcut>
#include <QSpinBox>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <tuple>

namespace app {

namespace {
const QColor kCurrent(0x1f, 0x77, 0xb4);
const QColor kPrevious(0x9e, 0x9e, 0x9e);
const QColor kPeak(0xd6, 0x27, 0x28);
constexpr double kShownRange_db = 100; // below the top, bins are quantisation noise: the axis stops there

QString hz(double f) {
    return QStringLiteral("%1 Hz").arg(f, 0, 'f', f < 10 ? 2 : 1);
}

QString db(double value) {
    return QStringLiteral("%1 dB").arg(value, 0, 'f', 1);
}

// The bin nearest f (the overlay's own bins may differ from this capture's when the records differ).
double magnitudeAt(const scope::Spectrum& s, double f) {
    if (s.magnitude_db.empty() || s.resolution_hz <= 0) return 0;
    const auto bin = std::size_t(std::clamp(std::lround(f / s.resolution_hz), 0L, long(s.magnitude_db.size()) - 1));
    return s.magnitude_db[bin];
}
} // namespace

SpectrumView::SpectrumView(QWidget* parent)
    : QDialog(parent), m_channel(new QComboBox(this)), m_window(new QComboBox(this)),
      m_logFrequency(new QCheckBox(tr("Log frequency"), this)), m_peakFrom(new QSpinBox(this)),
      m_plot(new QCustomPlot(this)), m_current(m_plot->addGraph()), m_previousGraph(m_plot->addGraph()),
      m_peak(new QCPItemTracer(m_plot)), m_peakLabel(new QCPItemText(m_plot)),
      m_previousPeak(new QCPItemTracer(m_plot)), m_previousPeakLabel(new QCPItemText(m_plot)),
      m_readout(new QLabel(this)) {
    setObjectName(QStringLiteral("spectrumView"));
    setWindowTitle(tr("Spectrum"));
    m_channel->setObjectName(QStringLiteral("spectrumChannel"));
    m_window->setObjectName(QStringLiteral("spectrumWindow"));
    m_window->addItem(tr("Hann"), int(scope::SpectrumWindow::Hann));
    m_window->addItem(tr("Hamming"), int(scope::SpectrumWindow::Hamming));
    m_window->addItem(tr("Rectangular"), int(scope::SpectrumWindow::Rectangular));
    m_window->setToolTip(tr("Hann or Hamming: a peak stands out of the leakage of a step; Rectangular: the sharpest "
                            "peak for a tone that fills the record"));
    m_logFrequency->setChecked(true);
    m_peakFrom->setObjectName(QStringLiteral("spectrumPeakFrom"));
    m_peakFrom->setRange(0, 100000);
    m_peakFrom->setSuffix(tr(" Hz"));
    m_peakFrom->setSpecialValueText(tr("auto"));
    m_peakFrom->setToolTip(tr("auto: the peak that stands furthest above its surroundings (half an octave either "
                              "side): a resonance, not a step's own content, which is largest at the lowest "
                              "frequencies. A frequency: the largest peak above it."));
    auto* peakLabel = new QLabel(tr("&Peak above"), this);
    peakLabel->setBuddy(m_peakFrom);
    auto* choices = new QHBoxLayout;
    auto* channelLabel = new QLabel(tr("&Channel"), this);
    channelLabel->setBuddy(m_channel);
    auto* windowLabel = new QLabel(tr("&Window"), this);
    windowLabel->setBuddy(m_window);
    for (QWidget* w : std::initializer_list<QWidget*>{channelLabel, m_channel, windowLabel, m_window, peakLabel,
                                                      m_peakFrom, m_logFrequency})
        choices->addWidget(w);
    choices->addStretch(1);

    // The overlay is drawn first, so this capture's trace lies on top of it.
    m_previousGraph->setPen(QPen(kPrevious, 1.4));
    m_current->setPen(QPen(kCurrent, 1.8));
    m_plot->legend->setVisible(true);
    // Bottom left: a step's spectrum falls from the top left, and the peaks' labels sit at the top.
    m_plot->axisRect()->insetLayout()->setInsetAlignment(0, Qt::AlignBottom | Qt::AlignLeft);
    m_plot->xAxis->setLabel(tr("frequency [Hz]"));
    m_plot->xAxis->grid()->setSubGridVisible(true);
    m_plot->setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
    m_plot->setMinimumSize(560, 380);
    QFont bold = m_peakLabel->font();
    bold.setBold(true);
    for (auto [tracer, label, colour] : {std::tuple{m_peak, m_peakLabel, kPeak.darker(120)},
                                         std::tuple{m_previousPeak, m_previousPeakLabel, kPrevious.darker(150)}}) {
        tracer->setStyle(QCPItemTracer::tsCircle);
        tracer->setSize(11);
        tracer->setPen(QPen(colour, 2));
        label->position->setParentAnchor(tracer->position);
        label->setPadding(QMargins(8, 4, 8, 4));
        label->setColor(colour);
        label->setFont(bold);
    }

    m_readout->setObjectName(QStringLiteral("spectrumReadout"));
    m_readout->setWordWrap(true);
    m_readout->setTextInteractionFlags(Qt::TextSelectableByMouse);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto* escape = new QShortcut(QKeySequence(Qt::Key_Escape), this); // the plot takes the keyboard focus
    escape->setContext(Qt::WidgetWithChildrenShortcut);
    connect(escape, &QShortcut::activated, this, &QDialog::reject);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(choices);
    layout->addWidget(m_plot, 1);
    layout->addWidget(m_readout);
    layout->addWidget(buttons);
    resize(780, 560);

    connect(m_channel, &QComboBox::currentTextChanged, this, [this] { recompute(); });
    connect(m_window, &QComboBox::currentIndexChanged, this, [this] { recompute(); });
    connect(m_logFrequency, &QCheckBox::toggled, this, [this] { replot(); });
    connect(m_peakFrom, &QSpinBox::valueChanged, this, [this] { recompute(); });
    recompute();
}

void SpectrumView::showCapture(const scope::Capture& capture) {
    if (m_raw) m_previousRaw = std::move(m_raw);
    m_raw = capture;
    refresh();
}

void SpectrumView::setDerivedChannels(std::function<scope::Capture(const scope::Capture&)> derive) {
    m_derive = std::move(derive);
    refresh();
}

void SpectrumView::refresh() {
    auto derived = [this](const std::optional<scope::Capture>& raw) -> std::optional<scope::Capture> {
        if (!raw) return std::nullopt;
        return m_derive ? m_derive(*raw) : *raw;
    };
    m_capture = derived(m_raw);
    m_previous = derived(m_previousRaw);
    if (m_capture) fillChannels();
    recompute();
}

void SpectrumView::setChannel(const QString& name) {
    m_channel->setCurrentText(name);
}

void SpectrumView::setWindow(scope::SpectrumWindow window) {
    m_window->setCurrentIndex(m_window->findData(int(window)));
}

void SpectrumView::setPeakFrom(int from_hz) {
    m_peakFrom->setValue(from_hz);
}

void SpectrumView::setLogFrequency(bool log) {
    m_logFrequency->setChecked(log);
}

void SpectrumView::showEvent(QShowEvent* event) {
    QDialog::showEvent(event);
    replot(); // captures that came while hidden were analysed, not plotted
}

void SpectrumView::fillChannels() {
    const QString kept = m_channel->currentText();
    const QSignalBlocker quiet(m_channel);
    m_channel->clear();
    for (const scope::CaptureChannel& c : m_capture->channels) m_channel->addItem(QString::fromStdString(c.name));
    for (const QString& name : {kept, QStringLiteral("VFB"), QStringLiteral("PFB")})
        if (const int i = m_channel->findText(name); !name.isEmpty() && i >= 0) {
            m_channel->setCurrentIndex(i);
            break;
        }
}

void SpectrumView::recompute() {
    m_spectrum = {};
    m_overlay.reset();
    m_peakShown.reset();
    m_overlayPeak.reset();
    const std::string name = m_channel->currentText().toStdString();
    scope::SpectrumOptions options;
    options.window = scope::SpectrumWindow(m_window->currentData().toInt());
    auto analyse = [&](const scope::Capture& c) -> std::optional<scope::Spectrum> {
        for (std::size_t i = 0; i < c.channels.size(); ++i)
            if (c.channels[i].name == name) return scope::computeSpectrum(c, i, options);
        return std::nullopt;
    };
    if (m_capture) {
        if (auto s = analyse(*m_capture)) m_spectrum = std::move(*s);
        if (m_previous)
            if (auto s = analyse(*m_previous); s && s->ok()) m_overlay = std::move(*s);
    }
    auto peakOf = [this](const scope::Spectrum& s) {
        return m_peakFrom->value() > 0 ? scope::findPeakFrom(s, m_peakFrom->value()) : scope::findProminentPeak(s);
    };
    m_peakShown = peakOf(m_spectrum);
    if (m_overlay) m_overlayPeak = peakOf(*m_overlay);
    m_readout->setText(describe());
    if (isVisible()) replot();
}

// Bins from 1 up: DC (the channel's mean) has no place on a log axis and says nothing about a resonance.
void SpectrumView::plotSpectrum(QCPGraph* graph, const scope::Spectrum& s) const {
    QVector<double> f, mag;
    for (std::size_t k = 1; k < s.magnitude_db.size(); ++k) {
        f << s.frequencyAt(k);
        mag << s.magnitude_db[k];
    }
    graph->setData(f, mag, true);
}

void SpectrumView::replot() {
    const bool ok = m_capture && m_spectrum.ok();
    m_current->data()->clear();
    m_previousGraph->data()->clear();
    if (ok) plotSpectrum(m_current, m_spectrum);
    if (ok && m_overlay) plotSpectrum(m_previousGraph, *m_overlay);
    m_current->setName(ok ? QString::fromStdString(m_capture->title.empty() ? "this capture" : m_capture->title)
                          : QString());
    m_previousGraph->setName(m_previous ? tr("%1 (previous)").arg(QString::fromStdString(m_previous->title))
                                        : QString());
    m_previousGraph->setVisible(ok && m_overlay);
    m_previousGraph->removeFromLegend();
    if (m_previousGraph->visible()) m_previousGraph->addToLegend();
    m_current->removeFromLegend();
    if (ok) m_current->addToLegend();

    QCPAxis* x = m_plot->xAxis;
    const bool log = m_logFrequency->isChecked();
    x->setScaleType(log ? QCPAxis::stLogarithmic : QCPAxis::stLinear);
    if (log) {
        x->setTicker(QSharedPointer<QCPAxisTickerLog>(new QCPAxisTickerLog));
        x->setNumberFormat(QStringLiteral("g"));
    } else {
        x->setTicker(QSharedPointer<QCPAxisTicker>(new QCPAxisTicker));
    }
    m_plot->yAxis->setLabel(ok ? tr("magnitude [%1]").arg(QString::fromStdString(m_spectrum.dbUnit()))
                               : tr("magnitude [dB]"));
    if (ok) {
        const double nyquist = m_spectrum.sampleRate_hz / 2;
        x->setRange(log ? m_spectrum.resolution_hz : 0, nyquist);
        double top = -1e300, bottom = 1e300;
        for (const QCPGraph* g : {m_current, m_previousGraph}) {
            if (!g->visible()) continue;
            bool found = false;
            const QCPRange r = g->data()->valueRange(found);
            if (!found) continue;
            top = std::max(top, r.upper);
            bottom = std::min(bottom, r.lower);
        }
        top += 6;
        m_plot->yAxis->setRange(std::max(bottom, top - kShownRange_db) - 3, top);
    }
    markPeaks();
    m_plot->replot();
}

// This capture's peak in red, the overlay's in grey; each label beside its mark, the higher one above it and
// the lower one below, so the two never overlap when the peaks share a frequency.
void SpectrumView::markPeaks() {
    const bool shown = m_capture && m_spectrum.ok() && m_peakShown;
    const bool previous = shown && m_overlayPeak;
    m_peak->setVisible(shown);
    m_peakLabel->setVisible(shown);
    m_previousPeak->setVisible(previous);
    m_previousPeakLabel->setVisible(previous);
    if (!shown) return;
    auto place = [this](QCPItemTracer* tracer, QCPItemText* label, const scope::SpectrumPeak& p, bool above) {
        tracer->position->setCoords(p.frequency_hz, p.interpolated_db);
        // Right of the mark, unless that runs off the plot: then left of it.
        const bool rightPart = m_plot->xAxis->coordToPixel(p.frequency_hz) >
                               m_plot->axisRect()->left() + 0.65 * m_plot->axisRect()->width();
        label->setPositionAlignment((rightPart ? Qt::AlignRight : Qt::AlignLeft) |
                                    (above ? Qt::AlignBottom : Qt::AlignTop));
    };
    const scope::SpectrumPeak& p = *m_peakShown;
    const bool previousHigher = previous && m_overlayPeak->interpolated_db > p.interpolated_db;
    place(m_peak, m_peakLabel, p, !previousHigher);
    m_peakLabel->setText(tr("peak %1, %2").arg(hz(p.frequency_hz), db(p.interpolated_db)));
    if (!previous) return;
    const scope::SpectrumPeak& q = *m_overlayPeak;
    place(m_previousPeak, m_previousPeakLabel, q, previousHigher);
    m_previousPeakLabel->setText(tr("previous peak %1, %2").arg(hz(q.frequency_hz), db(q.interpolated_db)));
}

QString SpectrumView::readout() const {
    return m_readout->text();
}

// One paragraph a new user can read: where the peak is, how fine the frequency grid is and why, and what the
// previous capture had at that frequency.
QString SpectrumView::describe() const {
    if (!m_capture)
        return tr("Nothing recorded yet: record a step (Scope > From Drive, or Run Once in the tuning panel with the "
                  "preset \"Step for frequency response\"); its spectrum shows here.");
    const QString channel = m_channel->currentText();
    if (!m_spectrum.ok()) return tr("No spectrum of %1: %2").arg(channel, QString::fromStdString(m_spectrum.error));
    const QString unit = QString::fromStdString(m_spectrum.dbUnit());
    QStringList parts;
    const QString above = m_peakFrom->value() > 0 ? tr(" above %1 Hz").arg(m_peakFrom->value()) : QString();
    if (m_peakShown) {
        const scope::SpectrumPeak& p = *m_peakShown;
        parts << tr("<b>Peak%1: %2 at %3 %4</b>")
                     .arg(above, hz(p.frequency_hz))
                     .arg(p.interpolated_db, 0, 'f', 1)
                     .arg(unit);
    } else {
        parts << tr("no peak%1: the record is too short or its samples too far apart").arg(above);
    }
    const double record_s = double(m_spectrum.sampleCount) / m_spectrum.sampleRate_hz;
    parts << tr("resolution \u0394f = %1 (1 / the %2 s record of %3 samples every %4 ms: a longer record "
                "separates closer frequencies)")
                 .arg(hz(m_spectrum.resolution_hz))
                 .arg(record_s, 0, 'f', 3)
                 .arg(m_spectrum.sampleCount)
                 .arg(1000 / m_spectrum.sampleRate_hz, 0, 'g', 3);
    parts << tr("%1 window").arg(m_window->currentText());
    // Compared at the previous capture's peak: where a filter set against a resonance should pull it down.
    if (m_overlay && m_overlayPeak) {
        const double f = m_overlayPeak->frequency_hz;
        const double before = magnitudeAt(*m_overlay, f), now = magnitudeAt(m_spectrum, f);
        parts << tr("previous capture's peak %1: %2 there before, %3 %4 now")
                     .arg(hz(f), db(before))
                     .arg(std::abs(now - before), 0, 'f', 1)
                     .arg(now <= before ? tr("dB lower") : tr("dB higher"));
    }
    return parts.join(QStringLiteral(" \u00b7 "));
}

} // namespace app
