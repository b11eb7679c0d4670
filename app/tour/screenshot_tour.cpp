// ScreenshotTour: the steps, and the timer-driven walk through them.
#include "screenshot_tour.h"

#include "machine_tour_steps.h"

#include "connection_dialog.h"
#include "docks_tour_steps.h"
#include "families/bds5/drive_connection.h"
#include "drive_tour_steps.h"
#include "editor_tour_steps.h"
#include "main_window.h"
#include "tabs_tour_steps.h"
#include "terminal_dock.h"
#include "terminal_widget.h"
#include "transfer_tour_steps.h"
#include "scope_tour_steps.h"
#include "spectrum_tour_steps.h"
#include "math_trigger_tour_steps.h"
#include "cursors_xy_tour_steps.h"
#include "families/sc750/sc750_tour_steps.h"
#include "tuning_tour_steps.h"
#include "families/pmc960/pmc960_tour_steps.h"
#include "shot_facts.h"

#include "drive_core/bds5/bds5_drive.h"
#include "editor/program_editor.h"

#include <QCoreApplication>
#include <QFile>
#include <QKeyEvent>
#include <QPointer>
#include <QTextStream>

namespace app {

namespace {
const QString kHello = QStringLiteral("HELLO, WORLD");
const QString kPrompt = QStringLiteral("-->");
constexpr int kSettleTicks = 2; // event-loop turns between "ready" and the grab, for layout and paint
} // namespace

ScreenshotTour::ScreenshotTour(MainWindow& window, const QString& outputDir, QObject* parent)
    : QObject(parent), m_window(window), m_outputDir(outputDir) {
    m_timer.setInterval(kPollMs);
    connect(&m_timer, &QTimer::timeout, this, &ScreenshotTour::poll);
}

void ScreenshotTour::start() {
    if (!m_outputDir.mkpath(QStringLiteral("."))) {
        QTimer::singleShot(0, this, [this] { fail(tr("cannot create %1").arg(m_outputDir.path())); });
        return;
    }
    m_steps = buildSteps();
    m_current = 0;
    QTimer::singleShot(0, this, &ScreenshotTour::beginStep);
}

std::vector<ScreenshotTour::Step> ScreenshotTour::buildSteps() {
    TerminalWidget* terminal = m_window.terminal();
    auto driveReady = [this] {
        const auto* session = m_window.connection().session();
        return session && session->state() == serialport::Bds5Session::State::Ready;
    };
    std::vector<Step> steps;
    // A drive on a serial port signed on before we opened it; only the simulator's sign-on can be awaited.
    const bool simulated = m_window.connection().choice().kind == ConnectionChoice::Kind::Simulator;
    steps.push_back({.name = QStringLiteral("sign-on"), .ready = [terminal, driveReady, simulated] {
                         const QString text = terminal->text();
                         return (!simulated ||
                                 text.contains(QString::fromLatin1(drive_core::bds5::kSignOn))) &&
                                text.endsWith(kPrompt) && driveReady();
                     }});
    steps.push_back(
        {.name = QStringLiteral("hello-world"),
         .act = [this] { typeIntoTerminal(QStringLiteral("P \"%1\"\r").arg(kHello)); },
         .ready = [this, driveReady] { return terminalShowsPromptAfter(kHello) && driveReady(); }});
    steps.push_back({.name = QStringLiteral("main-window"), .grab = [this] { return TourShot::of(&m_window); }});
    steps.push_back({.name = QStringLiteral("terminal"),
                     .grab = [this] { return TourShot::of(m_window.terminalDock()); },
                     .text = [terminal] { return terminal->text(); }});
    steps.push_back({.name = QStringLiteral("editor"), .grab = [this] { return TourShot::of(m_window.editor()); }});
    steps.push_back(dialogStep(QStringLiteral("connection-dialog"), [this] {
        ConnectionDialog* dialog = m_window.showConnectionDialog();
        dialog->setChoice(ConnectionChoice::simulator());
        return dialog;
    }));
    for (Step& step : transferTourSteps(m_window)) steps.push_back(std::move(step));
    for (Step& step : tabsTourSteps(m_window, m_outputDir)) steps.push_back(std::move(step));
    for (Step& step : editorTourSteps(m_window)) steps.push_back(std::move(step));
    for (Step& step : driveTourSteps(m_window)) steps.push_back(std::move(step));
    for (Step& step : scopeTourSteps(m_window)) steps.push_back(std::move(step));
    // Before the spectrum's steps: they change the drive's loop (PL, LPF) and the step response is the last
    // capture here.
    for (Step& step : mathTriggerTourSteps(m_window)) steps.push_back(std::move(step));
    for (Step& step : spectrumTourSteps(m_window)) steps.push_back(std::move(step));
    for (Step& step : cursorsXyTourSteps(m_window)) steps.push_back(std::move(step)); // after scope-math's viewAgain
    for (Step& step : docksTourSteps(m_window)) steps.push_back(std::move(step));
    for (Step& step : sc750TourSteps(m_window)) steps.push_back(std::move(step)); // last: it switches family
    for (Step& step : pmc960TourSteps(m_window)) steps.push_back(std::move(step)); // switches family too
    for (Step& step : tuningTourSteps(m_window)) steps.push_back(std::move(step));  // each family, then the BDS5
    for (Step& step : machineTourSteps(m_window)) steps.push_back(std::move(step)); // a line of its own
    return steps;
}

void ScreenshotTour::beginStep() {
    if (m_current >= m_steps.size()) {
        m_timer.stop();
        emit finished(0);
        return;
    }
    m_elapsedMs = 0;
    m_settleTicks = 0;
    if (const Step& step = m_steps[m_current]; step.act) step.act();
    m_timer.start();
}

void ScreenshotTour::poll() {
    const Step& step = m_steps[m_current];
    m_elapsedMs += kPollMs;
    if (step.ready && !step.ready()) {
        m_settleTicks = 0;
        if (m_elapsedMs >= kStepTimeoutMs)
            fail(tr("step \"%1\" was not ready after %2 s%3")
                     .arg(step.name)
                     .arg(kStepTimeoutMs / 1000)
                     .arg(step.state ? QStringLiteral(" (%1)").arg(step.state()) : QString()));
        return;
    }
    if (++m_settleTicks < kSettleTicks) return;
    m_timer.stop();
    if (step.grab && !save(step.name, step.grab())) return;
    if (step.text) {
        const QString path = m_outputDir.absoluteFilePath(step.name + QStringLiteral(".txt"));
        QFile file(path);
        if (!file.open(QIODevice::WriteOnly | QIODevice::Truncate) || file.write(step.text().toUtf8()) < 0) {
            fail(tr("cannot write %1").arg(path));
            return;
        }
        QTextStream(stdout) << path << Qt::endl;
    }
    if (step.cleanUp) step.cleanUp();
    ++m_current;
    beginStep();
}

// "<name>.png", and beside it what the picture shows, read from its widgets now: "<name>.png.facts".
bool ScreenshotTour::save(const QString& name, const TourShot& shot) {
    const QString path = m_outputDir.absoluteFilePath(name + QStringLiteral(".png"));
    QFile facts(path + QStringLiteral(".facts"));
    if (!shot.picture.save(path) || !facts.open(QIODevice::WriteOnly | QIODevice::Truncate) ||
        facts.write((shotFacts(shot).join(QLatin1Char('\n')) + QLatin1Char('\n')).toUtf8()) < 0) {
        fail(tr("cannot write %1").arg(path));
        return false;
    }
    QTextStream(stdout) << path << Qt::endl;
    return true;
}

void ScreenshotTour::fail(const QString& why) {
    m_timer.stop();
    QTextStream(stderr) << "servodesk: screenshot tour failed: " << why << Qt::endl;
    if (m_window.terminal()) {
        QTextStream(stderr) << "terminal shows:\n" << m_window.terminal()->text() << Qt::endl;
    }
    emit finished(1);
}

void ScreenshotTour::typeIntoTerminal(const QString& text) {
    // The same path as a user's keys: key events to the terminal widget, which sends the bytes.
    TerminalWidget* terminal = m_window.terminal();
    terminal->setFocus();
    for (const QChar ch : text) {
        const int key = ch == QLatin1Char('\r') ? int(Qt::Key_Return) : int(ch.toUpper().unicode());
        const QString keyText = ch == QLatin1Char('\r') ? QStringLiteral("\r") : QString(ch);
        QKeyEvent press(QEvent::KeyPress, key, Qt::NoModifier, keyText);
        QCoreApplication::sendEvent(terminal, &press);
        QKeyEvent release(QEvent::KeyRelease, key, Qt::NoModifier, keyText);
        QCoreApplication::sendEvent(terminal, &release);
    }
}

bool ScreenshotTour::terminalShowsPromptAfter(const QString& line) const {
    const QStringList lines = m_window.terminal()->text().split(QLatin1Char('\n'));
    const qsizetype at = lines.lastIndexOf(line);
    return at >= 0 && lines.last() == kPrompt && at < lines.size() - 1;
}

} // namespace app
