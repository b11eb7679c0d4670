// Editor tour steps: a new tab with a pick-and-place program that has five mistakes, as a user would see it
// after typing it; the pictures include the tool-tip windows (help popup, completion list) over the window.
#include "editor_tour_steps.h"

#include "editor_area.h"
#include "editor_tabs.h"
#include "help_browser.h"
#include "main_window.h"

#include "editor/bds5_diagnostics.h"
#include "editor/bds5_language.h"
#include "editor/help_popup.h"
#include "editor/program_editor.h"

#include <QCoreApplication>
#include <QKeyEvent>
#include <QPointer>

#include <memory>

namespace app {

namespace {

// Mistakes on lines 4 (a switch set to 2), 18 (no such command), 20 (no label 20), 21 (spaces inside an
// expression) and 22 (a ';' comment without a space before it).
const QString kCellProgram = QStringLiteral("; PICK AND PLACE CELL - WHAT THE DRIVE WOULD SAY, AS YOU TYPE\n"
                                            "POWER-UP$                ;POWER-UP LABEL\n"
                                            "PLIM OFF                 ;NO SOFTWARE LIMITS\n"
                                            "PROP 2                   ;PROPORTIONAL LOOP\n"
                                            "END\n"
                                            ";\n"
                                            "A$ I7 OFF                ;THERMOSTAT OPENED\n"
                                            "P \"THERMOSTAT OPENED\"\n"
                                            "DIS\n"
                                            "B\n"
                                            ";\n"
                                            "10$                      ;PICK CYCLE\n"
                                            "X1=X1+1\n"
                                            "IF X1 GT 100\n"
                                            "  MA 4000 1000\n"
                                            "  W 0\n"
                                            "ELSE\n"
                                            "  MOVE 2000\n"
                                            "ENDIF\n"
                                            "GOTO 20\n"
                                            "X2 = X1 + 5\n"
                                            "J 10;RUN SLOWLY\n"
                                            "P \"CYCLES:\" X1[6]\n"
                                            "END\n"
                                            ";\n"
                                            "ERROR$                   ;ERROR HANDLER\n"
                                            "P \"ERROR \" LSTERR\n"
                                            "B\n");

void typeInto(QWidget* widget, const QString& text) {
    for (const QChar ch : text) {
        QKeyEvent press(QEvent::KeyPress, ch.toUpper().unicode(), Qt::NoModifier, QString(ch));
        QCoreApplication::sendEvent(widget, &press);
        QKeyEvent release(QEvent::KeyRelease, ch.toUpper().unicode(), Qt::NoModifier, QString(ch));
        QCoreApplication::sendEvent(widget, &release);
    }
}

} // namespace

std::vector<ScreenshotTour::Step> editorTourSteps(MainWindow& window) {
    auto editor = std::make_shared<QPointer<editor::ProgramEditor>>();
    auto diagnostics = [editor]() -> editor::Bds5Diagnostics* {
        editor::Bds5Language* language = editor::Bds5Language::of(*editor);
        return language ? language->diagnostics() : nullptr;
    };
    std::vector<ScreenshotTour::Step> steps;
    steps.push_back({.name = QStringLiteral("editor-diagnostics"),
                     .act =
                         [&window, editor] {
                             *editor = window.editorArea()->tabs()->addEditor(QStringLiteral("cell.bds"));
                             (*editor)->setText(kCellProgram);
                             // Scrolled to the routine with four of the five mistakes.
                             (*editor)->setCursorPosition(20, 7);
                             (*editor)->setFirstVisibleLine(11);
                             (*editor)->setFocus();
                         },
                     .ready =
                         [diagnostics] {
                             const editor::Bds5Diagnostics* d = diagnostics();
                             return d && !d->pending() && d->errorCount() == 5;
                         },
                     .grab = [&window] { return TourShot::of(&window); }});
    steps.push_back({.name = QStringLiteral("editor-help"),
                     .act =
                         [editor] {
                             (*editor)->setCursorPosition(14, 3); // on MA
                             editor::Bds5Language::of(*editor)->showHelpAtCursor();
                         },
                     .ready =
                         [editor] {
                             editor::Bds5Language* language = editor::Bds5Language::of(*editor);
                             return language && language->helpPopup()->isVisible();
                         },
                     .grab = [&window] { return TourShot::withPopups(&window); },
                     .cleanUp =
                         [&window, editor] {
                             editor::Bds5Language::of(*editor)->hideHelp();
                             window.helpBrowser()->hide();
                         }});
    steps.push_back({.name = QStringLiteral("editor-completion"),
                     .act =
                         [editor] {
                             (*editor)->setCursorPosition(13, 12); // the end of IF X1 GT 100
                             (*editor)->setFocus();
                             QKeyEvent enter(QEvent::KeyPress, Qt::Key_Return, Qt::NoModifier, QStringLiteral("\r"));
                             QCoreApplication::sendEvent(*editor, &enter);
                             typeInto(*editor, QStringLiteral("  X3=PE"));
                         },
                     .ready = [editor] { return *editor && (*editor)->isListActive(); },
                     .grab = [&window] { return TourShot::withPopups(&window); },
                     .cleanUp =
                         [&window, editor] {
                             if (!*editor) return;
                             (*editor)->cancelList();
                             (*editor)->setModified(false);
                             window.editorArea()->tabs()->removeEditor(*editor);
                         }});
    return steps;
}

} // namespace app
