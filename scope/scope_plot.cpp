// ScopePlot: graphs, axes, overlays, cursors and themes on a QCustomPlot.
#include "scope_plot.h"

#include "column_graph.h"
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
const QColor kLight[ScopePlot::kMaxChannels] = {
    QColor(0x1a, 0x73, 0xe8), QColor(0xd9, 0x30, 0x25), QColor(0x18, 0x80, 0x38), QColor(0xe3, 0x74, 0x00),
    QColor(0x93, 0x34, 0xe6), QColor(0x12, 0x9e, 0xaf), QColor(0xd0, 0x18, 0x84), QColor(0x79, 0x55, 0x48)};
const QColor kDark[ScopePlot::kMaxChannels] = {
    QColor(0x8a, 0xb4, 0xf8), QColor(0xf2, 0x8b, 0x82), QColor(0x81, 0xc9, 0x95), QColor(0xfd, 0xd6, 0x63),
    QColor(0xc5, 0x8a, 0xf9), QColor(0x78, 0xd9, 0xec), QColor(0xff, 0x8b, 0xcb), QColor(0xbc, 0xaa, 0xa4)};

void widen(std::optional<ValueRange>& range, ValueRange by) {
    if (!range) range = by;
    widen(*range, by);
}

// As QCPAxis::rescale sets a range it found: one of zero size keeps the axis's size, centred on it.
void setFoundRange(QCPAxis* axis, ValueRange found) {
    QCPRange range(found.minimum, found.maximum);
    if (!QCPRange::validRange(range)) {
        const double centre = (range.lower + range.upper) / 2;
        range = QCPRange(centre - axis->range().size() / 2, centre + axis->range().size() / 2);
    }
    axis->setRange(range);
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
    m_plot->axisRect()->insetLayout()->setInsetAlignment(0, Qt::AlignTop | Qt::AlignLeft); // until a trace is under it
    m_valueAxes = {m_plot->yAxis};
    for (int i = 0; i < 2; ++i) {
        m_cursor[i] = new QCPItemStraightLine(m_plot);
        m_cursor[i]->setVisible(false);
        m_cursor[i]->setSelectable(false);
        // The letter rides on its line at the top of the axis rect, whatever the value axes' ranges.
        QCPItemText* label = m_cursorLabel[i] = new QCPItemText(m_plot);
        label->setText(i == 0 ? QStringLiteral("A") : QStringLiteral("B"));
        label->position->setTypeX(QCPItemPosition::ptPlotCoords);
        label->position->setTypeY(QCPItemPosition::ptAxisRectRatio);
        label->setPositionAlignment(Qt::AlignHCenter | Qt::AlignTop);
        label->setPadding(QMargins(3, 1, 3, 1));
        label->setClipToAxisRect(false);
        label->setVisible(false);
        label->setSelectable(false);
    }
    m_readout->setToolTip(tr("Cursors A and B: double-click places the nearer one, drag moves it. Keys, with the "
                             "plot focused: C places both in view, Space switches A/B, Shift+Left/Right moves the "
                             "active one a sample, Ctrl+Shift+Left/Right a tenth of the view."));
    connect(m_plot, &QCustomPlot::mousePress, this, &ScopePlot::onMousePress);
    connect(m_plot, &QCustomPlot::mouseMove, this, &ScopePlot::onMouseMove);
    connect(m_plot, &QCustomPlot::mouseRelease, this, &ScopePlot::onMouseRelease);
    connect(m_plot, &QCustomPlot::mouseDoubleClick, this, &ScopePlot::onDoubleClick);
    // After the layout, before drawing: the axis rect's width is final, for replots and exports alike.
    connect(m_plot, &QCustomPlot::afterLayout, this, &ScopePlot::decimateGraphs);
    connect(m_plot, &QCustomPlot::afterLayout, this, &ScopePlot::placeLegend); // over what was just decimated
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

// Channel 0 on the left axis, 1 on the right; then even channels left and odd right, each further out.
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

// On the first axis until layoutAxes() puts it on the axis of its unit.
ColumnGraph* ScopePlot::addGraph() {
    auto* g = new ColumnGraph(m_plot->xAxis, m_valueAxes.first()); // owned by the plot
    g->setAdaptiveSampling(true);
    g->setLineStyle(QCPGraph::lsLine);
    return g;
}

void ScopePlot::clear() {
    for (const Overlay& o : m_overlays)
        for (ColumnGraph* g : o.graphs) m_plot->removeGraph(g);
    m_overlays.clear();
    for (ColumnGraph* g : m_graphs) m_plot->removeGraph(g);
    m_graphs.clear();
    m_store = SeriesStore();
    m_drawn.reset();
    m_capture = {};
    emit overlaysChanged();
    updateReadout();
    requestReplot();
}

void ScopePlot::showCapture(const Capture& capture, bool keepPrevious) {
    if (keepPrevious && !m_graphs.isEmpty()) {
        Overlay o{m_title, m_graphs, true, std::move(m_store)};
        for (ColumnGraph* g : o.graphs) g->removeFromLegend();
        m_overlays.push_front(std::move(o));
        m_graphs.clear();
        while (int(m_overlays.size()) > m_maxOverlays) {
            for (ColumnGraph* g : m_overlays.back().graphs) m_plot->removeGraph(g);
            m_overlays.pop_back();
        }
    } else {
        for (const Overlay& o : m_overlays)
            for (ColumnGraph* g : o.graphs) m_plot->removeGraph(g);
        m_overlays.clear();
        for (ColumnGraph* g : m_graphs) m_plot->removeGraph(g);
        m_graphs.clear();
    }
    const std::size_t count = std::min<std::size_t>(capture.channels.size(), kMaxChannels);
    std::vector<std::pair<std::string, std::string>> names;
    for (std::size_t c = 0; c < count; ++c) names.emplace_back(capture.channels[c].name, capture.channels[c].unit);
    // The store holds the whole capture, however long; the graphs get its decimation frame by frame.
    beginTrace(names, std::max<std::size_t>(SeriesStore::kDefaultCapacity, capture.sampleCount()));
    m_capture = capture;
    m_title = QString::fromStdString(capture.title);
    for (std::size_t c = 0; c < count; ++c) {
        const auto& values = capture.channels[c].values;
        for (std::size_t i = 0; i < values.size(); ++i) m_store.append(c, {capture.timeAt(i), values[i]});
    }
    recolourOverlays();
    const double end = capture.sampleCount() > 1 ? capture.timeAt(capture.sampleCount() - 1) : 1.0;
    if (!cursorsVisible() || m_cursorTime[1] > end) setCursors(end * 0.25, end * 0.75);
    updateReadout(); // the cursors stayed where they were: their values are the new trace's
    autoScale();
    emit overlaysChanged();
}

void ScopePlot::replaceCapture(const Capture& capture) {
    std::deque<Overlay> kept = std::move(m_overlays);
    m_overlays.clear();
    showCapture(capture, false); // with no overlays, drops the current trace alone
    m_overlays = std::move(kept);
    recolourOverlays();
    emit overlaysChanged();
}

void ScopePlot::beginLive(const std::vector<std::pair<std::string, std::string>>& namesAndUnits) {
    beginTrace(namesAndUnits, SeriesStore::kDefaultCapacity);
}

void ScopePlot::beginTrace(const std::vector<std::pair<std::string, std::string>>& namesAndUnits,
                           std::size_t capacity) {
    for (ColumnGraph* g : m_graphs) m_plot->removeGraph(g);
    m_graphs.clear();
    m_store = SeriesStore(capacity);
    m_drawn.reset();
    m_capture = {};
    m_title.clear();
    const std::size_t count = std::min<std::size_t>(namesAndUnits.size(), kMaxChannels);
    for (std::size_t c = 0; c < count; ++c) {
        const auto& [name, unit] = namesAndUnits[c];
        m_store.addChannel(name, unit);
        ColumnGraph* g = addGraph();
        g->setName(QString::fromStdString(name));
        m_graphs.append(g);
    }
    layoutAxes();
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

// Live samples reach the graphs with the next frame's decimation (the store's revision has moved on).
void ScopePlot::syncFromStore() {
    updateReadout(); // new samples under the cursors (at most once per kSyncMs)
    requestReplot();
}

// Each visible graph gets its store's min/max decimation for the x range, about a column per pixel of the
// axis rect: O(width) points a graph, whatever the number of samples (ColumnGraph::showRange).
void ScopePlot::decimateGraphs() {
    const QCPRange x = m_plot->xAxis->range();
    const int columns = std::max(1, m_plot->axisRect()->width());
    const DrawnFor now{x.lower, x.upper, columns, m_store.revision()};
    if (m_drawn == now) return;
    m_drawn = now;
    const auto feed = [&x, columns](const SeriesStore& store, const QList<ColumnGraph*>& graphs) {
        for (qsizetype c = 0; c < graphs.size() && std::size_t(c) < store.channelCount(); ++c)
            if (graphs[c]->visible()) graphs[c]->showRange(store, std::size_t(c), x.lower, x.upper, columns);
    };
    feed(m_store, m_graphs);
    for (const Overlay& o : m_overlays)
        if (o.visible) feed(o.store, o.graphs);
}

namespace {
PixelBox pixelBox(const QRect& r) {
    return {double(r.left()), double(r.top()), double(r.width()), double(r.height())};
}
} // namespace

// The visible graphs as the frame draws them, in the plot's pixels.
std::vector<std::vector<PixelPoint>> ScopePlot::drawnTraces() const {
    std::vector<std::vector<PixelPoint>> traces;
    for (int g = 0; g < m_plot->graphCount(); ++g) {
        const QCPGraph* graph = m_plot->graph(g);
        if (!graph->visible()) continue;
        std::vector<PixelPoint>& trace = traces.emplace_back();
        trace.reserve(std::size_t(graph->data()->size()));
        for (const QCPGraphData& d : *graph->data()) {
            const QPointF p = graph->coordsToPixels(d.key, d.value);
            trace.push_back({p.x(), p.y()});
        }
    }
    return traces;
}

int ScopePlot::tracesUnderLegend() const {
    const QCPLegend* legend = m_plot->legend;
    if (!legend->visible() || legend->itemCount() == 0) return 0;
    return segmentsThrough(drawnTraces(), pixelBox(legend->outerRect()));
}

// The legend goes to the corner of the plot area where it hides the least of the drawn graphs (legend_corner.h),
// laid out again at once so that this frame draws it there.
void ScopePlot::placeLegend() {
    const QCPLegend* legend = m_plot->legend;
    if (!legend->visible() || legend->itemCount() == 0) return;
    const QSize size = legend->outerRect().size();
    const LegendCorner corner = bestLegendCorner(drawnTraces(), pixelBox(m_plot->axisRect()->rect()), size.width(),
                                                 size.height(), 0, m_legendCorner);
    if (corner == m_legendCorner) return;
    m_legendCorner = corner;
    const Qt::Alignment horizontal =
        corner == LegendCorner::TopLeft || corner == LegendCorner::BottomLeft ? Qt::AlignLeft : Qt::AlignRight;
    const Qt::Alignment vertical =
        corner == LegendCorner::TopLeft || corner == LegendCorner::TopRight ? Qt::AlignTop : Qt::AlignBottom;
    QCPLayoutInset* inset = m_plot->axisRect()->insetLayout();
    inset->setInsetAlignment(0, horizontal | vertical);
    inset->update(QCPLayoutElement::upLayout);
}

// The current trace's channels grouped onto value axes (axis_groups.h); every graph, an overlay's too, goes
// on the axis of its unit.
void ScopePlot::layoutAxes() {
    std::vector<std::pair<std::string, std::string>> namesAndUnits;
    for (std::size_t c = 0; c < std::size_t(m_graphs.size()) && c < m_store.channelCount(); ++c)
        namesAndUnits.emplace_back(m_store.channel(c).name, m_store.channel(c).unit);
    m_layout = groupAxes(namesAndUnits, m_axisMode);
    ensureAxes(std::max<std::size_t>(m_layout.axes.size(), 1));
    m_valueAxes.first()->setLabel(QString());
    for (std::size_t a = 0; a < m_layout.axes.size(); ++a)
        m_valueAxes[qsizetype(a)]->setLabel(QString::fromStdString(m_layout.axes[a].label));
    for (qsizetype c = 0; c < m_graphs.size(); ++c)
        m_graphs[c]->setValueAxis(m_valueAxes[qsizetype(m_layout.axisOf[std::size_t(c)])]);
    for (Overlay& o : m_overlays)
        for (qsizetype c = 0; c < o.graphs.size() && std::size_t(c) < o.store.channelCount(); ++c)
            o.graphs[c]->setValueAxis(axisForUnit(o.store.channel(std::size_t(c)).unit));
}

// An earlier trace's channel of a unit the current one does not have goes on the first axis.
QCPAxis* ScopePlot::axisForUnit(const std::string& unit) const {
    if (m_axisMode == AxisMode::PerUnit)
        for (std::size_t a = 0; a < m_layout.axes.size(); ++a)
            if (m_layout.axes[a].unit == unit) return m_valueAxes[qsizetype(a)];
    return m_valueAxes.first();
}

void ScopePlot::setAxisMode(AxisMode mode) {
    m_axisMode = mode;
    layoutAxes();
    applyTheme();
    autoScale();
}

QList<QCPAxis*> ScopePlot::valueAxes() const {
    return m_valueAxes.mid(0, qsizetype(std::max<std::size_t>(m_layout.axes.size(), 1)));
}

int ScopePlot::pointCount(std::size_t channel) const {
    return channel < std::size_t(m_graphs.size()) ? int(m_store.channel(channel).samples.size()) : 0;
}

int ScopePlot::drawnPointCount(std::size_t channel) const {
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
    for (ColumnGraph* g : o.graphs) g->setVisible(visible);
    m_drawn.reset(); // a hidden overlay's graphs were not kept up to date
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
        QPen pen = m_cursor[i]->pen();
        pen.setStyle(i == m_activeCursor ? Qt::SolidLine : Qt::DashLine); // the one the keys move is solid
        m_cursor[i]->setPen(pen);
        m_cursorLabel[i]->position->setCoords(m_cursorTime[i], 0);
        m_cursorLabel[i]->setVisible(true);
    }
    updateReadout();
    emit cursorsChanged();
    requestReplot();
}

void ScopePlot::setCursorsVisible(bool visible) {
    for (auto* c : m_cursor) c->setVisible(visible);
    for (auto* c : m_cursorLabel) c->setVisible(visible);
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

// Time: the span of every visible trace; each value axis: the whole span of its channel's visible traces.
// From the stores (O(log n) a channel): the graphs hold only what the last frame showed.
void ScopePlot::autoScale() {
    std::optional<ValueRange> time;
    std::vector<std::optional<ValueRange>> values(std::size_t(m_valueAxes.size()));
    // Each value axis over the channels drawn against it (one unit, or every channel when shared).
    const auto include = [this, &time, &values](const SeriesStore& store, const QList<ColumnGraph*>& graphs) {
        for (qsizetype c = 0; c < graphs.size() && std::size_t(c) < store.channelCount(); ++c) {
            const auto& samples = store.channel(std::size_t(c)).samples;
            if (!graphs[c]->visible() || samples.empty()) continue;
            widen(time, {samples.front().time_s, samples.back().time_s});
            const auto range = store.valueRange(std::size_t(c), samples.front().time_s, samples.back().time_s);
            const auto axis = std::size_t(m_valueAxes.indexOf(graphs[c]->valueAxis()));
            if (axis < values.size() && std::isfinite(range->minimum) && std::isfinite(range->maximum))
                widen(values[axis], *range); // QCPAxis::rescale skipped NaN too
        }
    };
    include(m_store, m_graphs);
    for (const Overlay& o : m_overlays) include(o.store, o.graphs);
    if (time) setFoundRange(m_plot->xAxis, *time);
    for (qsizetype c = 0; c < m_valueAxes.size(); ++c) {
        QCPAxis* axis = m_valueAxes[c];
        if (values[std::size_t(c)]) setFoundRange(axis, *values[std::size_t(c)]);
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
        // An axis of one channel takes its colour; one shared by several stays neutral (the legend tells them
        // apart).
        const auto index = std::size_t(m_valueAxes.indexOf(axis));
        const bool single = index < m_layout.axes.size() && m_layout.axes[index].channels.size() == 1;
        const QColor colour = single ? channelColour(m_layout.axes[index].channels.front()) : foreground;
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
    for (int i = 0; i < 2; ++i) {
        m_cursor[i]->setPen(QPen(cursor, 1, i == m_activeCursor ? Qt::SolidLine : Qt::DashLine));
        m_cursorLabel[i]->setColor(foreground);
        m_cursorLabel[i]->setBrush(QColor(background.red(), background.green(), background.blue(), 220));
    }
    m_readout->setStyleSheet(
        QStringLiteral("QLabel { color: %1; background: %2; }").arg(foreground.name(), background.name()));
    recolourOverlays();
    requestReplot();
}

bool ScopePlot::eventFilter(QObject* watched, QEvent* event) {
    if (watched != m_plot || event->type() != QEvent::KeyPress) return QWidget::eventFilter(watched, event);
    auto* key = static_cast<QKeyEvent*>(event);
    if (cursorKey(key->key(), key->modifiers())) return true;
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

// The cursor keys (cursor_keys.h); false for any other key. Space and the arrows act on shown cursors only.
bool ScopePlot::cursorKey(int key, Qt::KeyboardModifiers modifiers) {
    const bool shift = modifiers.testFlag(Qt::ShiftModifier);
    const bool ctrl = modifiers.testFlag(Qt::ControlModifier);
    CursorKey action;
    if (key == Qt::Key_C && !ctrl && !modifiers.testFlag(Qt::AltModifier))
        action = CursorKey::Place;
    else if (key == Qt::Key_Space && cursorsVisible())
        action = CursorKey::SwitchActive;
    else if ((key == Qt::Key_Left || key == Qt::Key_Right) && shift && cursorsVisible())
        action = key == Qt::Key_Left ? (ctrl ? CursorKey::JumpBack : CursorKey::StepBack)
                                     : (ctrl ? CursorKey::JumpForward : CursorKey::StepForward);
    else
        return false;
    const QCPRange x = m_plot->xAxis->range();
    const CursorView view{x.lower, x.upper, m_capture.channels.empty() ? 0.0 : m_capture.interval_s};
    const CursorPair moved = applyCursorKey({m_cursorTime[0], m_cursorTime[1], m_activeCursor}, action, view);
    m_activeCursor = moved.active;
    setCursors(moved.a_s, moved.b_s);
    return true;
}

void ScopePlot::onMousePress(QMouseEvent* event) {
    m_dragging = -1;
    if (!cursorsVisible()) return;
    for (int i = 0; i < 2; ++i) {
        if (std::abs(m_plot->xAxis->coordToPixel(m_cursorTime[i]) - event->position().x()) <= kCursorGrabPixels) {
            m_dragging = i;
            m_activeCursor = i; // the keys move the cursor last dragged
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
    m_activeCursor = std::abs(t - times[0]) <= std::abs(t - times[1]) ? 0 : 1;
    times[m_activeCursor] = t;
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
        svg.channels.push_back({&m_capture.channels[std::size_t(c)], m_graphs[c]->valueAxis()->range().lower,
                                m_graphs[c]->valueAxis()->range().upper,
                                channelColour(std::size_t(c)).name().toStdString()});
    svg.interval_s = m_capture.interval_s;
    svg.start_s = m_capture.start_s;
    QFile file(path);
    return file.open(QIODevice::WriteOnly | QIODevice::Truncate) &&
           file.write(QByteArray::fromStdString(writeSvg(svg))) > 0;
}

} // namespace scope
