// WatchView: chooser, buttons and the incremental rolling chart.
#include "watch_view.h"

#include "variable_watcher.h"
#include "watch_source.h"

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
      m_rate(new QLabel(this)), m_plot(new QCustomPlot(this)) {
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

    auto* buttons = new QHBoxLayout;
    buttons->addWidget(m_start);
    buttons->addWidget(m_stop);
    buttons->addWidget(m_rate, 1);
    auto* right = new QVBoxLayout;
    right->addWidget(m_plot, 1);
    right->addLayout(buttons);
    auto* layout = new QHBoxLayout(this);
    layout->addWidget(m_chooser);
    layout->addLayout(right, 1);
    resize(820, 420);

    connect(m_start, &QPushButton::clicked, this, &WatchView::start);
    connect(m_stop, &QPushButton::clicked, this, &WatchView::stop);
    connect(m_watcher, &VariableWatcher::sampled, this, &WatchView::onSampled);
    connect(m_watcher, &VariableWatcher::stateChanged, this, &WatchView::updateState);
    connect(m_watcher, &VariableWatcher::message, m_rate, &QLabel::setText);
    connect(this, &QDialog::finished, this, &WatchView::stop); // closing the window stops the polls
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
    m_watcher->start();
}

void WatchView::stop() {
    m_watcher->stop();
}

// Appends only the new samples and drops what left the window: the graphs are never rebuilt.
void WatchView::onSampled(double time_s) {
    const scope::SeriesStore& store = m_watcher->store();
    QList<QCPAxis*> scaled; // each axis fits its first graph, then grows to hold the others on it
    for (int g = 0; g < m_plot->graphCount() && std::size_t(g) < store.channelCount(); ++g) {
        const auto& s = store.channel(std::size_t(g)).samples;
        for (auto it = s.rbegin(); it != s.rend() && it->time_s > m_plottedUntil_s; ++it)
            m_plot->graph(g)->addData(it->time_s, it->value); // addData keeps the graph sorted by key
        m_plot->graph(g)->data()->removeBefore(time_s - VariableWatcher::kWindow_s);
        QCPAxis* y = m_plot->graph(g)->valueAxis();
        m_plot->graph(g)->rescaleValueAxis(scaled.contains(y), true);
        scaled.append(y);
    }
    m_plottedUntil_s = time_s;
    m_plot->xAxis->setRange(std::max(0.0, time_s - VariableWatcher::kWindow_s), std::max(time_s, 1.0));
    for (QCPAxis* y : {m_plot->yAxis, m_plot->yAxis2}) {
        if (y->range().size() == 0) y->setRange(y->range().lower - 1, y->range().upper + 1);
        else y->scaleRange(1.08, y->range().center()); // a margin: a trace on the frame is hard to see
    }
    m_rate->setText(m_watcher->rateText());
    m_plot->replot(QCustomPlot::rpQueuedReplot);
}

void WatchView::updateState() {
    const bool running = m_watcher->isRunning();
    m_start->setEnabled(!running);
    m_stop->setEnabled(running);
    m_chooser->setEnabled(!running);
    if (m_watcher->isPaused() || !running) m_rate->setText(running ? m_watcher->rateText() : tr("stopped"));
}

} // namespace app
