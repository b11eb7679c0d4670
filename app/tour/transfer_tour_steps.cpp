// Transfer tour steps: real transfers against the simulated drive at 9600 baud, grabbed as a user sees them.
#include "transfer_tour_steps.h"

#include "families/bds5/bds5_workspace.h"

#include "editor_area.h"
#include "editor_tabs.h"
#include "main_window.h"
#include "families/bds5/program_controller.h"
#include "terminal_widget.h"
#include "transfer_dialog.h"
#include "transfer_markers.h"
#include "families/bds5/variables_controller.h"

#include "editor/program_editor.h"

#include <QAbstractButton>
#include <QMessageBox>
#include <QPainter>
#include <QProgressBar>
#include <QStatusBar>

namespace app {

namespace {

// An indexing program with Motion Link-style comments, sent without them; the drive counts only code lines,
// so its error on drive line 9 must be marked on editor line 15. The table makes the download last long
// enough at 9600 baud to be seen in progress.
QString tourProgram() {
    QString text = QStringLiteral("; INDEX.BDS - five-station indexer (ServoDesk screenshot tour)\n"
                                  "; Sent without comments: the drive's line numbers count code lines only.\n"
                                  "\n"
                                  "10$                     ; start of cycle\n"
                                  "  X1=0                  ; station counter\n"
                                  "  P \"INDEXING\"          ; tell the operator\n"
                                  "20$                     ; next station\n"
                                  "  X1=X1+1\n"
                                  "  ? X1 LT 5 GOTO 20     ; five stations\n"
                                  "  P \"DONE \" X1\n"
                                  "  GOSUB 30\n"
                                  "  B\n"
                                  "\n"
                                  "30$                     ; settle before the next cycle\n"
                                  "  D -1                  ; a negative dwell: the drive answers ERR 83\n"
                                  "  RET\n"
                                  "\n"
                                  "; station positions, counts\n");
    for (int i = 0; i < 120; ++i)
        text += QStringLiteral("X%1=%2\n").arg(101 + i).arg((i + 1) * 4096);
    return text;
}

// The window with the (separate, non-modal) transfer dialog drawn over its centre, as the user sees them.
TourShot windowWithDialog(MainWindow& window) {
    TourShot shot = TourShot::of(&window);
    if (TransferDialog* dialog = window.findChild<TransferDialog*>(); dialog && dialog->isVisible()) {
        const QSize room = window.size() - dialog->size();
        const QPoint at(room.width() / 2, room.height() / 3);
        QPainter(&shot.picture).fillRect(QRect(at, dialog->size()).adjusted(-1, -1, 1, 1), QColor(0x60, 0x60, 0x60));
        shot.paintOver(dialog, at);
    }
    return shot;
}

bool statusSays(MainWindow& window, const QString& text) {
    return window.statusBar()->currentMessage().contains(text);
}

} // namespace

std::vector<ScreenshotTour::Step> transferTourSteps(MainWindow& window) {
    std::vector<ScreenshotTour::Step> steps;
    steps.push_back({.name = QStringLiteral("program-download-progress"),
                     .act =
                         [&window] {
                             EditorTabs& tabs = *window.editorArea()->tabs();
                             editor::ProgramEditor* editor = tabs.addEditor(QStringLiteral("INDEX.BDS"));
                             editor->setText(tourProgram());
                             tabs.refreshTab(editor);
                             window.programController().setStripComments(true);
                             window.programController().download();
                             // The editor underlines D -1 (kept for the run-time error shot): the user
                             // downloads anyway to see the drive's own answer.
                             if (QMessageBox* question = window.programController().downloadQuestion())
                                 for (QAbstractButton* button : question->buttons())
                                     if (question->buttonRole(button) == QMessageBox::AcceptRole) button->click();
                         },
                     .ready =
                         [] {
                             TransferDialog* dialog = TransferDialog::active();
                             const auto* bar = dialog ? dialog->findChild<QProgressBar*>() : nullptr;
                             return bar && bar->maximum() > 0 && bar->value() >= 30 &&
                                    bar->value() < bar->maximum() - 40;
                         },
                     .grab = [&window] { return windowWithDialog(window); }});
    steps.push_back({.name = QStringLiteral("program-download-result"),
                     .ready =
                         [&window] {
                             return !TransferDialog::active() &&
                                    statusSays(window, QStringLiteral("Verified"));
                         },
                     .grab = [&window] { return TourShot::of(&window); },
                     .text = [&window] { return window.statusBar()->currentMessage(); }});
    steps.push_back({.name = QStringLiteral("program-error-line"),
                     .act =
                         [&window] {
                             window.programController().setStripComments(false);
                             window.terminal()->setFocus();
                             // The same bytes a user's Enter sends after typing RUN 10.
                             emit window.terminal()->bytesTyped(QByteArrayLiteral("RUN 10\r"));
                         },
                     .ready =
                         [&window] {
                             return !TransferMarkers::markedLines(*window.editor()).isEmpty() &&
                                    window.terminal()->text().endsWith(QStringLiteral("-->"));
                         },
                     .grab = [&window] { return TourShot::of(&window); },
                     .text =
                         [&window] {
                             return QStringLiteral("marked lines: %1\n%2")
                                 .arg(TransferMarkers::markedLines(*window.editor()).value(0))
                                 .arg(window.statusBar()->currentMessage());
                         }});
    steps.push_back({.name = QStringLiteral("variables-file"),
                     .act = [&window] { window.bds5().variablesController().fromDrive(); },
                     .ready =
                         [&window] {
                             return !TransferDialog::active() &&
                                    window.windowTitle().startsWith(QStringLiteral("drive-variables"));
                         },
                     .grab = [&window] { return TourShot::of(&window); },
                     .text = [&window] { return window.editor()->text(); },
                     // Later steps expect the tour's first tab (the sample program) in front again.
                     .cleanUp = [&window] { window.editorArea()->tabs()->setCurrentIndex(0); }});
    return steps;
}

} // namespace app
