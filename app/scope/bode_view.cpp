// BodeView: two axis rects sharing a log frequency axis, the bandwidth marker and the summary line.
#include "bode_view.h"

#include <qcustomplot.h>

#include <QDialogButtonBox>
#include <QLabel>
#include <QShortcut>
#include <QVBoxLayout>

namespace app {

namespace {
const QColor kMagnitude(0x1f, 0x77, 0xb4);
const QColor kPhase(0xd6, 0x27, 0x28);
const QColor kMarker(0x2c, 0xa0, 0x2c);

void setUpAxes(QCPAxisRect* rect, const QString& yLabel, bool showFrequency) {
    QCPAxis* x = rect->axis(QCPAxis::atBottom);
    x->setScaleType(QCPAxis::stLogarithmic);
    x->setTicker(QSharedPointer<QCPAxisTickerLog>(new QCPAxisTickerLog));
    x->setNumberFormat(QStringLiteral("g"));
    x->setTickLabels(showFrequency);
    if (showFrequency) x->setLabel(QObject::tr("frequency [Hz]"));
    x->grid()->setSubGridVisible(true);
    rect->axis(QCPAxis::atLeft)->setLabel(yLabel);
}
} // namespace

BodeView::BodeView(QWidget* parent)
    : QDialog(parent), m_plot(new QCustomPlot(this)), m_magnitude(new QCPAxisRect(m_plot)),
      m_phase(new QCPAxisRect(m_plot)), m_summary(new QLabel(this)) {
    setObjectName(QStringLiteral("bodeView"));
    setWindowTitle(tr("Frequency Response"));
    m_plot->plotLayout()->clear();
    m_plot->plotLayout()->addElement(0, 0, m_magnitude);
    m_plot->plotLayout()->addElement(1, 0, m_phase);
    auto* margins = new QCPMarginGroup(m_plot);
    m_magnitude->setMarginGroup(QCP::msLeft | QCP::msRight, margins);
    m_phase->setMarginGroup(QCP::msLeft | QCP::msRight, margins);
    setUpAxes(m_magnitude, tr("magnitude [dB]"), false);
    setUpAxes(m_phase, tr("phase [deg]"), true);
    // Zooming or dragging the frequency of one rect moves the other.
    connect(m_magnitude->axis(QCPAxis::atBottom), qOverload<const QCPRange&>(&QCPAxis::rangeChanged),
            m_phase->axis(QCPAxis::atBottom), qOverload<const QCPRange&>(&QCPAxis::setRange));
    connect(m_phase->axis(QCPAxis::atBottom), qOverload<const QCPRange&>(&QCPAxis::rangeChanged),
            m_magnitude->axis(QCPAxis::atBottom), qOverload<const QCPRange&>(&QCPAxis::setRange));
    m_plot->setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
    m_plot->setMinimumSize(560, 420);
    m_summary->setObjectName(QStringLiteral("bodeSummary"));
    m_summary->setWordWrap(true);
    m_summary->setTextInteractionFlags(Qt::TextSelectableByMouse);
    // Close and Esc (the plot takes the keyboard focus, so Esc is a shortcut of the whole view).
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto* escape = new QShortcut(QKeySequence(Qt::Key_Escape), this);
    escape->setContext(Qt::WidgetWithChildrenShortcut);
    connect(escape, &QShortcut::activated, this, &QDialog::reject);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_plot, 1);
    layout->addWidget(m_summary);
    layout->addWidget(buttons);
    resize(760, 600);
}

QString BodeView::summary() const {
    return m_summary->text();
}

void BodeView::showNothing(const QString& why) {
    m_response = {};
    m_plot->clearGraphs();
    m_plot->clearItems();
    m_plot->replot();
    m_summary->setText(why);
}

bool BodeView::showCapture(const scope::Capture& capture, const QString& input, const QString& output) {
    const scope::CaptureChannel* in = capture.find(input.toStdString());
    const scope::CaptureChannel* out = capture.find(output.toStdString());
    if (!in || !out) {
        showNothing(input == QStringLiteral("VCMD")
                        ? tr("The capture holds no VCMD and VFB: record them with a velocity step (tuning panel "
                             "preset \"Step for frequency response\").")
                        : tr("The run holds no %1 and %2: run a test move on the simulated drive, whose bench "
                             "records both.")
                              .arg(input, output));
        return false;
    }
    m_response = scope::estimateFrequencyResponse(in->values, out->values, capture.interval_s);
    if (m_response.status != scope::FrequencyResponse::Status::Ok) {
        showNothing(tr("No frequency response from %1: %2")
                        .arg(QString::fromStdString(capture.title), QString::fromStdString(m_response.error)));
        return false;
    }
    plotResponse(QString::fromStdString(capture.title), input + QStringLiteral(" \u2192 ") + output);
    return true;
}

