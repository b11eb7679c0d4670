// ScopeView: toolbar, plot, measurements.
#include "scope_view.h"

#include "measurements_table.h"

#include "scope/scope_plot.h"

#include <QAction>
#include <QMenu>
#include <QSplitter>
#include <QToolBar>
#include <QToolButton>
#include <QVBoxLayout>

namespace app {

ScopeView::ScopeView(QWidget* parent)
    : QWidget(parent), m_toolBar(new QToolBar(this)), m_plot(new scope::ScopePlot(this)),
      m_measurements(new MeasurementsTable(this)), m_overlayMenu(new QMenu(tr("Overlays"), this)) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(0);
    m_toolBar->setIconSize(QSize(16, 16));
    m_toolBar->setToolButtonStyle(Qt::ToolButtonTextOnly);
    layout->addWidget(m_toolBar);
    auto* split = new QSplitter(Qt::Vertical, this);
    split->addWidget(m_plot);
    split->addWidget(m_measurements);
    split->setStretchFactor(0, 4);
    split->setStretchFactor(1, 1);
    split->setSizes({800, 200}); // the plot first: the table's size hint would otherwise take half
    layout->addWidget(split, 1);

    QAction* fit = m_toolBar->addAction(tr("Auto-scale"), m_plot, &scope::ScopePlot::autoScale);
    fit->setToolTip(tr("Fit every channel (Home or A in the plot). Drag to pan, wheel to zoom time, "
                       "+/- and arrow keys too."));
    QAction* grid = m_toolBar->addAction(tr("Grid"));
    grid->setCheckable(true);
    grid->setChecked(true);
    connect(grid, &QAction::toggled, m_plot, &scope::ScopePlot::setGridVisible);
    QAction* dark = m_toolBar->addAction(tr("Dark"));
    dark->setCheckable(true);
    connect(dark, &QAction::toggled, m_plot, &scope::ScopePlot::setDarkTheme);
    QAction* cursors = m_toolBar->addAction(tr("Cursors"));
    cursors->setCheckable(true);
    cursors->setToolTip(tr("Two cursors with \u0394t and \u0394y; double-click places the nearer one, drag moves it."));
    connect(cursors, &QAction::toggled, m_plot, &scope::ScopePlot::setCursorsVisible);
    connect(m_plot, &scope::ScopePlot::cursorsChanged, cursors, [this, cursors] {
        const QSignalBlocker block(cursors);
        cursors->setChecked(m_plot->cursorsVisible());
    });
    auto* overlays = new QToolButton(this);
    overlays->setText(tr("Overlays"));
    overlays->setMenu(m_overlayMenu);
    overlays->setPopupMode(QToolButton::InstantPopup);
    m_toolBar->addWidget(overlays);
    connect(m_plot, &scope::ScopePlot::overlaysChanged, this, &ScopeView::rebuildOverlayMenu);
    rebuildOverlayMenu();
}

void ScopeView::showCapture(const scope::Capture& capture, bool keepPrevious) {
    m_plot->showCapture(capture, keepPrevious);
    m_measurements->showMeasurements(capture);
}

void ScopeView::rebuildOverlayMenu() {
    m_overlayMenu->clear();
    if (m_plot->overlayCount() == 0) m_overlayMenu->addAction(tr("(no earlier captures)"))->setEnabled(false);
    for (int i = 0; i < m_plot->overlayCount(); ++i) {
        QAction* a = m_overlayMenu->addAction(m_plot->overlayTitle(i).isEmpty() ? tr("Capture %1 back").arg(i + 1)
                                                                                : m_plot->overlayTitle(i));
        a->setCheckable(true);
        a->setChecked(m_plot->isOverlayVisible(i));
        connect(a, &QAction::toggled, this, [this, i](bool on) { m_plot->setOverlayVisible(i, on); });
    }
}

} // namespace app
