// ScopeController: Motion Link's SCOPE menu and the Scope dock — From Drive (RECORD set-up, trigger, PLAY
// with progress and cancel), View Again, From Disk / Save (.CSV), View Data (table), Print Plot, PDF, PNG
// and SVG export, Frequency Response (Bode), Watch Variables (polled chart) — and the Tuning panel dock. MainWindow constructs it and adds menu() and the docks.
// GUI thread only.
#pragma once

#include "scope/capture.h"
#include "serialport/bds5_record_play.h"

#include <QObject>
#include <QPointer>

#include <optional>

class QDialog;
class QAction;
class QDockWidget;
class QMenu;

namespace app {

class BodeView;
class ScopeExport;
class SpectrumView;
class MainWindow;
class ScopeView;
class WatchView;
class TuningPanel;
class TuningRunner;

class ScopeController final : public QObject {
    Q_OBJECT
public:
    explicit ScopeController(MainWindow& window);

    QMenu* menu() const { return m_menu; }
    QDockWidget* scopeDock() const { return m_scopeDock; }
    QDockWidget* tuningDock() const { return m_tuningDock; }
    ScopeView* view() const { return m_view; }
    TuningPanel* tuningPanel() const { return m_tuning; }
    TuningRunner& tuningRunner() const; // the BDS5's, behind the panel
    const std::optional<scope::Capture>& lastCapture() const { return m_last; }
    ScopeExport* exporter() const { return m_export; } // whole record or visible range (Export Range)

    void fromDrive();                                    // the RECORD set-up dialog, then record()
    void record(const serialport::Bds5RecordPlan& plan); // RECORD + trigger + PLAY, shown when done
    void viewAgain();
    void openFromDisk();
    bool loadCsv(const QString& path);
    void saveCsvAs();
    bool saveCsv(const QString& path); // the whole record or the visible range, as exporter() says
    QDialog* viewData(); // non-modal table of the last capture; nullptr when there is none
    void printPlot();
    void exportPlot(); // PDF, PNG or SVG by the chosen file's suffix
    bool exportTo(const QString& path);
    // Bode view of the last capture (recorded, opened or a tuning run) that holds VCMD and VFB; it follows
    // each new one while open.
    BodeView* frequencyResponse();
    WatchView* watchVariables(); // the polled rolling chart (one window, reused)
    // Spectrum of a channel of the last capture (recorded, opened or a tuning run) over the one before it. It
    // follows every capture, also while closed, so the overlay is there when it opens.
    SpectrumView* spectrum();

signals:
    void captureShown(const scope::Capture& capture);
    void recordFinished(const serialport::Bds5TransferResult& result);

private:
    void show(const scope::Capture& capture);
    void keepForBode(const scope::Capture& capture);
    void raiseScopeDock();
    void status(const QString& message);

    MainWindow& m_window;
    QMenu* m_menu;
    QDockWidget* m_scopeDock;
    QDockWidget* m_tuningDock;
    ScopeView* m_view;
    TuningPanel* m_tuning;
    std::optional<scope::Capture> m_last;
    std::optional<scope::Capture> m_lastVelocity; // the last with VCMD and VFB, for the Bode view
    QPointer<BodeView> m_bode;
    SpectrumView* m_spectrum;
    QPointer<WatchView> m_watch;
    ScopeExport* m_export = nullptr;
};

} // namespace app
