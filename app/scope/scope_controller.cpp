// ScopeController: the Scope menu's actions.
#include "scope_controller.h"

#include "bode_view.h"
#include "capture_table_model.h"
#include "families/bds5/drive_connection.h"
#include "main_window.h"
#include "families/bds5/tuning/move_watch.h"
#include "families/bds5/record/play_terminal_fold.h"
#include "families/bds5/record/record_dialog.h"
#include "families/bds5/record/scope_catalog.h"
#include "scope_export.h"
#include "scope_view.h"
#include "spectrum_view.h"
#include "terminal_dock.h"
#include "transfer_dialog.h"
#include "transfer_reporter.h"
#include "app/tuning/tuning_panel.h"
#include "families/bds5/tuning/bds5_tuning_controls.h"
#include "families/bds5/tuning/tuning_runner.h"
#include "terminal_tabs.h"
#include "session_watch_source.h"
#include "watch_view.h"

#include "scope/capture_csv.h"
#include "scope/play_parser.h"
#include "scope/scope_plot.h"

#include <qcustomplot.h>

#include <QDateTime>
#include <QDialog>
#include <QDockWidget>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QHeaderView>
#include <QMenu>
#include <QPainter>
#include <QPrintDialog>
#include <QPrinter>
#include <QStatusBar>
#include <QTableView>
#include <QVBoxLayout>

