// ScopePlot: the thin QCustomPlot view over a SeriesStore. Up to 4 channels, each on its own y-axis with
// its unit; legend; mouse and key zoom/pan; two draggable cursors with a Δt/Δy readout; auto-scale; grid;
// light/dark; the last N captures kept as overlays in fading colours, each one toggleable. Data is appended
// incrementally (appendLive) and replots are coalesced (rpQueuedReplot); a hidden plot does not replot.
// GUI thread only.
#pragma once

#include "capture.h"
#include "cursor_readout.h"
#include "series_store.h"

#include <QTimer>
#include <QWidget>

#include <deque>

class QCPAxis;
class QCPGraph;
class QCPItemStraightLine;
class QCustomPlot;
class QLabel;
class QMouseEvent;

namespace scope {

class ScopePlot final : public QWidget {
    Q_OBJECT
public:
    static constexpr int kMaxChannels = 4;

    explicit ScopePlot(QWidget* parent = nullptr);
    ~ScopePlot() override;

    QCustomPlot* customPlot() const { return m_plot; }

    // Shows a capture as the current trace. keepPrevious: the trace shown so far becomes the newest
    // overlay (the oldest beyond maxOverlays() goes); otherwise every overlay is dropped.
    void showCapture(const Capture& capture, bool keepPrevious = false);
    const Capture& capture() const { return m_capture; }
    void clear();

    // Live data: channels without a fixed interval, appended as they come (seconds, drive units).
    void beginLive(const std::vector<std::pair<std::string, std::string>>& namesAndUnits);
    void appendLive(std::size_t channel, double time_s, double value);
    const SeriesStore& store() const { return m_store; }
    // Points in the current trace's graph of a channel (what the plot holds, for tests).
    int pointCount(std::size_t channel) const;

    int overlayCount() const { return int(m_overlays.size()); }
    QString overlayTitle(int index) const; // 0 is the newest
    bool isOverlayVisible(int index) const;
    void setOverlayVisible(int index, bool visible);
    void setMaxOverlays(int count);
    int maxOverlays() const { return m_maxOverlays; }

    void setCursors(double first_s, double second_s);
    void setCursorsVisible(bool visible);
    bool cursorsVisible() const;
    // What the line under the plot shows, kept current as the cursors move, a trace is shown or live data arrive.
    CursorReadout readout() const;

    void autoScale();
    void setGridVisible(bool visible);
    void setDarkTheme(bool dark);
    bool isDarkTheme() const { return m_dark; }

    // Exports of what is shown; sizes in pixels (0: the widget's size).
    bool savePng(const QString& path, int width = 0, int height = 0);
    bool savePdf(const QString& path, int width = 0, int height = 0);
    bool saveSvg(const QString& path, int width = 0, int height = 0);

signals:
    void cursorsChanged();
    void overlaysChanged();

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;
    void showEvent(QShowEvent* event) override;

private:
    struct Overlay {
        QString title;
        QList<QCPGraph*> graphs;
        bool visible = true;
    };

    void ensureAxes(std::size_t count);
    QCPGraph* addGraph(std::size_t channel);
    void syncFromStore();
    void scheduleSync();
    void requestReplot();
    void applyTheme();
    void recolourOverlays();
    void updateReadout();
    void onMousePress(QMouseEvent* event);
    void onMouseMove(QMouseEvent* event);
    void onMouseRelease(QMouseEvent* event);
    void onDoubleClick(QMouseEvent* event);
    QColor channelColour(std::size_t channel) const;

    QCustomPlot* m_plot;
    QLabel* m_readout;
    SeriesStore m_store;
    Capture m_capture; // the current trace when it came as a capture (cursors read it)
    QString m_title;
    QList<QCPGraph*> m_graphs;         // current trace, one per channel
    std::vector<double> m_syncedUntil; // per channel: the last time handed to its graph
    std::deque<Overlay> m_overlays;    // newest first
    QList<QCPAxis*> m_valueAxes;
    QCPItemStraightLine* m_cursor[2] = {nullptr, nullptr};
    double m_cursorTime[2] = {0, 0};
    int m_dragging = -1; // cursor being dragged
    int m_maxOverlays = 5;
    bool m_dark = false;
    bool m_grid = true;
    QTimer m_syncTimer;
};

} // namespace scope