void BodeView::plotResponse(const QString& title, const QString& pair) {
    m_plot->clearGraphs();
    m_plot->clearItems();
    QVector<double> f, mag, phase;
    // Plotted down to 40 dB below the lowest frequency's gain: further down, a recording in whole counts
    // holds only quantisation noise, whose ratios would scatter over the plot and unwrap the phase wildly.
    const double floor_db = m_response.points.empty() ? 0.0 : m_response.points.front().magnitude_db - 40.0;
    for (const scope::FrequencyPoint& p : m_response.points) {
        if (p.magnitude_db < floor_db) break;
        f << p.frequency_hz;
        mag << p.magnitude_db;
        phase << p.phase_deg;
    }
    auto addGraph = [this](QCPAxisRect* rect, const QColor& colour, const QVector<double>& x,
                           const QVector<double>& y) {
        QCPGraph* g = m_plot->addGraph(rect->axis(QCPAxis::atBottom), rect->axis(QCPAxis::atLeft));
        g->setPen(QPen(colour, 1.8));
        g->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssDisc, colour, 4));
        g->setData(x, y, true);
        g->rescaleAxes();
        return g;
    };
    addGraph(m_magnitude, kMagnitude, f, mag);
    addGraph(m_phase, kPhase, f, phase);
    QCPAxis* magY = m_magnitude->axis(QCPAxis::atLeft);
    magY->setRange(std::min(magY->range().lower, m_response.reference_db - 6) - 2,
                   std::max(magY->range().upper, m_response.reference_db) + 2);
    m_phase->axis(QCPAxis::atLeft)->scaleRange(1.15);
    m_magnitude->axis(QCPAxis::atBottom)->setRange(f.front() * 0.9, f.back() * 1.1);

    // The -3 dB level, and the bandwidth as a vertical line through both rects with its label.
    auto* level = new QCPItemStraightLine(m_plot);
    level->setClipAxisRect(m_magnitude);
    level->setPen(QPen(Qt::gray, 1, Qt::DashLine));
    for (QCPItemPosition* p : {level->point1, level->point2}) p->setAxes(m_magnitude->axis(QCPAxis::atBottom), magY);
    level->point1->setCoords(f.front(), m_response.reference_db - 3);
    level->point2->setCoords(f.back(), m_response.reference_db - 3);
    if (m_response.bandwidth_hz) {
        for (QCPAxisRect* rect : {m_magnitude, m_phase}) {
            auto* line = new QCPItemStraightLine(m_plot);
            line->setClipAxisRect(rect);
            line->setPen(QPen(kMarker, 1.5, Qt::DashLine));
            for (QCPItemPosition* p : {line->point1, line->point2})
                p->setAxes(rect->axis(QCPAxis::atBottom), rect->axis(QCPAxis::atLeft));
            line->point1->setCoords(*m_response.bandwidth_hz, 0);
            line->point2->setCoords(*m_response.bandwidth_hz, 1);
        }
        auto* label = new QCPItemText(m_plot);
        label->setClipAxisRect(m_magnitude);
        label->position->setAxes(m_magnitude->axis(QCPAxis::atBottom), magY);
        label->position->setCoords(*m_response.bandwidth_hz, m_response.reference_db - 3);
        label->setPositionAlignment(Qt::AlignLeft | Qt::AlignTop);
        label->setPadding(QMargins(6, 4, 4, 4));
        label->setColor(kMarker.darker(130));
        label->setText(tr("\u22123 dB: %1 Hz").arg(*m_response.bandwidth_hz, 0, 'f', 1));
        QFont bold = label->font();
        bold.setBold(true);
        label->setFont(bold);
    }

    QStringList parts;
    parts << tr("<b>%1</b>: %2").arg(title.toHtmlEscaped(), pair.toHtmlEscaped());
    parts << (m_response.bandwidth_hz
                  ? tr("\u22123 dB bandwidth <b>%1 Hz</b> (phase there %2\u00b0)")
                        .arg(*m_response.bandwidth_hz, 0, 'f', 1)
                        .arg(*m_response.phaseAtBandwidth_deg, 0, 'f', 0)
                  : tr("no \u22123 dB bandwidth: %1").arg(QString::fromStdString(m_response.bandwidthNote)));
    parts << (m_response.phaseMargin_deg
                  ? tr("phase margin <b>%1\u00b0</b> at %2 Hz, of the open loop estimated as H/(1\u2212H)")
                        .arg(*m_response.phaseMargin_deg, 0, 'f', 0)
                        .arg(*m_response.crossover_hz, 0, 'f', 1)
                  : QString::fromStdString(m_response.marginNote));
    m_summary->setText(parts.join(QStringLiteral(" \u00b7 ")));
    m_plot->replot();
}

} // namespace app
