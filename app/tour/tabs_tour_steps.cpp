// Tabs and editor-function tour steps.
#include "tabs_tour_steps.h"

#include "document_controller.h"
#include "editor_actions.h"
#include "editor_area.h"
#include "editor_tabs.h"
#include "main_window.h"

#include "editor/editor_size_dialog.h"
#include "editor/find_bar.h"
#include "editor/go_to_line_dialog.h"
#include "editor/program_editor.h"

#include <QCoreApplication>
#include <QFile>
#include <QKeyEvent>
#include <QLabel>
#include <QPointer>
#include <QStatusBar>

#include <algorithm>
#include <memory>

namespace app {

namespace {
// A program in the manual's style: comment lines around the code, so "go to line" without counting
// comments lands somewhere else than with.
const char* const kMotionProgram = "; MOTION.BDS - INDEX A CONVEYOR IN STEPS, WITH A JOG HOME FIRST\r\n"
                                   "; X1 = STEP DISTANCE (COUNTS), X2 = STEP SPEED (RPM), X3 = STEPS LEFT\r\n"
                                   "\r\n"
                                   "1$                      ;START HERE\r\n"
                                   "X1 = 4096               ;ONE MOTOR TURN PER STEP\r\n"
                                   "X2 = 600\r\n"
                                   "X3 = 12                 ;STEPS PER CYCLE\r\n"
                                   "GOSUB 5                 ;JOG TO HOME FIRST\r\n"
                                   "\r\n"
                                   "; THE INDEX LOOP\r\n"
                                   "10$\r\n"
                                   "MI X1 X2                ;ONE STEP\r\n"
                                   "X3 = X3-1\r\n"
                                   "IF X3 GT 0\r\n"
                                   "  GOTO 10\r\n"
                                   "ELSE\r\n"
                                   "  P \"CYCLE DONE\"\r\n"
                                   "ENDIF\r\n"
                                   "B\r\n"
                                   ";\r\n"
                                   "; JOG HOME: SLOW, THEN STOP\r\n"
                                   "5$\r\n"
                                   "J 100                   ;SLOW JOG\r\n"
                                   "W 2                     ;UNTIL THE JOG IS AT SPEED\r\n"
                                   "J 0\r\n"
                                   "RET\r\n";
const char* const kVariables = "X1=4096\r\nX2=600\r\nX3=12\r\nVMAX=3000\r\nACC=5000\r\nDEC=5000\r\n";
const char* const kCapture = "-->P \"HELLO, WORLD\"\r\nHELLO, WORLD\r\n-->RUN 10\r\nCYCLE DONE\r\n-->\r\n";

bool writeFile(const QString& path, const char* text) {
    QFile file(path);
    return file.open(QIODevice::WriteOnly | QIODevice::Truncate) && file.write(text) >= 0;
}

void sendKey(QWidget* to, int key, Qt::KeyboardModifiers modifiers) {
    QKeyEvent override(QEvent::ShortcutOverride, key, modifiers);
    QCoreApplication::sendEvent(to, &override);
    QKeyEvent press(QEvent::KeyPress, key, modifiers);
    QCoreApplication::sendEvent(to, &press);
    QKeyEvent release(QEvent::KeyRelease, key, modifiers);
    QCoreApplication::sendEvent(to, &release);
}

// The status bar's keys label says a chord waits for its second key ("^K ...").
bool chordShown(const MainWindow& window) {
    const QList<QLabel*> labels = window.findChildren<QLabel*>();
    return std::any_of(labels.cbegin(), labels.cend(), [](const QLabel* label) {
        return label->isVisible() && label->width() > 0 && label->text().contains(QLatin1String("^K"));
    });
}
} // namespace

std::vector<ScreenshotTour::Step> tabsTourSteps(MainWindow& window, const QDir& outputDir) {
    EditorArea* area = window.editorArea();
    EditorTabs* tabs = area->tabs();
    auto opened = std::make_shared<QList<QPointer<editor::ProgramEditor>>>();
    auto sizeDialog = std::make_shared<QPointer<editor::EditorSizeDialog>>();
    const QString motion = outputDir.absoluteFilePath(QStringLiteral("MOTION.BDS"));
    std::vector<ScreenshotTour::Step> steps;

    steps.push_back({.name = QStringLiteral("editor-tabs"),
                     .act =
                         [area, tabs, opened, outputDir, motion] {
                             const QString vars = outputDir.absoluteFilePath(QStringLiteral("SETUP.VAR"));
                             const QString capture = outputDir.absoluteFilePath(QStringLiteral("SESSION.CAP"));
                             writeFile(motion, kMotionProgram);
                             writeFile(vars, kVariables);
                             writeFile(capture, kCapture);
                             for (const QString& path : {vars, capture, motion}) {
                                 area->documents()->openFile(path);
                                 opened->append(tabs->currentEditor());
                             }
                             editor::ProgramEditor* editor = tabs->currentEditor();
                             editor->setCursorPosition(11, 0);
                             editor->setFocus();
                             // The classic keymap, halfway through a chord: the status bar shows "^K ...".
                             area->applyKeymap(QStringLiteral("classic"));
                             sendKey(editor, Qt::Key_K, Qt::ControlModifier);
                         },
                     .ready =
                         [&window, tabs, opened] {
                             if (opened->size() != 3 || tabs->count() < 4) return false;
                             // "Opened <path>" folds the status bar's editor cells away while it shows (a long
                             // path folds the keys label: StatusBarRoom): the shot is of the chord, not of it.
                             window.statusBar()->clearMessage();
                             if (chordShown(window)) return true;
                             // Focus left the editor (a loaded machine: another window took it) and the pending
                             // chord went with it: type ^K again, and grab only once it stays shown.
                             editor::ProgramEditor* editor = tabs->currentEditor();
                             editor->setFocus();
                             sendKey(editor, Qt::Key_K, Qt::ControlModifier);
                             return false;
                         },
                     .grab = [&window] { return TourShot::of(&window); },
                     .cleanUp = [area] { area->reloadKeymap(); }});

    steps.push_back({.name = QStringLiteral("editor-find"),
                     .act =
                         [area] {
                             editor::FindBar* find = area->findBar();
                             area->currentEditor()->setCursorPosition(0, 0);
                             find->showReplace();
                             find->setSearchText(QStringLiteral("X3"));
                             find->setReplaceText(QStringLiteral("X9"));
                             find->setWholeWords(true);
                             find->findNext();
                             find->findNext();
                         },
                     .ready = [area] { return area->findBar()->isVisible(); },
                     .grab = [&window] { return TourShot::of(&window); },
                     .text = [area] { return area->findBar()->statusText(); },
                     .cleanUp =
                         [area] {
                             area->findBar()->setWholeWords(false);
                             area->findBar()->hide();
                         }});

    steps.push_back(ScreenshotTour::dialogStep(QStringLiteral("editor-goto-line"), [area] {
        editor::GoToLineDialog* goToLine = area->actions()->showGoToLine();
        goToLine->setCounting(editor::LineCounting::WithoutComments);
        goToLine->setLineNumber(6);
        return goToLine;
    }));

    steps.push_back({.name = QStringLiteral("editor-size"),
                     .act = [area, sizeDialog] { *sizeDialog = area->actions()->showSize(); },
                     .ready = [sizeDialog] { return *sizeDialog && (*sizeDialog)->isVisible(); },
                     .grab = [sizeDialog] { return TourShot::of(*sizeDialog); },
                     .text = [sizeDialog] { return *sizeDialog ? (*sizeDialog)->figuresText() : QString(); },
                     .cleanUp =
                         [tabs, opened, sizeDialog] {
                             if (*sizeDialog) (*sizeDialog)->close();
                             for (const auto& editor : *opened)
                                 if (editor) tabs->removeEditor(editor);
                             tabs->setCurrentIndex(0);
                         }});
    return steps;
}

} // namespace app
