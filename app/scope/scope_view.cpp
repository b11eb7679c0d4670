// ScopeView: toolbar, plot, measurements.
#include "scope_view.h"

#include "math_channel_dialog.h"
#include "measurements_table.h"

#include "scope/scope_plot.h"
#include "scope/xy_plot.h"

#include <QAction>
#include <QMenu>
#include <QSplitter>
#include <QTabWidget>
#include <QToolBar>
#include <QToolButton>
#include <QVBoxLayout>

namespace app {

ScopeView::ScopeView(QWidget* parent)
    : QWidget(parent), m_toolBar(new QToolBar(this)), m_plot(new scope::ScopePlot(this)),
      m_measurements(new MeasurementsTable(this)), m_overlayMenu(new QMenu(tr("Overlays"), this)),
      m_mathMenu(new QMenu(tr("Math"), this)) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(0);
    m_toolBar->setIconSize(QSize(16, 16));
    m_toolBar->setToolButtonStyle(Qt::ToolButtonTextOnly);
    layout->addWidget(m_toolBar);
    auto* split = new QSplitter(Qt::Vertical, this);
    // The same capture against time, and one channel against another (XY), as tabs.
    m_tabs = new QTabWidget(this);
    m_tabs->setObjectName(QStringLiteral("scopeTabs"));
    m_tabs->setDocumentMode(true);
    m_xy = new scope::XyPlot(m_tabs);
    m_tabs->addTab(m_plot, tr("Time"));
    m_tabs->addTab(m_xy, tr("XY"));
    split->addWidget(m_tabs);
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
    cursors->setToolTip(tr("Cursors A and B with \u0394t, 1/\u0394t and each channel's \u0394y. Double-click places "
                           "the nearer one, drag moves it. Keys (click the plot first): C places both, Space "
                           "switches A/B, Shift+Left/Right moves one sample, Ctrl+Shift+Left/Right a tenth of "
                           "the view."));
    connect(cursors, &QAction::toggled, m_plot, &scope::ScopePlot::setCursorsVisible);
    connect(m_plot, &scope::ScopePlot::cursorsChanged, cursors, [this, cursors] {
        const QSignalBlocker block(cursors);
        cursors->setChecked(m_plot->cursorsVisible());
    });
    QAction* perUnit = m_toolBar->addAction(tr("Axis per Unit"));
    perUnit->setObjectName(QStringLiteral("axisPerUnit"));
    perUnit->setCheckable(true);
    perUnit->setChecked(m_plot->axisMode() == scope::AxisMode::PerUnit);
    perUnit->setToolTip(tr("On: one value axis per unit (VEL, %, POS), each scaled to its own channels, so a "
                           "small current is not flattened by a large velocity. Off: one axis shared by all."));
    connect(perUnit, &QAction::toggled, m_plot,
            [this](bool on) { m_plot->setAxisMode(on ? scope::AxisMode::PerUnit : scope::AxisMode::Shared); });
    auto* overlays = new QToolButton(this);
    overlays->setText(tr("Overlays"));
    overlays->setMenu(m_overlayMenu);
    overlays->setPopupMode(QToolButton::InstantPopup);
    m_toolBar->addWidget(overlays);
    connect(m_plot, &scope::ScopePlot::overlaysChanged, this, &ScopeView::rebuildOverlayMenu);
    rebuildOverlayMenu();
    auto* math = new QToolButton(this);
    math->setObjectName(QStringLiteral("mathButton"));
    math->setText(tr("Math"));
    math->setToolTip(tr("Channels computed from the captured ones: A \u2212 B, k\u00b7A, d/dt, \u222b, moving average, "
                        "following error. Kept, recomputed, for the next capture of the same channels."));
    math->setMenu(m_mathMenu);
    math->setPopupMode(QToolButton::InstantPopup);
    m_toolBar->addWidget(math);
    rebuildMathMenu();
}

void ScopeView::showCapture(const scope::Capture& capture, bool keepPrevious) {
    m_raw = capture;
    const MathChannelList::Applied shown = m_math.apply(capture, scope::ScopePlot::kMaxChannels);
    m_skipped = shown.skipped;
    m_plot->showCapture(shown.capture, keepPrevious);
    m_xy->showCapture(shown.capture);
    m_measurements->showMeasurements(shown.capture);
    rebuildMathMenu();
}

scope::Capture ScopeView::withMath(const scope::Capture& capture) const {
    return m_math.apply(capture, scope::ScopePlot::kMaxChannels).capture;
}

MathChannelDialog* ScopeView::openMathDialog() {
    const scope::Capture& shown = m_plot->capture();
    auto* dialog = new MathChannelDialog(shown, scope::ScopePlot::kMaxChannels - int(shown.channels.size()), this);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    connect(dialog, &QDialog::accepted, this, [this, dialog] { addMathChannel(dialog->spec()); });
    dialog->open();
    return dialog;
}

bool ScopeView::addMathChannel(const scope::MathChannelSpec& spec) {
    if (spec.name.empty() || m_math.contains(QString::fromStdString(spec.name))) return false;
    m_math.add(spec);
    reshowWithMath();
    return true;
}

bool ScopeView::removeMathChannel(const QString& name) {
    if (!m_math.remove(name)) return false;
    reshowWithMath();
    return true;
}

// The same capture again, with the math channels as they are now; the overlays stay.
void ScopeView::reshowWithMath() {
    const MathChannelList::Applied shown = m_math.apply(m_raw, scope::ScopePlot::kMaxChannels);
    m_skipped = shown.skipped;
    m_plot->replaceCapture(shown.capture);
    m_xy->showCapture(shown.capture);
    m_measurements->showMeasurements(shown.capture);
    rebuildMathMenu();
    emit mathChannelsChanged();
}

void ScopeView::rebuildMathMenu() {
    m_mathMenu->clear();
    QAction* add = m_mathMenu->addAction(tr("Add Math Channel..."), this, &ScopeView::openMathDialog);
    add->setEnabled(!m_plot->capture().channels.empty());
    if (!m_math.isEmpty()) m_mathMenu->addSeparator();
    for (const scope::MathChannelSpec& spec : m_math.specs()) {
        const QString name = QString::fromStdString(spec.name);
        QString notShown;
        for (const QString& why : m_skipped)
            if (why.startsWith(name + QLatin1String(": "))) notShown = why;
        QAction* remove = m_mathMenu->addAction(notShown.isEmpty() ? tr("Remove %1").arg(name)
                                                                    : tr("Remove %1 (not shown)").arg(name));
        remove->setToolTip(notShown);
        connect(remove, &QAction::triggered, this, [this, name] { removeMathChannel(name); });
    }
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