namespace app {

namespace {
constexpr int kStatusMs = 15000;
const QString kCsvFilter = QObject::tr("Scope data (*.csv *.CSV);;All files (*)");

std::vector<std::string> toStd(const QStringList& lines) {
    std::vector<std::string> out;
    out.reserve(std::size_t(lines.size()));
    for (const QString& l : lines) out.push_back(l.toStdString());
    return out;
}
} // namespace

ScopeController::ScopeController(MainWindow& window)
    : QObject(&window), m_window(window), m_menu(new QMenu(tr("S&cope"), &window)),
      m_scopeDock(new QDockWidget(tr("Scope"), &window)), m_tuningDock(new QDockWidget(tr("Tuning"), &window)),
      m_view(new ScopeView(m_scopeDock)), m_tuning(makeBds5TuningPanel(window.connection(), m_tuningDock)),
      m_spectrum(new SpectrumView(&window)) {
    m_menu->setObjectName(QStringLiteral("scopeMenu"));
    m_scopeDock->setObjectName(QStringLiteral("scopeDock"));
    m_scopeDock->setWidget(m_view);
    m_tuningDock->setObjectName(QStringLiteral("tuningDock"));
    m_tuningDock->setWidget(m_tuning);
    m_export = new ScopeExport(*m_view, this);

    m_menu->addAction(tr("From &Drive..."), QKeySequence(tr("Ctrl+Alt+D")), this, &ScopeController::fromDrive);
    m_menu->addAction(tr("View &Again"), this, &ScopeController::viewAgain);
    m_menu->addAction(tr("From Dis&k..."), this, &ScopeController::openFromDisk);
    m_menu->addAction(tr("&Save CSV..."), this, &ScopeController::saveCsvAs);
    m_menu->addSeparator();
    m_menu->addAction(tr("&View Data"), this, &ScopeController::viewData);
    m_menu->addAction(tr("&Math Channel..."), m_view, &ScopeView::openMathDialog);
    m_menu->addAction(tr("&Print Plot..."), this, &ScopeController::printPlot);
    m_menu->addAction(tr("&Export Plot (PDF, PNG, SVG)..."), this, &ScopeController::exportPlot);
    m_export->addRangeChoice(m_menu); // whole record or visible range, for Save CSV and Export Plot
    m_menu->addSeparator();
    m_menu->addAction(tr("&Frequency Response..."), this, &ScopeController::frequencyResponse);
    QAction* spectrumAction =
        m_menu->addAction(tr("Spect&rum..."), QKeySequence(tr("Ctrl+Alt+F")), this, &ScopeController::spectrum);
    spectrumAction->setToolTip(tr("Spectrum (FFT) of a channel of the shown capture: find a resonance, set LPFHZ"));
    // Where the captures are looked at: the Scope dock and the tuning panel's scope.
    for (ScopeView* view : {m_view, m_tuning->view()})
        view->toolBar()
            ->addAction(tr("Spectrum"), this, &ScopeController::spectrum)
            ->setToolTip(spectrumAction->toolTip());
    m_menu->addAction(tr("&Watch Variables..."), this, &ScopeController::watchVariables);
    m_menu->addSeparator();
    m_menu->addAction(terminalTabAction(m_window, m_window.terminalDock(), m_scopeDock, tr("Sc&ope"), this));
    m_menu->addAction(terminalTabAction(m_window, m_window.terminalDock(), m_tuningDock, tr("&Tuning Panel"), this));
    connect(this, &ScopeController::captureShown, this, &ScopeController::keepForBode);
    connect(this, &ScopeController::captureShown, m_spectrum, &SpectrumView::showCapture);
    m_spectrum->setDerivedChannels([this](const scope::Capture& c) { return m_view->withMath(c); });
    connect(m_view, &ScopeView::mathChannelsChanged, m_spectrum, &SpectrumView::refresh);
    connect(&tuningRunner(), &TuningRunner::runFinished, m_spectrum,
            [this](const TuningRun& run) { m_spectrum->showCapture(run.capture); });
    connect(&tuningRunner(), &TuningRunner::runFinished, this,
            [this](const TuningRun& run) { keepForBode(run.capture); });
    // Each run's PLAY listing would put 250-300 lines in the terminal: one line stands for them.
    connect(&tuningRunner(), &TuningRunner::recordStarted, this, [this](serialport::Bds5RecordPlay* record) {
        new PlayTerminalFold(*record, *m_window.terminal(), tr("Tuning panel"));
    });
}

void ScopeController::keepForBode(const scope::Capture& capture) {
    if (!capture.find("VCMD") || !capture.find("VFB")) return;
    m_lastVelocity = capture;
    if (m_bode && m_bode->isVisible()) m_bode->showCapture(capture);
}

BodeView* ScopeController::frequencyResponse() {
    if (!m_bode) m_bode = new BodeView(&m_window);
    if (m_lastVelocity)
        m_bode->showCapture(*m_lastVelocity);
    else
        m_bode->showNothing(tr("Nothing recorded with VCMD and VFB yet: in the tuning panel choose the preset "
                               "\"Step for frequency response\" and Run Once (or record them with From Drive)."));
    m_bode->show();
    m_bode->raise();
    return m_bode;
}

TuningRunner& ScopeController::tuningRunner() const {
    return m_tuning->runner<TuningRunner>();
}

SpectrumView* ScopeController::spectrum() {
    m_spectrum->show();
    m_spectrum->raise();
    return m_spectrum;
}

WatchView* ScopeController::watchVariables() {
    if (!m_watch) m_watch = new WatchView(new SessionWatchSource(SessionHost::of(m_window.connection())), &m_window);
    m_watch->show();
    m_watch->raise();
    return m_watch;
}

void ScopeController::status(const QString& message) {
    m_window.statusBar()->showMessage(message, kStatusMs);
}

void ScopeController::fromDrive() {
    auto* dialog = new RecordDialog(&m_window);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    connect(dialog, &QDialog::accepted, this, [this, dialog] { record(dialog->plan()); });
    dialog->open();
}

void ScopeController::record(const serialport::Bds5RecordPlan& plan) {
    if (!TransferReporter::canStart(m_window)) return;
    auto* transfer = new serialport::Bds5RecordPlay(*m_window.connection().session(), plan);
    auto* watch = new MoveWatch(*m_window.connection().session(), *transfer); // a refused or faulted move stops it
    new TransferDialog(tr("Scope From Drive"), transfer, &m_window);
    new PlayTerminalFold(*transfer, *m_window.terminal(), tr("Scope")); // the samples, not 250 lines of them
    connect(transfer, &serialport::Bds5Transfer::finished, this,
            [this, watch](const serialport::Bds5TransferResult& r) {
                // A move the drive refused or cut short is not shown: its samples would look like a response.
                const serialport::Bds5LineError* refused = r.errors.isEmpty() ? nullptr : &r.errors.first();
                const QString stopped = !watch->reason().isEmpty() ? watch->summary()
                                        : refused ? tr("Record stopped: the drive refused %1: %2. Nothing is shown.")
                                                        .arg(refused->sent, serialport::describeError(refused->error))
                                                  : QString();
                status(r.ok() && !stopped.isEmpty() ? stopped : r.summary);
                if (r.ok() && stopped.isEmpty()) {
                    const auto parsed = scope::parsePlay(toStd(r.lines), unitOf);
                    if (!parsed.capture) {
                        status(tr("PLAY could not be read: %1").arg(QString::fromStdString(parsed.error)));
                    } else {
                        scope::Capture capture = *parsed.capture;
                        capture.title = QDateTime::currentDateTime().toString(QStringLiteral("HH:mm:ss")).toStdString();
                        show(capture);
                    }
                }
                emit recordFinished(r);
            });
    transfer->start();
}

// The Scope dock shows tabbed with the terminal (tabified only now: a hidden tab in the terminal's group
// would take the terminal's size until then).
void ScopeController::raiseScopeDock() {
    raiseInTerminalTabs(m_window, m_window.terminalDock(), m_scopeDock);
}

void ScopeController::show(const scope::Capture& capture) {
    m_last = capture;
    raiseScopeDock();
    m_view->showCapture(capture, true);
    emit captureShown(capture);
}

void ScopeController::viewAgain() {
    if (!m_last) return status(tr("Nothing recorded yet: use Scope > From Drive or From Disk."));
    raiseScopeDock();
    m_view->showCapture(*m_last, false);
}

void ScopeController::openFromDisk() {
    auto* dialog = new QFileDialog(&m_window, tr("Open Scope Data"), QString(), kCsvFilter);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->setFileMode(QFileDialog::ExistingFile);
    connect(dialog, &QFileDialog::fileSelected, this, [this](const QString& path) { loadCsv(path); });
    dialog->open();
}

bool ScopeController::loadCsv(const QString& path) {
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        status(tr("Cannot open %1: %2").arg(path, file.errorString()));
        return false;
    }
    const auto r = scope::readCsv(file.readAll().toStdString());
    if (!r.capture) {
        status(tr("%1 is not scope data: %2").arg(QFileInfo(path).fileName(), QString::fromStdString(r.error)));
        return false;
    }
    scope::Capture capture = *r.capture;
    capture.title = QFileInfo(path).fileName().toStdString();
    show(capture);
    status(tr("Opened %1: %2 samples").arg(QFileInfo(path).fileName()).arg(capture.sampleCount()));
    return true;
}

