// WatchView: chooser, buttons and the incremental rolling chart.
#include "watch_view.h"

#include "trigger_bar.h"
#include "variable_watcher.h"
#include "watch_source.h"
#include "watch_trigger.h"

#include <qcustomplot.h>

#include <QHBoxLayout>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QVBoxLayout>

namespace app {

namespace {
constexpr int kMaxVariables = 4;
const QColor kColours[] = {QColor(0x1f, 0x77, 0xb4), QColor(0xd6, 0x27, 0x28), QColor(0x2c, 0xa0, 0x2c),
                           QColor(0x94, 0x67, 0xbd)};
} // namespace

WatchView::WatchView(WatchSource* source, QWidget* parent)
    : QDialog(parent), m_watcher(new VariableWatcher(*source, this)), m_chooser(new QListWidget(this)),
      m_start(new QPushButton(tr("&Start"), this)), m_stop(new QPushButton(tr("S&top"), this)),
      m_rate(new QLabel(this)), m_plot(new QCustomPlot(this)), m_triggerBar(new TriggerBar(this)),
      m_trigger(new WatchTrigger(*m_watcher, this)), m_triggerLine(new QCPItemStraightLine(m_plot)),
      m_levelLine(new QCPItemStraightLine(m_plot)), m_triggerMark(new QCPItemText(m_plot)) {
    setObjectName(QStringLiteral("watchView"));
    source->setParent(this);
    setWindowTitle(tr("Watch Variables \u2014 %1").arg(source->familyName()));
    for (const WatchSource::Choice& choice : source->choices()) {
        auto* item = new QListWidgetItem(choice.label, m_chooser);
        item->setData(Qt::UserRole, choice.name);
        item->setFlags(item->flags() | Qt::ItemIsUserCheckable);
        item->setCheckState(Qt::Unchecked);
    }
    m_chooser->setMaximumWidth(source->familyName() == QLatin1String("BDS5") ? 140 : 190);
    m_chooser->setToolTip(tr("Tick up to %1 variables. %2").arg(kMaxVariables).arg(source->method()));
    m_plot->setMinimumSize(480, 300);
    m_plot->xAxis->setLabel(tr("time [s]"));
    m_plot->axisRect()->setupFullAxesBox(false);
    m_plot->legend->setVisible(true);
    m_plot->setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
    m_triggerLine->setPen(QPen(QColor(0xe0, 0x7b, 0x00), 1.4, Qt::DashLine));
    m_triggerLine->point1->setCoords(0, 0);
    m_triggerLine->point2->setCoords(0, 1);
    m_levelLine->setPen(QPen(QColor(0xe0, 0x7b, 0x00), 1, Qt::DotLine));
    m_triggerMark->setText(tr("\u25bc trigger"));
    m_triggerMark->setColor(QColor(0xb0, 0x5a, 0x00));
    m_triggerMark->setPositionAlignment(Qt::AlignLeft | Qt::AlignTop); // beside the line, not over it
    m_triggerMark->setPadding(QMargins(4, 2, 0, 0));
    m_triggerMark->position->setTypeX(QCPItemPosition::ptPlotCoords);
    m_triggerMark->position->setTypeY(QCPItemPosition::ptAxisRectRatio);
    m_triggerMark->position->setCoords(0, 0.01);
    for (QCPAbstractItem* item : std::initializer_list<QCPAbstractItem*>{m_triggerLine, m_levelLine, m_triggerMark})
        item->setVisible(false);

    auto* buttons = new QHBoxLayout;
    buttons->addWidget(m_start);
    buttons->addWidget(m_stop);
    buttons->addWidget(m_rate, 1);
    auto* right = new QVBoxLayout;
    right->addWidget(m_plot, 1);
    right->addLayout(buttons);
    right->addWidget(m_triggerBar);
    auto* layout = new QHBoxLayout(this);
    layout->addWidget(m_chooser);
    layout->addLayout(right, 1);
    resize(940, 540);

    connect(m_start, &QPushButton::clicked, this, &WatchView::start);
    connect(m_stop, &QPushButton::clicked, this, &WatchView::stop);
    connect(m_watcher, &VariableWatcher::sampled, this, &WatchView::onSampled);
    connect(m_watcher, &VariableWatcher::stateChanged, this, &WatchView::updateState);
    connect(m_watcher, &VariableWatcher::message, m_rate, &QLabel::setText);
    connect(this, &QDialog::finished, this, &WatchView::stop); // closing the window stops the polls
    connect(m_chooser, &QListWidget::itemChanged, this, [this] {
        QStringList ticked;
        for (int i = 0; i < m_chooser->count(); ++i)
            if (m_chooser->item(i)->checkState() == Qt::Checked) ticked << m_chooser->item(i)->text();
        if (!m_watcher->isRunning()) m_triggerBar->setSources(ticked);
    });
    connect(m_triggerBar, &TriggerBar::settingsChanged, this, &WatchView::onTriggerSettings);
    connect(m_triggerBar, &TriggerBar::armClicked, this, &WatchView::arm);
    connect(m_trigger, &WatchTrigger::frameReady, this, &WatchView::showFrame);
    connect(m_trigger, &WatchTrigger::statusChanged, this,
            [this] { m_triggerBar->setState(m_trigger->statusText()); });
    updateState();
}

QString WatchView::rateLabel() const {
    return m_rate->text();
}

void WatchView::watch(const QStringList& names) {
    for (int i = 0; i < m_chooser->count(); ++i) {
        QListWidgetItem* item = m_chooser->item(i);
        const bool wanted = names.contains(item->data(Qt::UserRole).toString(), Qt::CaseInsensitive) ||
                            names.contains(item->text(), Qt::CaseInsensitive);
        item->setCheckState(wanted ? Qt::Checked : Qt::Unchecked);
    }
    start();
}

void WatchView::start() {
    QStringList names;
    for (int i = 0; i < m_chooser->count(); ++i)
        if (m_chooser->item(i)->checkState() == Qt::Checked) names << m_chooser->item(i)->data(Qt::UserRole).toString();
    if (names.size() > kMaxVariables) {
        m_rate->setText(tr("At most %1 variables: the more a poll asks for, the slower each sample.").arg(kMaxVariables));
        return;
    }
    m_watcher->setVariables(names);
    m_plot->clearGraphs();
    m_plottedUntil_s = -1;
    for (int i = 0; i < names.size(); ++i) {
        // The first variable on the left axis, the second on the right, the others share the left one.
        QCPAxis* y = i == 1 ? m_plot->yAxis2 : m_plot->yAxis;
        QCPGraph* graph = m_plot->addGraph(m_plot->xAxis, y);
        const auto choice = m_watcher->source().choice(names[i]);
        const QString label = choice ? choice->label : names[i];
        const QString unit = choice ? choice->unit : QString();
        graph->setName(unit.isEmpty() ? label : QStringLiteral("%1 [%2]").arg(label, unit));
        graph->setPen(QPen(kColours[i % kMaxVariables], 1.6));
        graph->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssDisc, 4));
        y->setLabel(graph->name());
    }
    m_plot->yAxis2->setTickLabels(names.size() > 1);
    QStringList labels;
    for (int g = 0; g < m_plot->graphCount(); ++g) labels << m_plot->graph(g)->name();
    m_triggerBar->setSources(labels);
    m_watcher->start();
    showRolling();
    m_trigger->setSettings(m_triggerBar->settings());
    if (m_watcher->isRunning()) m_trigger->arm();
}

