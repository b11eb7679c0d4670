// ScopeExport: what Scope > Save CSV and Export Plot write — the whole record, or only the visible range (the
// samples inside the time axis' range, with their own times, in the same .CSV layout so the file loads back;
// the plot as it is zoomed for PNG, SVG and PDF). The choice is the Scope menu's Export Range. GUI thread only.
#pragma once

#include "scope/capture.h"

#include <QObject>

class QAction;
class QMenu;

namespace app {

class ScopeView;

enum class ExportRange { WholeRecord, VisibleRange };

class ScopeExport final : public QObject {
    Q_OBJECT
public:
    ScopeExport(ScopeView& view, QObject* parent);

    // "Export Range" with its two exclusive choices, added to the menu (objectNames exportWholeRecord and
    // exportVisibleRange, for tests).
    void addRangeChoice(QMenu* menu);
    ExportRange range() const;
    void setRange(ExportRange range);

    // The capture a .CSV gets: whole as given, or the samples inside the plot's time axis.
    scope::Capture forCsv(const scope::Capture& whole) const;
    // The plot as PNG, SVG or PDF by the path's suffix. For the whole record the plot is fitted to it for the
    // export and put back as it was after.
    bool savePlot(const QString& path);
    // " (visible range)" or "", for status messages.
    QString rangeNote() const;

private:
    ScopeView& m_view;
    QAction* m_whole;
    QAction* m_visible;
};

} // namespace app
