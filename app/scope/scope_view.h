// ScopeView: a ScopePlot with its toolbar (auto-scale, grid, dark, cursors, overlays to toggle) and the
// measurements table under it. The Scope dock holds one; the tuning panel holds another. GUI thread only.
#pragma once

#include "scope/capture.h"

#include <QWidget>

class QMenu;
class QToolBar;

namespace scope {
class ScopePlot;
}

namespace app {

class MeasurementsTable;

class ScopeView final : public QWidget {
    Q_OBJECT
public:
    explicit ScopeView(QWidget* parent = nullptr);

    // Plots the capture (keepPrevious: the one shown so far stays as an overlay) and measures it.
    void showCapture(const scope::Capture& capture, bool keepPrevious = false);
    scope::ScopePlot* plot() const { return m_plot; }
    MeasurementsTable* measurements() const { return m_measurements; }
    QToolBar* toolBar() const { return m_toolBar; }

private:
    void rebuildOverlayMenu();

    QToolBar* m_toolBar;
    scope::ScopePlot* m_plot;
    MeasurementsTable* m_measurements;
    QMenu* m_overlayMenu;
};

} // namespace app
