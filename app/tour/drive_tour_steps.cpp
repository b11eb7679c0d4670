// Drive tour steps: everything against the simulated drive through the session, grabbed as a user sees it.
#include "drive_tour_steps.h"

#include "families/bds5/bds5_workspace.h"

#include "capture_dock.h"
#include "capture_log.h"
#include "families/bds5/debug_highlighter.h"
#include "families/bds5/drive_actions.h"
#include "families/bds5/drive_connection.h"
#include "editor_area.h"
#include "editor_tabs.h"
#include "help_browser.h"
#include "main_window.h"
#include "options_controller.h"
#include "options_dialog.h"
#include "terminal_dock.h"
#include "terminal_widget.h"

#include "editor/program_editor.h"

#include <QAction>
#include <QPlainTextEdit>
#include <QPointer>
#include <QScrollBar>
#include <QTextBlock>
#include <QTextDocument>

#include <algorithm>
#include <memory>

namespace app {

namespace {

// Scrolls the capture's text so that the last line holding `text` is the lowest line in sight.
void scrollToLast(CaptureDock& dock, const QString& text) {
    auto* edit = dock.findChild<QPlainTextEdit*>(QStringLiteral("captureText"));
    if (!edit) return;
    const QTextCursor found = edit->document()->find(text, edit->document()->characterCount(),
                                                     QTextDocument::FindBackward);
    if (found.isNull()) return;
    const int lines = std::max(1, edit->viewport()->height() / edit->fontMetrics().lineSpacing());
    edit->verticalScrollBar()->setValue(std::max(0, found.blockNumber() - lines + 1));
}
// The manual's nested IF (L4074-4088) and a loop to trace.
const QStringList kProgram{
    QStringLiteral("; NESTED.BDS - the manual's nested IF (L4074-4088), and a loop to trace"),
    QStringLiteral("55$"),
    QStringLiteral("IF X1 GT 0"),
    QStringLiteral("  IF X2 GT 0"),
    QStringLiteral("    P \"BOTH X1 AND X2 > 0\""),
    QStringLiteral("  ELSE"),
    QStringLiteral("    P \"ONLY X1 GT 0\""),
    QStringLiteral("  ENDIF"),
    QStringLiteral("ELSE"),
    QStringLiteral("  IF X2 GT 0"),
    QStringLiteral("    P \"ONLY X2 GT 0\""),
    QStringLiteral("  ELSE"),
    QStringLiteral("    P \"NEITHER X1 NOR X2 > 0\""),
    QStringLiteral("  ENDIF"),
    QStringLiteral("ENDIF"),
    QStringLiteral("B"),
    QString(),
    QStringLiteral("20$                ; count passes, slowly"),
    QStringLiteral("  X3=X3+1"),
    QStringLiteral("  P \"PASS \" X3"),
    QStringLiteral("  D 150"),
    QStringLiteral("  GOTO 20"),
};

bool driveReady(MainWindow& window) {
    const auto* session = window.connection().session();
    return session && session->state() == serialport::Bds5Session::State::Ready;
}
QString lastLine(MainWindow& window) {
    return window.terminal()->text().section(QLatin1Char('\n'), -1);
}
} // namespace

std::vector<ScreenshotTour::Step> driveTourSteps(MainWindow& window) {
    std::vector<ScreenshotTour::Step> steps;
    auto stepped = std::make_shared<int>(0);
    // Load the program the way a terminal user would (>BDS, the lines, Esc) with the capture running.
    steps.push_back({.name = QStringLiteral("debug-load"),
                     .act =
                         [&window] {
                             window.bds5().captureLog().start();
                             EditorTabs& tabs = *window.editorArea()->tabs();
                             editor::ProgramEditor* editor = tabs.addEditor(QStringLiteral("NESTED.BDS"));
                             editor->setText(kProgram.join(QLatin1Char('\n')) + QLatin1Char('\n'));
                             tabs.refreshTab(editor);
                             auto* session = window.connection().session();
                             session->send(QStringLiteral(">BDS"));
                             for (QString line : kProgram.mid(1)) { // sent without comments
                                 line = line.section(QLatin1String(" ;"), 0, 0);
                                 while (line.endsWith(QLatin1Char(' '))) line.chop(1);
                                 if (!line.isEmpty()) session->send(line);
                             }
                             session->sendEscape();
                             for (const char* line : {"X1=1", "X2=1", "X3=0", "TRC OFF"})
                                 session->send(QString::fromLatin1(line));
                             window.driveActions().singleStepAction()->trigger(); // SS ON
                             window.driveActions().run(55);
                         },
                     .ready = [&window] { return window.debugHighlighter().currentLine() == 1 && driveReady(window); }});
    // Two Steps: the drive shows "  IF X2 GT 0" at its s--> prompt, the editor highlights that line.
    steps.push_back({.name = QStringLiteral("debug-single-step"),
                     .ready =
                         [&window, stepped] {
                             if (!driveReady(window) || lastLine(window) != QStringLiteral("s-->")) return false;
                             if (window.debugHighlighter().currentLine() == 3) return true;
                             if (window.debugHighlighter().currentLine() == 1 + *stepped && *stepped < 2) {
                                 ++*stepped;
                                 window.driveActions().stepAction()->trigger();
                             }
                             return false;
                         },
                     .grab = [&window] { return TourShot::of(&window); }});
    // Continue (SS OFF): 55$ runs on to its B and the drive is back at -->.
    steps.push_back({.name = QStringLiteral("debug-continue"),
                     .act = [&window] { window.driveActions().continueAction()->trigger(); },
                     .ready =
                         [&window] {
                             return driveReady(window) && lastLine(window) == QStringLiteral("-->") &&
                                    window.debugHighlighter().currentLine() < 0;
                         }});
    // Trace the loop: a program running with trace, the highlight following it.
    steps.push_back({.name = QStringLiteral("terminal-trace"),
                     .act =
                         [&window] {
                             window.driveActions().traceAction()->trigger(); // TRC ON
                             window.driveActions().run(20);
                         },
                     .ready =
                         [&window] {
                             return window.terminal()->text().count(QStringLiteral("t...  P \"PASS \" X3")) >= 4 &&
                                    window.debugHighlighter().currentLine() >= 17;
                         },
                     .grab = [&window] { return TourShot::of(&window); },
                     .text = [&window] { return window.terminal()->text(); },
                     .cleanUp =
                         [&window] {
                             window.driveActions().stopAction()->trigger(); // ^X
                             window.driveActions().traceAction()->trigger(); // TRC OFF
                         }});
    steps.push_back({.name = QStringLiteral("capture"),
                     .act =
                         [&window] {
                             window.bds5().captureDock()->setView(CaptureDock::View::Transcript);
                             window.bds5().captureDock()->show();
                             window.bds5().captureDock()->raise();
                         },
                     .ready =
                         [&window] {
                             return driveReady(window) && window.bds5().captureDock()->isVisible() &&
                                    window.bds5().captureDock()->shownText().contains(QStringLiteral("<^X>"));
                         },
                     .grab =
                         [&window] {
                             // The drive's last trace lines may still arrive after ^X and scroll it out of
                             // sight (a loaded machine): the shot shows the ^X line at the foot of the view.
                             scrollToLast(*window.bds5().captureDock(), QStringLiteral("<^X>"));
                             return TourShot::of(window.bds5().captureDock());
                         },
                     .text = [&window] { return window.bds5().captureDock()->shownText(); },
                     .cleanUp =
                         [&window] {
                             window.bds5().captureLog().stop();
                             window.terminalDock()->raise();
                         }});
    for (const QString& page : {QStringLiteral("communications"), QStringLiteral("drive")}) {
        const QString name = page == QLatin1String("drive") ? QStringLiteral("options-drive") : QStringLiteral("options");
        steps.push_back(ScreenshotTour::dialogStep(name, [&window, page] {
            OptionsDialog* dialog = window.optionsController().showDialog();
            dialog->showPage(page);
            return dialog;
        }));
    }
    steps.push_back({.name = QStringLiteral("help-reference"),
                     .act = [&window] { window.helpBrowser()->showTopic(QStringLiteral("ERR 25")); },
                     .ready = [&window] { return window.helpBrowser()->isVisible(); },
                     .grab = [&window] { return TourShot::of(window.helpBrowser()); },
                     .text = [&window] { return window.helpBrowser()->pageText(); },
                     .cleanUp = [&window] { window.helpBrowser()->hide(); }});
    return steps;
}

} // namespace app
