// XyPlot: channel choosers and the curve.
#include "xy_plot.h"

#include "xy_series.h"

#include <qcustomplot.h>

#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QVBoxLayout>

namespace scope {

namespace {
const QColor kCurve(0x1a, 0x73, 0xe8);
} // namespace

XyPlot::XyPlot(QWidget* parent)
    : QWidget(parent), m_x(new QComboBox(this)), m_y(new QComboBox(this)), m_plot(new QCustomPlot(this)),
      m_curve(new QCPCurve(m_plot->xAxis, m_plot->yAxis)) {
    setObjectName(QStringLiteral("xyPlot"));
    m_x->setObjectName(QStringLiteral("xyXChannel"));
    m_y->setObjectName(QStringLiteral("xyYChannel"));
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(2);
    auto* bar = new QHBoxLayout;
    bar->setContentsMargins(6, 2, 6, 0);
    bar->addWidget(new QLabel(tr("X:"), this));
    bar->addWidget(m_x);
    bar->addSpacing(12);
    bar->addWidget(new QLabel(tr("Y:"), this));
    bar->addWidget(m_y);
    bar->addStretch(1);
    layout->addLayout(bar);
    layout->addWidget(m_plot, 1);
    const QString tip = tr("Plot one recorded channel against another, sample by sample "
                           "(e.g. following error PE against velocity VFB).");
    m_x->setToolTip(tip);
    m_y->setToolTip(tip);

    m_plot->setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
    m_curve->setPen(QPen(kCurve, 1.5));
    m_curve->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssDisc, kCurve, 3));
    m_curve->setName(tr("XY"));
    const auto changed = [this] { replot(); };
    connect(m_x, &QComboBox::currentIndexChanged, this, changed);
    connect(m_y, &QComboBox::currentIndexChanged, this, changed);
    replot();
}

// The choice follows the channels by name: a new recording of the same variables keeps the XY pair.
void XyPlot::showCapture(const Capture& capture) {
    const QString xName = m_x->currentData().toString(); // the bare name; the combo shows "PE [POS]"
    const QString yName = m_y->currentData().toString();
    m_capture = capture;
    const QSignalBlocker bx(m_x);
    const QSignalBlocker by(m_y);
    m_x->clear();
    m_y->clear();
    for (const CaptureChannel& c : capture.channels) {
        const QString name = QString::fromStdString(c.name);
        const QString title =
            c.unit.empty() ? name : QStringLiteral("%1 [%2]").arg(name, QString::fromStdString(c.unit));
        m_x->addItem(title, name);
        m_y->addItem(title, name);
    }
    // First against second unless the same names come again.
    const int x = m_x->findData(xName);
    const int y = m_y->findData(yName);
    m_x->setCurrentIndex(x >= 0 ? x : 0);
    m_y->setCurrentIndex(y >= 0 ? y : std::min(1, m_y->count() - 1));
    replot();
}

void XyPlot::setChannels(int xChannel, int yChannel) {
    if (xChannel >= 0 && xChannel < m_x->count()) m_x->setCurrentIndex(xChannel);
    if (yChannel >= 0 && yChannel < m_y->count()) m_y->setCurrentIndex(yChannel);
    replot();
}

int XyPlot::xChannel() const {
    return m_x->currentIndex();
}

int XyPlot::yChannel() const {
    return m_y->currentIndex();
}

void XyPlot::replot() {
    const XySeries s = xySeries(m_capture, std::size_t(std::max(0, xChannel())), std::size_t(std::max(0, yChannel())));
    QVector<QCPCurveData> points;
    points.reserve(qsizetype(s.x.size()));
    for (std::size_t i = 0; i < s.x.size(); ++i) points.append(QCPCurveData(double(i), s.x[i], s.y[i]));
    m_curve->data()->set(points, true);
    m_plot->xAxis->setLabel(s.x.empty() ? tr("X (record a capture with two channels)")
                                        : QString::fromStdString(s.xTitle));
    m_plot->yAxis->setLabel(s.y.empty() ? tr("Y") : QString::fromStdString(s.yTitle));
    if (!s.x.empty()) {
        m_curve->rescaleAxes();
        // A little room around the curve, so its extremes do not sit on the frame.
        for (QCPAxis* axis : {m_plot->xAxis, m_plot->yAxis}) {
            const QCPRange r = axis->range();
            const double pad = std::max(r.size() * 0.05, std::max(std::abs(r.center()) * 0.05, 1e-9));
            axis->setRange(r.lower - pad, r.upper + pad);
        }
    }
    m_plot->replot(QCustomPlot::rpQueuedReplot);
}

} // namespace scope