void WatchView::stop() {
    m_watcher->stop();
    m_trigger->stop();
}

// Arm: a new frame (Single's next one), starting the polls if they were stopped.
void WatchView::arm() {
    if (!m_watcher->isRunning()) return start();
    m_trigger->setSettings(m_triggerBar->settings());
    m_trigger->arm();
}

// As on a scope, a change of the trigger takes effect at once: re-armed while watching; Off rolls again.
void WatchView::onTriggerSettings() {
    m_trigger->setSettings(m_triggerBar->settings());
    if (!m_triggerBar->settings()) showRolling();
    if (m_watcher->isRunning()) m_trigger->arm();
    else m_triggerBar->setState(m_trigger->statusText());
}

// The graphs again from the rolling window's samples (onSampled adds all of them after this).
void WatchView::showRolling() {
    if (!m_frameShown) return;
    m_frameShown = false;
    for (int g = 0; g < m_plot->graphCount(); ++g) m_plot->graph(g)->data()->clear();
    m_plottedUntil_s = -1;
    m_plot->xAxis->setLabel(tr("time [s]"));
    for (QCPAbstractItem* item : std::initializer_list<QCPAbstractItem*>{m_triggerLine, m_levelLine, m_triggerMark})
        item->setVisible(false);
    m_plot->replot(QCustomPlot::rpQueuedReplot);
}