void ScopeController::saveCsvAs() {
    if (!m_last) return status(tr("Nothing to save: record or open scope data first."));
    auto* dialog = new QFileDialog(&m_window, tr("Save Scope Data"), QStringLiteral("scope.csv"), kCsvFilter);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->setAcceptMode(QFileDialog::AcceptSave);
    dialog->setDefaultSuffix(QStringLiteral("csv"));
    connect(dialog, &QFileDialog::fileSelected, this, [this](const QString& path) { saveCsv(path); });
    dialog->open();
}

bool ScopeController::saveCsv(const QString& path) {
    if (!m_last) return false;
    QFile file(path);
    const bool ok =
        file.open(QIODevice::WriteOnly | QIODevice::Truncate) &&
        file.write(QByteArray::fromStdString(scope::writeCsv(m_export->forCsv(m_view->withMath(*m_last))))) >= 0;
    status(ok ? tr("Saved %1%2").arg(QFileInfo(path).fileName(), m_export->rangeNote())
              : tr("Cannot write %1: %2").arg(path, file.errorString()));
    return ok;
}

QDialog* ScopeController::viewData() {
    if (!m_last) {
        status(tr("Nothing recorded yet: use Scope > From Drive or From Disk."));
        return nullptr;
    }
    auto* dialog = new QDialog(&m_window);
    dialog->setObjectName(QStringLiteral("scopeDataDialog"));
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->setWindowTitle(tr("Scope Data \u2014 %1").arg(QString::fromStdString(m_last->title)));
    auto* layout = new QVBoxLayout(dialog);
    auto* table = new QTableView(dialog);
    table->setModel(new CaptureTableModel(m_view->withMath(*m_last), table));
    table->setAlternatingRowColors(true);
    table->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    table->verticalHeader()->setDefaultSectionSize(table->fontMetrics().height() + 6);
    layout->addWidget(table);
    dialog->resize(560, 520);
    dialog->show();
    return dialog;
}

void ScopeController::printPlot() {
    auto* printer = new QPrinter(QPrinter::HighResolution);
    printer->setPageOrientation(QPageLayout::Landscape);
    auto* dialog = new QPrintDialog(printer, &m_window);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    connect(dialog, &QDialog::finished, this, [printer] { delete printer; });
    connect(dialog, &QDialog::accepted, this, [this, printer] {
        QCustomPlot* plot = m_view->plot()->customPlot();
        QCPPainter painter(printer);
        const QRectF page = printer->pageRect(QPrinter::DevicePixel);
        const double scale = page.width() / plot->width();
        painter.setMode(QCPPainter::pmVectorized);
        painter.setMode(QCPPainter::pmNoCaching);
        painter.scale(scale, scale);
        plot->toPainter(&painter, plot->width(), int(page.height() / scale));
        status(tr("Plot sent to the printer."));
    });
    dialog->open();
}

void ScopeController::exportPlot() {
    auto* dialog = new QFileDialog(&m_window, tr("Export Plot"), QStringLiteral("scope.pdf"),
                                   tr("PDF (*.pdf);;PNG image (*.png);;SVG drawing (*.svg)"));
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->setAcceptMode(QFileDialog::AcceptSave);
    connect(dialog, &QFileDialog::fileSelected, this, [this](const QString& path) { exportTo(path); });
    dialog->open();
}

bool ScopeController::exportTo(const QString& path) {
    const bool ok = m_export->savePlot(path); // PDF, PNG or SVG by the suffix
    status(ok ? tr("Exported the plot to %1%2").arg(QFileInfo(path).fileName(), m_export->rangeNote())
              : tr("Cannot write %1").arg(path));
    return ok;
}

} // namespace app
