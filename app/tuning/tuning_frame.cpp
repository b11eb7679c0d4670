// The shared frame of the Tuning docks.
#include "tuning_frame.h"

#include "app/scope/scope_view.h"
#include "scope/signal_analysis.h"

#include <QColor>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QScrollArea>
#include <QSplitter>
#include <QTableWidget>
#include <QVBoxLayout>

namespace app {

void layOutTuningFrame(QWidget* panel, QWidget* controls, ScopeView* view, QTableWidget* runs,
                       const QList<QPushButton*>& runButtons) {
    auto* scroll = new QScrollArea(panel);
    scroll->setWidget(controls);
    scroll->setWidgetResizable(true);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    scroll->setMinimumWidth(340);
    scroll->setMaximumWidth(400);

    auto* runsBox = new QWidget(panel);
    auto* runsLayout = new QVBoxLayout(runsBox);
    runsLayout->setContentsMargins(0, 0, 0, 0);
    runsLayout->addWidget(runs, 1);
    auto* buttons = new QHBoxLayout;
    for (QPushButton* b : runButtons) buttons->addWidget(b);
    buttons->addStretch(1);
    runsLayout->addLayout(buttons);

    auto* right = new QSplitter(Qt::Vertical, panel);
    right->addWidget(view);
    right->addWidget(runsBox);
    right->setStretchFactor(0, 3);
    right->setStretchFactor(1, 1);
    auto* layout = new QHBoxLayout(panel);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(scroll);
    layout->addWidget(right, 1);
}

void setUpRunsTable(QTableWidget* runs, const QStringList& columns) {
    runs->setColumnCount(int(columns.size()));
    runs->setHorizontalHeaderLabels(columns);
    runs->verticalHeader()->hide();
    runs->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    runs->horizontalHeader()->setStretchLastSection(true);
    runs->setEditTriggers(QAbstractItemView::NoEditTriggers);
    runs->setSelectionBehavior(QAbstractItemView::SelectRows);
    runs->setSelectionMode(QAbstractItemView::SingleSelection);
}

ControlGroup addControlGroup(QWidget* panel, const QString& title) {
    auto* box = new QGroupBox(title, panel);
    return {box, new QFormLayout(box)};
}

void addRow(const ControlGroup& group, QWidget* row) {
    group.form->addRow(row);
}

RunButtons addRunButtons(QWidget* box, QFormLayout* form) {
    RunButtons b;
    b.once = new QPushButton(QObject::tr("Run Once"), box);
    b.loop = new QPushButton(QObject::tr("Run Continuously"), box);
    b.stop = new QPushButton(QObject::tr("Stop"), box);
    auto* row = new QHBoxLayout;
    row->addWidget(b.once);
    row->addWidget(b.loop);
    row->addWidget(b.stop);
    form->addRow(row);
    return b;
}

void RunButtons::update(bool running, bool continuous, bool stoppable) const {
    once->setEnabled(!running);
    loop->setEnabled(!continuous);
    stop->setEnabled(stoppable);
}

QLabel* addStatusLine(QWidget* box, QFormLayout* form, const QString& objectName) {
    auto* status = new QLabel(box);
    status->setObjectName(objectName);
    status->setWordWrap(true);
    form->addRow(status);
    return status;
}

void appendRun(QTableWidget* runs, const RunRow& row) {
    const int at = runs->rowCount();
    runs->insertRow(at);
    for (int c = 0; c < int(row.cells.size()); ++c) {
        auto* item = new QTableWidgetItem(row.cells[c]);
        item->setTextAlignment(row.leftAligned.contains(c) ? Qt::AlignLeft | Qt::AlignVCenter
                                                           : Qt::AlignRight | Qt::AlignVCenter);
        if (!row.fault.isEmpty()) {
            item->setForeground(QColor(0xb0, 0x00, 0x20));
            item->setToolTip(row.fault);
        }
        runs->setItem(at, c, item);
    }
    runs->scrollToBottom();
}

int selectedRunNumber(const QTableWidget* runs) {
    const int row = runs->currentRow();
    const QTableWidgetItem* item = row >= 0 ? runs->item(row, 0) : nullptr;
    return item ? item->text().toInt() : 0;
}

QString milliseconds(const std::optional<double>& seconds) {
    return seconds ? QString::number(*seconds * 1000, 'f', 1) : QStringLiteral("\u2014");
}

QString stepSummary(int runNumber, const scope::StepMetrics& metrics) {
    return QObject::tr("Run %1: overshoot %2 %, rise %3 ms, settle %4 ms.")
        .arg(runNumber)
        .arg(metrics.overshoot_pct, 0, 'f', 1)
        .arg(milliseconds(metrics.rise_s), milliseconds(metrics.settling_s));
}

} // namespace app
