// ScopeView: a ScopePlot with its toolbar (auto-scale, grid, dark, cursors, axis per unit, overlays to toggle,
// math channels), an XY tab beside it, and the measurements table under them. The Scope dock holds one; the tuning panel holds another. GUI thread only.
#pragma once

#include "math_channel_list.h"

#include "scope/capture.h"

#include <QWidget>

class QMenu;
class QTabWidget;
class QToolBar;

namespace scope {
class ScopePlot;
class XyPlot;
}

namespace app {

class MathChannelDialog;
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
    // The Time and XY tabs; the XY plot shows every capture the time plot does.
    QTabWidget* tabs() const { return m_tabs; }
    scope::XyPlot* xyPlot() const { return m_xy; }

    // Math channels (Math on the toolbar), added to every capture shown and recomputed for each.
    MathChannelDialog* openMathDialog(); // non-modal; its channel is added when the user presses Add
    bool addMathChannel(const scope::MathChannelSpec& spec); // spec.name set; false if that name is shown
    bool removeMathChannel(const QString& name);
    const MathChannelList& mathChannels() const { return m_math; }
    const QStringList& skippedMathChannels() const { return m_skipped; } // not shown, with why
    // capture with the math channels appended, as the plot shows it (for the .CSV and the data table).
    scope::Capture withMath(const scope::Capture& capture) const;

signals:
    void mathChannelsChanged(); // one was added or removed (the spectrum offers them too)

private:
    void rebuildOverlayMenu();
    void rebuildMathMenu();
    void reshowWithMath();

    QToolBar* m_toolBar;
    scope::ScopePlot* m_plot;
    MeasurementsTable* m_measurements;
    QMenu* m_overlayMenu;
    QTabWidget* m_tabs = nullptr;
    scope::XyPlot* m_xy = nullptr;
    QMenu* m_mathMenu;
    MathChannelList m_math;
    scope::Capture m_raw; // the capture shown, without its math channels
    QStringList m_skipped;
};

} // namespace app