// A frame replaces what the graphs hold; its times count from the trigger, so the trigger sample is at 0.
void WatchView::showFrame(const scope::TriggerFrame& frame) {
    m_frameShown = true;
    for (int g = 0; g < m_plot->graphCount() && std::size_t(g) < frame.values.size(); ++g) {
        QVector<double> keys, values;
        for (std::size_t i = 0; i < frame.time_s.size(); ++i) {
            keys << frame.time_s[i] - frame.trigger_s;
            values << frame.values[std::size_t(g)][i];
        }
        m_plot->graph(g)->setData(keys, values, true);
    }
    m_plot->xAxis->setLabel(frame.triggered ? tr("time from the trigger [s]") : tr("time from the forced trigger [s]"));
    m_plot->xAxis->setRange(frame.time_s.front() - frame.trigger_s, frame.time_s.back() - frame.trigger_s);
    fitValueAxes();
    const auto settings = m_trigger->settings();
    const int source = settings ? int(settings->channel) : 0;
    m_triggerLine->setVisible(true);
    m_triggerMark->setVisible(true);
    const bool level = settings && settings->kind == scope::TriggerKind::Level && source < m_plot->graphCount();
    m_levelLine->setVisible(level);
    if (level) {
        m_levelLine->point1->setAxes(m_plot->xAxis, m_plot->graph(source)->valueAxis());
        m_levelLine->point2->setAxes(m_plot->xAxis, m_plot->graph(source)->valueAxis());
        m_levelLine->point1->setCoords(0, settings->level);
        m_levelLine->point2->setCoords(1, settings->level);
    }
    m_plot->replot(QCustomPlot::rpQueuedReplot);
}

// Appends only the new samples and drops what left the window: the graphs are never rebuilt.
void WatchView::onSampled(double time_s) {
    m_rate->setText(m_watcher->rateText());
    if (m_frameShown) return; // a triggered frame holds the chart until the next one
    const scope::SeriesStore& store = m_watcher->store();
    for (int g = 0; g < m_plot->graphCount() && std::size_t(g) < store.channelCount(); ++g) {
        const auto& s = store.channel(std::size_t(g)).samples;
        for (auto it = s.rbegin(); it != s.rend() && it->time_s > m_plottedUntil_s; ++it)
            m_plot->graph(g)->addData(it->time_s, it->value); // addData keeps the graph sorted by key
        m_plot->graph(g)->data()->removeBefore(time_s - VariableWatcher::kWindow_s);
    }
    m_plottedUntil_s = time_s;
    m_plot->xAxis->setRange(std::max(0.0, time_s - VariableWatcher::kWindow_s), std::max(time_s, 1.0));
    fitValueAxes();
    m_plot->replot(QCustomPlot::rpQueuedReplot);
}

void WatchView::fitValueAxes() {
    QList<QCPAxis*> scaled; // each axis fits its first graph, then grows to hold the others on it
    for (int g = 0; g < m_plot->graphCount(); ++g) {
        QCPAxis* y = m_plot->graph(g)->valueAxis();
        m_plot->graph(g)->rescaleValueAxis(scaled.contains(y), true);
        scaled.append(y);
    }
    for (QCPAxis* y : {m_plot->yAxis, m_plot->yAxis2}) {
        if (y->range().size() == 0) y->setRange(y->range().lower - 1, y->range().upper + 1);
        else y->scaleRange(1.08, y->range().center()); // a margin: a trace on the frame is hard to see
    }
}

void WatchView::updateState() {
    const bool running = m_watcher->isRunning();
    m_start->setEnabled(!running);
    m_stop->setEnabled(running);
    m_chooser->setEnabled(!running);
    if (m_watcher->isPaused() || !running) m_rate->setText(running ? m_watcher->rateText() : tr("stopped"));
}

} // namespace app
