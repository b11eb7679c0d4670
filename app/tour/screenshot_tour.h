// ScreenshotTour: `servodesk --screenshot-tour DIR`. Walks a list of named steps over a shown MainWindow
// connected to the simulated drive — act, wait (polling on a timer, never blocking) until the view shows
// what it should, save "<name>.png" and what it shows, "<name>.png.facts" (see shot_facts.h) — then reports
// finished(0), or finished(1) on a time-out.
// Later views join the tour by appending steps in buildSteps().
#pragma once

#include "tour_shot.h"

#include <QDir>
#include <QObject>
#include <QSize>
#include <QTimer>

#include <functional>
#include <memory>
#include <type_traits>
#include <vector>

namespace app {

class MainWindow;

class ScreenshotTour final : public QObject {
    Q_OBJECT
public:
    static constexpr QSize kWindowSize{1280, 800};
    // A hang guard, not a speed goal: the longest step (scope-bode) reads 500 samples of two variables with
    // PLAY at the simulated 9600 baud, about 14 s, and a loaded CI machine stretches that.
    static constexpr int kStepTimeoutMs = 45000;
    static constexpr int kPollMs = 50;

    struct Step {
        QString name;                  // names the PNG ("terminal" -> terminal.png) and time-out messages
        std::function<void()> act;     // optional: what a user would do first (type, open a dialog)
        std::function<bool()> ready;   // optional: polled until true before the grab
        std::function<TourShot()> grab; // optional: the picture to save, with its widgets; none when empty
        std::function<QString()> text; // optional: what the view says, saved as "<name>.txt" for tests
        std::function<void()> cleanUp; // optional: after the grab (close the dialog)
        std::function<QString()> state; // optional: what the step waits on, said when it times out
    };

    // A step that opens a dialog (open() returns it, set up as the shot wants), waits until it shows, grabs
    // it and closes it with reject().
    template <typename Open>
    static Step dialogStep(const QString& name, Open open) {
        using Dialog = std::remove_pointer_t<std::invoke_result_t<Open>>;
        auto dialog = std::make_shared<QPointer<Dialog>>();
        return {.name = name,
                .act = [dialog, open] { *dialog = open(); },
                .ready = [dialog] { return *dialog && (*dialog)->isVisible(); },
                .grab = [dialog] { return TourShot::of(*dialog); },
                .cleanUp = [dialog] {
                    if (*dialog) (*dialog)->reject();
                }};
    }

    ScreenshotTour(MainWindow& window, const QString& outputDir, QObject* parent = nullptr);

    // Starts with the first step on the next event-loop turn.
    void start();

signals:
    void finished(int exitCode);

private:
    std::vector<Step> buildSteps();
    void beginStep();
    void poll();
    void fail(const QString& why);
    bool save(const QString& name, const TourShot& shot);
    void typeIntoTerminal(const QString& text);
    bool terminalShowsPromptAfter(const QString& line) const;

    MainWindow& m_window;
    QDir m_outputDir;
    std::vector<Step> m_steps;
    std::size_t m_current = 0;
    int m_elapsedMs = 0;
    int m_settleTicks = 0;
    QTimer m_timer;
};

} // namespace app
