// ScopePlot: graphs, axes, overlays, cursors and themes on a QCustomPlot.
#include "scope_plot.h"

#include "svg_export.h"

#include <qcustomplot.h>

#include <QFile>
#include <QKeyEvent>
#include <QLabel>
#include <QVBoxLayout>

#include <cmath>

namespace scope {

namespace {
constexpr int kSyncMs = 30;          // live appends reach the graphs at most this often
constexpr int kCursorGrabPixels = 6; // how close a press must be to drag a cursor
constexpr double kZoomStep = 0.8;    // + / - keys
constexpr double kPanStep = 0.1;     // arrow keys, of the visible span
constexpr std::size_t kWidePenPoints = 20000;
const QColor kLight[ScopePlot::kMaxChannels] = {QColor(0x1a, 0x73, 0xe8), QColor(0xd9, 0x30, 0x25),
                                                QColor(0x18, 0x80, 0x38), QColor(0xe3, 0x74, 0x00)};
const QColor kDark[ScopePlot::kMaxChannels] = {QColor(0x8a, 0xb4, 0xf8), QColor(0xf2, 0x8b, 0x82),
                                               QColor(0x81, 0xc9, 0x95), QColor(0xfd, 0xd6, 0x63)};

QString axisLabel(const std::string& name, const std::string& unit) {
    return unit.empty() ? QString::fromStdString(name)
                        : QStringLiteral("%1 [%2]").arg(QString::fromStdString(name), QString::fromStdString(unit));
}
} // namespace

ScopePlot::ScopePlot(QWidget* parent) : QWidget(parent), m_plot(new QCustomPlot(this)), m_readout(new QLabel(this)) {
    setObjectName(QStringLiteral("scopePlot"));
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(2);
    layout->addWidget(m_plot, 1);
    layout->addWidget(m_readout);
    m_readout->setObjectName(QStringLiteral("cursorReadout"));
    m_readout->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_readout->setContentsMargins(6, 0, 6, 2);

    m_plot->setFocusPolicy(Qt::StrongFocus);
    m_plot->installEventFilter(this);
    m_plot->setNoAntialiasingOnDrag(true);
    m_plot->setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
    m_plot->axisRect()->setRangeZoom(Qt::Horizontal);
    m_plot->xAxis->setLabel(tr("Time [s]"));
    m_plot->legend->setVisible(true);
    m_plot->axisRect()->insetLayout()->setInsetAlignment(0, Qt::AlignTop | Qt::AlignLeft); // steps start low and left
    m_valueAxes = {m_plot->yAxis};
    for (int i = 0; i < 2; ++i) {
        m_cursor[i] = new QCPItemStraightLine(m_plot);
        m_cursor[i]->setVisible(false);
        m_cursor[i]->setSelectable(false);
    }
    connect(m_plot, &QCustomPlot::mousePress, this, &ScopePlot::onMousePress);
    connect(m_plot, &QCustomPlot::mouseMove, this, &ScopePlot::onMouseMove);
    connect(m_plot, &QCustomPlot::mouseRelease, this, &ScopePlot::onMouseRelease);
    connect(m_plot, &QCustomPlot::mouseDoubleClick, this, &ScopePlot::onDoubleClick);
    m_syncTimer.setSingleShot(true);
    m_syncTimer.setInterval(kSyncMs);
    connect(&m_syncTimer, &QTimer::timeout, this, &ScopePlot::syncFromStore);
    applyTheme();
    updateReadout();
}

ScopePlot::~ScopePlot() = default;

QColor ScopePlot::channelColour(std::size_t channel) const {
    return (m_dark ? kDark : kLight)[channel % kMaxChannels];
}

// Channel 0 on the left axis, 1 on the right, 2 and 3 on further axes outside them.
void ScopePlot::ensureAxes(std::size_t count) {
    while (std::size_t(m_valueAxes.size()) < count) {
        const auto n = m_valueAxes.size();
        if (n == 1)
            m_valueAxes.append(m_plot->yAxis2);
        else
            m_valueAxes.append(m_plot->axisRect()->addAxis(n % 2 ? QCPAxis::atRight : QCPAxis::atLeft));
    }
    for (qsizetype i = 0; i < m_valueAxes.size(); ++i) {
        m_valueAxes[i]->setVisible(std::size_t(i) < count || i == 0);
        m_valueAxes[i]->setTickLabels(true);
    }
    m_plot->axisRect()->setRangeDragAxes({m_plot->xAxis}, m_valueAxes);
    m_plot->axisRect()->setRangeZoomAxes({m_plot->xAxis}, m_valueAxes);
}

QCPGraph* ScopePlot::addGraph(std::size_t channel) {
    QCPGraph* g = m_plot->addGraph(m_plot->xAxis, m_valueAxes.at(qsizetype(channel)));
    g->setAdaptiveSampling(true);
    g->setLineStyle(QCPGraph::lsLine);
    return g;
}

void ScopePlot::clear() {
    for (const Overlay& o : m_overlays)
        for (QCPGraph* g : o.graphs) m_plot->removeGraph(g);
    m_overlays.clear();
    for (QCPGraph* g : m_graphs) m_plot->removeGraph(g);
    m_graphs.clear();
    m_store = SeriesStore();
    m_syncedUntil.clear();
    m_capture = {};
    emit overlaysChanged();
    updateReadout();
    requestReplot();
}

void ScopePlot::showCapture(const Capture& capture, bool keepPrevious) {
    if (keepPrevious && !m_graphs.isEmpty()) {
        Overlay o{m_title, m_graphs, true};
        for (QCPGraph* g : o.graphs) g->removeFromLegend();
        m_overlays.push_front(o);
        m_graphs.clear();
        while (int(m_overlays.size()) > m_maxOverlays) {
            for (QCPGraph* g : m_overlays.back().graphs) m_plot->removeGraph(g);
            m_overlays.pop_back();
        }
    } else {
        for (const Overlay& o : m_overlays)
            for (QCPGraph* g : o.graphs) m_plot->removeGraph(g);
        m_overlays.clear();
        for (QCPGraph* g : m_graphs) m_plot->removeGraph(g);
        m_graphs.clear();
    }
    const std::size_t count = std::min<std::size_t>(capture.channels.size(), kMaxChannels);
    std::vector<std::pair<std::string, std::string>> names;
    for (std::size_t c = 0; c < count; ++c) names.emplace_back(capture.channels[c].name, capture.channels[c].unit);
    beginLive(names);
    m_capture = capture;
    m_title = QString::fromStdString(capture.title);
    // The whole capture at once: straight into the graphs (sorted), the store keeps a copy for ranges.
    for (std::size_t c = 0; c < count; ++c) {
        const auto& values = capture.channels[c].values;
        QVector<QCPGraphData> points(qsizetype(values.size()));
        for (std::size_t i = 0; i < values.size(); ++i) {
            points[qsizetype(i)] = {capture.timeAt(i), values[i]};
            m_store.append(c, {capture.timeAt(i), values[i]});
        }
        m_graphs[qsizetype(c)]->data()->set(points, true);
        m_syncedUntil[c] = values.empty() ? -INFINITY : capture.timeAt(values.size() - 1);
    }
    recolourOverlays();
    const double end = capture.sampleCount() > 1 ? capture.timeAt(capture.sampleCount() - 1) : 1.0;
    if (!cursorsVisible() || m_cursorTime[1] > end) setCursors(end * 0.25, end * 0.75);
    updateReadout(); // the cursors stayed where they were: their values are the new trace's
    autoScale();
    emit overlaysChanged();
}

void ScopePlot::beginLive(const std::vector<std::pair<std::string, std::string>>& namesAndUnits) {
    for (QCPGraph* g : m_graphs) m_plot->removeGraph(g);
    m_graphs.clear();
    m_store = SeriesStore();
    m_capture = {};
    m_title.clear();
    const std::size_t count = std::min<std::size_t>(namesAndUnits.size(), kMaxChannels);
    ensureAxes(std::max<std::size_t>(count, 1));
    m_syncedUntil.assign(count, -INFINITY);
    for (std::size_t c = 0; c < count; ++c) {
        const auto& [name, unit] = namesAndUnits[c];
        m_store.addChannel(name, unit);
        QCPGraph* g = addGraph(c);
        g->setName(QString::fromStdString(name));
        m_valueAxes[qsizetype(c)]->setLabel(axisLabel(name, unit));
        m_graphs.append(g);
    }
    applyTheme();
    updateReadout();
}

void ScopePlot::appendLive(std::size_t channel, double time_s, double value) {
    if (channel >= std::size_t(m_graphs.size())) return;
    if (m_store.append(channel, {time_s, value})) scheduleSync();
}

void ScopePlot::scheduleSync() {
    if (!m_syncTimer.isActive()) m_syncTimer.start();
}

// Hands the samples appended since the last sync to the graphs, and drops what the store dropped.
void ScopePlot::syncFromStore() {
    for (std::size_t c = 0; c < std::size_t(m_graphs.size()); ++c) {
        const auto& samples = m_store.channel(c).samples;
        auto first = samples.end();
        while (first != samples.begin() && std::prev(first)->time_s > m_syncedUntil[c]) --first;
        for (auto it = first; it != samples.end(); ++it) m_graphs[qsizetype(c)]->addData(it->time_s, it->value);
        if (first != samples.end()) m_syncedUntil[c] = samples.back().time_s;
        if (!samples.empty()) m_graphs[qsizetype(c)]->data()->removeBefore(samples.front().time_s);
    }
    updateReadout(); // new samples under the cursors (at most once per kSyncMs)
    requestReplot();
}

int ScopePlot::pointCount(std::size_t channel) const {
    return channel < std::size_t(m_graphs.size()) ? m_graphs[qsizetype(channel)]->dataCount() : 0;
}

void ScopePlot::requestReplot() {
    if (isVisible()) m_plot->replot(QCustomPlot::rpQueuedReplot);
}

void ScopePlot::showEvent(QShowEvent* event) {
    QWidget::showEvent(event);
    m_plot->replot(QCustomPlot::rpQueuedReplot);
}

QString ScopePlot::overlayTitle(int index) const {
    return index >= 0 && index < overlayCount() ? m_overlays[std::size_t(index)].title : QString();
}

bool ScopePlot::isOverlayVisible(int index) const {
    return index >= 0 && index < overlayCount() && m_overlays[std::size_t(index)].visible;
}

void ScopePlot::setOverlayVisible(int index, bool visible) {
    if (index < 0 || index >= overlayCount()) return;
    Overlay& o = m_overlays[std::size_t(index)];
    o.visible = visible;
    for (QCPGraph* g : o.graphs) g->setVisible(visible);
    requestReplot(); // not overlaysChanged(): the overlays are the same ones, a menu may be toggling them
}

void ScopePlot::setMaxOverlays(int count) {
    m_maxOverlays = std::max(0, count);
}

// Older overlays fade: each age turns the channel's hue a little and lowers its opacity.
void ScopePlot::recolourOverlays() {
    // Wide pens are stroked by the raster engine point by point: only small captures get them.
    const double width = m_capture.sampleCount() > kWidePenPoints ? 1.0 : 2.0;
    for (qsizetype c = 0; c < m_graphs.size(); ++c) {
        m_graphs[c]->setPen(QPen(channelColour(std::size_t(c)), width));
        m_graphs[c]->setAntialiased(m_capture.sampleCount() <= kWidePenPoints); // and antialiasing
    }
    for (std::size_t age = 0; age < m_overlays.size(); ++age) {
        const double fade = 1.0 - double(age + 1) / double(m_maxOverlays + 1);
        for (qsizetype c = 0; c < m_overlays[age].graphs.size(); ++c) {
            QColor colour = channelColour(std::size_t(c));
            colour.setHsv((colour.hsvHue() + 35 * int(age + 1)) % 360, int(colour.hsvSaturation() * 0.75),
                          colour.value(), int(40 + 170 * fade));
            m_overlays[age].graphs[c]->setPen(QPen(colour, 1.0));
        }
    }
}

void ScopePlot::setCursors(double first_s, double second_s) {
    m_cursorTime[0] = first_s;
    m_cursorTime[1] = second_s;
    for (int i = 0; i < 2; ++i) {
        m_cursor[i]->point1->setCoords(m_cursorTime[i], 0);
        m_cursor[i]->point2->setCoords(m_cursorTime[i], 1);
        m_cursor[i]->setVisible(true);
    }
    updateReadout();
    emit cursorsChanged();
    requestReplot();
}

void ScopePlot::setCursorsVisible(bool visible) {
    for (auto* c : m_cursor) c->setVisible(visible);
    updateReadout();
    requestReplot();
}

bool ScopePlot::cursorsVisible() const {
    return m_cursor[0]->visible();
}

// A capture's samples, or the live ones in the store when the trace came by appendLive().
CursorReadout ScopePlot::readout() const {
    return m_capture.channels.empty() ? readCursors(m_store, m_cursorTime[0], m_cursorTime[1])
                                      : readCursors(m_capture, m_cursorTime[0], m_cursorTime[1]);
}

void ScopePlot::updateReadout() {
    m_readout->setText(cursorsVisible() ? QString::fromStdString(readout().text())
                                        : tr("Double-click to place the cursors; drag them to move."));
}

void ScopePlot::autoScale() {
    m_plot->xAxis->rescale(true);
    for (qsizetype c = 0; c < m_valueAxes.size(); ++c) {
        QCPAxis* axis = m_valueAxes[c];
        axis->rescale(true);
        QCPRange r = axis->range();
        const double pad = std::max(r.size() * 0.06, std::max(std::abs(r.center()) * 0.05, 1e-9));
        axis->setRange(r.lower - pad, r.upper + pad);
    }
    if (m_graphs.isEmpty()) m_plot->xAxis->setRange(0, 1);
    requestReplot();
}

void ScopePlot::setGridVisible(bool visible) {
    m_grid = visible;
    applyTheme();
}

void ScopePlot::setDarkTheme(bool dark) {
    m_dark = dark;
    applyTheme();
}

void ScopePlot::applyTheme() {
    const QColor background = m_dark ? QColor(0x20, 0x21, 0x24) : Qt::white;
    const QColor foreground = m_dark ? QColor(0xe8, 0xea, 0xed) : QColor(0x3c, 0x40, 0x43);
    const QColor grid = m_dark ? QColor(0x3c, 0x40, 0x43) : QColor(0xe0, 0xe0, 0xe0);
    m_plot->setBackground(background);
    QList<QCPAxis*> axes = m_valueAxes;
    axes << m_plot->xAxis << m_plot->xAxis2;
    for (QCPAxis* axis : axes) {
        const int channel = int(m_valueAxes.indexOf(axis));
        const QColor colour =
            channel >= 0 && channel < m_graphs.size() ? channelColour(std::size_t(channel)) : foreground;
        axis->setBasePen(QPen(colour));
        axis->setTickPen(QPen(colour));
        axis->setSubTickPen(QPen(colour));
        axis->setTickLabelColor(colour);
        axis->setLabelColor(colour);
        axis->grid()->setPen(QPen(grid, 1, Qt::DotLine));
        axis->grid()->setZeroLinePen(QPen(grid, 1));
        axis->grid()->setVisible(m_grid && (axis == m_plot->xAxis || axis == m_plot->yAxis));
    }
    m_plot->legend->setBrush(QColor(background.red(), background.green(), background.blue(), 220));
    m_plot->legend->setTextColor(foreground);
    m_plot->legend->setBorderPen(QPen(grid));
    const QColor cursor = m_dark ? QColor(0xff, 0xff, 0xff, 170) : QColor(0x20, 0x21, 0x24, 170);
    for (auto* c : m_cursor) c->setPen(QPen(cursor, 1, Qt::DashLine));
    m_readout->setStyleSheet(
        QStringLiteral("QLabel { color: %1; background: %2; }").arg(foreground.name(), background.name()));
    recolourOverlays();
    requestReplot();
}

bool ScopePlot::eventFilter(QObject* watched, QEvent* event) {
    if (watched != m_plot || event->type() != QEvent::KeyPress) return QWidget::eventFilter(watched, event);
    auto* key = static_cast<QKeyEvent*>(event);
    QCPAxis* x = m_plot->xAxis;
    switch (key->key()) {
    case Qt::Key_Plus:
    case Qt::Key_Equal: x->scaleRange(kZoomStep, x->range().center()); break;
    case Qt::Key_Minus: x->scaleRange(1 / kZoomStep, x->range().center()); break;
    case Qt::Key_Left: x->moveRange(-x->range().size() * kPanStep); break;
    case Qt::Key_Right: x->moveRange(x->range().size() * kPanStep); break;
    case Qt::Key_Up:
    case Qt::Key_Down: {
        const double sign = key->key() == Qt::Key_Up ? 1 : -1;
        for (QCPAxis* axis : m_valueAxes) axis->moveRange(sign * axis->range().size() * kPanStep);
        break;
    }
    case Qt::Key_Home:
    case Qt::Key_A: autoScale(); return true;
    default: return QWidget::eventFilter(watched, event);
    }
    requestReplot();
    return true;
}

void ScopePlot::onMousePress(QMouseEvent* event) {
    m_dragging = -1;
    if (!cursorsVisible()) return;
    for (int i = 0; i < 2; ++i) {
        if (std::abs(m_plot->xAxis->coordToPixel(m_cursorTime[i]) - event->position().x()) <= kCursorGrabPixels) {
            m_dragging = i;
            m_plot->setInteraction(QCP::iRangeDrag, false);
            return;
        }
    }
}

void ScopePlot::onMouseMove(QMouseEvent* event) {
    if (m_dragging < 0) return;
    double t[2] = {m_cursorTime[0], m_cursorTime[1]};
    t[m_dragging] = m_plot->xAxis->pixelToCoord(event->position().x());
    setCursors(t[0], t[1]);
}

void ScopePlot::onMouseRelease(QMouseEvent*) {
    m_dragging = -1;
    m_plot->setInteraction(QCP::iRangeDrag, true);
}

// A double-click moves the nearer cursor there.
void ScopePlot::onDoubleClick(QMouseEvent* event) {
    const double t = m_plot->xAxis->pixelToCoord(event->position().x());
    double times[2] = {m_cursorTime[0], m_cursorTime[1]};
    if (!cursorsVisible()) times[0] = times[1] = t;
    times[std::abs(t - times[0]) <= std::abs(t - times[1]) ? 0 : 1] = t;
    setCursors(times[0], times[1]);
}

bool ScopePlot::savePng(const QString& path, int width, int height) {
    return m_plot->savePng(path, width, height);
}

bool ScopePlot::savePdf(const QString& path, int width, int height) {
    return m_plot->savePdf(path, width, height);
}

bool ScopePlot::saveSvg(const QString& path, int width, int height) {
    SvgPlot svg;
    svg.width = width > 0 ? width : m_plot->width();
    svg.height = height > 0 ? height : m_plot->height();
    svg.timeFrom_s = m_plot->xAxis->range().lower;
    svg.timeTo_s = m_plot->xAxis->range().upper;
    for (qsizetype c = 0; c < m_graphs.size() && std::size_t(c) < m_capture.channels.size(); ++c)
        svg.channels.push_back({&m_capture.channels[std::size_t(c)], m_valueAxes[c]->range().lower,
                                m_valueAxes[c]->range().upper, channelColour(std::size_t(c)).name().toStdString()});
    svg.interval_s = m_capture.interval_s;
    QFile file(path);
    return file.open(QIODevice::WriteOnly | QIODevice::Truncate) &&
           file.write(QByteArray::fromStdString(writeSvg(svg))) > 0;
}

} // namespace scope
