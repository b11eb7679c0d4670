// ScopeExport: the range choice, the .CSV slice and the plot files.
#include "scope_export.h"

#include "scope_view.h"

#include "scope/capture_slice.h"
#include "scope/scope_plot.h"

#include <qcustomplot.h>

#include <QActionGroup>
#include <QFileInfo>
#include <QMenu>

namespace app {

ScopeExport::ScopeExport(ScopeView& view, QObject* parent)
    : QObject(parent), m_view(view), m_whole(new QAction(tr("&Whole Record"), this)),
      m_visible(new QAction(tr("&Visible Range Only"), this)) {
    m_whole->setObjectName(QStringLiteral("exportWholeRecord"));
    m_visible->setObjectName(QStringLiteral("exportVisibleRange"));
    m_whole->setToolTip(tr("Save CSV and Export Plot write every sample of the capture."));
    m_visible->setToolTip(tr("Save CSV writes only the samples inside the plot's time axis, with their times "
                             "(the file loads back where it was cut); Export Plot writes the plot as zoomed."));
    auto* group = new QActionGroup(this);
    for (QAction* a : {m_whole, m_visible}) {
        a->setCheckable(true);
        group->addAction(a);
    }
    m_whole->setChecked(true);
}

void ScopeExport::addRangeChoice(QMenu* menu) {
    QMenu* sub = menu->addMenu(tr("Export Ran&ge"));
    sub->setObjectName(QStringLiteral("exportRangeMenu"));
    sub->setToolTipsVisible(true);
    sub->addAction(m_whole);
    sub->addAction(m_visible);
}

ExportRange ScopeExport::range() const {
    return m_visible->isChecked() ? ExportRange::VisibleRange : ExportRange::WholeRecord;
}

void ScopeExport::setRange(ExportRange range) {
    (range == ExportRange::VisibleRange ? m_visible : m_whole)->setChecked(true);
}

QString ScopeExport::rangeNote() const {
    return range() == ExportRange::VisibleRange ? tr(" (visible range)") : QString();
}

scope::Capture ScopeExport::forCsv(const scope::Capture& whole) const {
    if (range() == ExportRange::WholeRecord) return whole;
    const QCPRange x = m_view.plot()->customPlot()->xAxis->range();
    return scope::sliceCapture(whole, x.lower, x.upper);
}

bool ScopeExport::savePlot(const QString& path) {
    scope::ScopePlot* plot = m_view.plot();
    // Every axis's range, to put the user's zoom back after a whole-record export.
    QList<QPair<QCPAxis*, QCPRange>> zoom;
    if (range() == ExportRange::WholeRecord) {
        for (QCPAxis* axis : plot->customPlot()->axisRect()->axes()) zoom.append({axis, axis->range()});
        plot->autoScale();
    }
    const QString suffix = QFileInfo(path).suffix().toLower();
    const bool ok = suffix == QLatin1String("png")   ? plot->savePng(path)
                    : suffix == QLatin1String("svg") ? plot->saveSvg(path)
                                                     : plot->savePdf(path);
    for (const auto& [axis, r] : zoom) axis->setRange(r);
    if (!zoom.isEmpty()) plot->customPlot()->replot(QCustomPlot::rpQueuedReplot);
    return ok;
}

} // namespace app
