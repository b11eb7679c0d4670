// ScopePlot: the thin QCustomPlot view over a SeriesStore. Up to 8 channels, one y-axis per unit (or one
// shared axis: axis_groups.h); legend; mouse and key zoom/pan; A/B cursors, dragged or moved by keys
// (cursor_keys.h), with a Δt, 1/Δt, Δy readout; auto-scale; grid;
// light/dark; the last N captures kept as overlays in fading colours, each one toggleable. Data is appended
// incrementally (appendLive) and replots are coalesced (rpQueuedReplot); a hidden plot does not replot.
// Every trace (current and overlays) lives in a SeriesStore; each frame hands QCustomPlot only its min/max
// decimation for the visible time range at the plot's width, so a frame costs O(pixels), not O(samples).
// GUI thread only.
#pragma once

#include "axis_groups.h"
#include "capture.h"
#include "cursor_keys.h"
#include "cursor_readout.h"
#include "legend_corner.h"
#include "series_store.h"

#include <QTimer>
#include <QWidget>

#include <cstdint>
#include <deque>
#include <optional>

class QCPAxis;
class QCPItemStraightLine;
class QCPItemText;
class QCustomPlot;
class QLabel;
class QMouseEvent;

namespace scope {

class ColumnGraph;

class ScopePlot final : public QWidget {
    Q_OBJECT
public:
    static constexpr int kMaxChannels = 8;

    explicit ScopePlot(QWidget* parent = nullptr);
    ~ScopePlot() override;

    QCustomPlot* customPlot() const { return m_plot; }
    // How many segments of the drawn graphs the legend hides where the last frame drew it (0: none).
    int tracesUnderLegend() const;

    // Shows a capture as the current trace. keepPrevious: the trace shown so far becomes the newest
    // overlay (the oldest beyond maxOverlays() goes); otherwise every overlay is dropped.
    void showCapture(const Capture& capture, bool keepPrevious = false);
    // Shows capture in place of the current trace, the overlays kept: the same capture with a math channel
    // added or removed.
    void replaceCapture(const Capture& capture);
    const Capture& capture() const { return m_capture; }
    void clear();

    // Live data: channels without a fixed interval, appended as they come (seconds, drive units).
    void beginLive(const std::vector<std::pair<std::string, std::string>>& namesAndUnits);
    void appendLive(std::size_t channel, double time_s, double value);
    const SeriesStore& store() const { return m_store; }
    // Samples in the current trace of a channel (what the plot shows, before decimation; for tests).
    int pointCount(std::size_t channel) const;
    // Points the current trace's graph of a channel holds: the decimation the last frame drew.
    int drawnPointCount(std::size_t channel) const;

    int overlayCount() const { return int(m_overlays.size()); }
    QString overlayTitle(int index) const; // 0 is the newest
    bool isOverlayVisible(int index) const;
    void setOverlayVisible(int index, bool visible);
    void setMaxOverlays(int count);
    int maxOverlays() const { return m_maxOverlays; }

    void setCursors(double first_s, double second_s);
    void setCursorsVisible(bool visible);
    bool cursorsVisible() const;
    // The cursor the keys move: 0 A, 1 B (drawn solid; the other dashed).
    int activeCursor() const { return m_activeCursor; }

    // One value axis per unit (default) or one shared by every channel; each axis auto-scales on its own.
    void setAxisMode(AxisMode mode);
    AxisMode axisMode() const { return m_axisMode; }
    // The value axes in use, in AxisLayout order (left, right, left, ...), labelled "VCMD, VFB [VEL]".
    QList<QCPAxis*> valueAxes() const;
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
        QList<ColumnGraph*> graphs;
        bool visible = true;
        SeriesStore store; // the trace's samples: its graphs are decimated from them, as the current one's
    };
    // What the graphs were last decimated for; any other range, width or data decimates again.
    struct DrawnFor {
        double from_s = 0;
        double to_s = 0;
        int columns = 0;
        std::uint64_t revision = 0; // of m_store (overlays do not change; a new trace resets m_drawn)
        bool operator==(const DrawnFor&) const = default;
    };

    void ensureAxes(std::size_t count);
    ColumnGraph* addGraph();
    void beginTrace(const std::vector<std::pair<std::string, std::string>>& namesAndUnits, std::size_t capacity);
    void decimateGraphs();
    void placeLegend();
    std::vector<std::vector<PixelPoint>> drawnTraces() const;
    void syncFromStore();
    void scheduleSync();
    void requestReplot();
    void applyTheme();
    void recolourOverlays();
    void updateReadout();
    void layoutAxes();
    QCPAxis* axisForUnit(const std::string& unit) const;
    bool cursorKey(int key, Qt::KeyboardModifiers modifiers);
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
    QList<ColumnGraph*> m_graphs;    // current trace, one per channel
    LegendCorner m_legendCorner = LegendCorner::TopLeft;
    std::optional<DrawnFor> m_drawn; // what the graphs hold now; nullopt: decimate on the next frame
    std::deque<Overlay> m_overlays;  // newest first
    QList<QCPAxis*> m_valueAxes;
    QCPItemStraightLine* m_cursor[2] = {nullptr, nullptr};
    QCPItemText* m_cursorLabel[2] = {nullptr, nullptr}; // "A", "B" at the top of each line
    int m_activeCursor = 0;
    AxisMode m_axisMode = AxisMode::PerUnit;
    AxisLayout m_layout; // of the current trace's channels
    double m_cursorTime[2] = {0, 0};
    int m_dragging = -1; // cursor being dragged
    int m_maxOverlays = 5;
    bool m_dark = false;
    bool m_grid = true;
    QTimer m_syncTimer;
};

} // namespace scope
