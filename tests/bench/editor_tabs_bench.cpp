// Opening a 2,000-line BDS5 program the way a user does (File > Open: a new tab, BDS5 language support,
// load, highlight of the whole text) and what each keystroke costs on top (status-bar size figures, the
// autosave write of the whole buffer). Prints figures; never asserts a time.
#include "app/editing/autosaver.h"
#include "app/editing/document_controller.h"
#include "app/editing/editor_area.h"
#include "app/editing/editor_tabs.h"
#include "app/main_window.h"

#include "editor/editor_size.h"
#include "editor/program_editor.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QFile>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTextStream>

#include <algorithm>
#include <vector>

namespace {
constexpr int kLines = 2000;
constexpr int kRuns = 7;

// A program in the manual's style: labels, moves, waits, IF blocks, prints, comments.
QByteArray program() {
    QByteArray text;
    for (int i = 0; text.count('\n') < kLines; ++i) {
        text += "; BLOCK " + QByteArray::number(i) + " - INDEX, WAIT, CHECK\r\n";
        text += QByteArray::number(100 + i) + "$                 ;STEP " + QByteArray::number(i) + "\r\n";
        text += "MI X1 X2                ;ONE STEP\r\n";
        text += "W 2\r\n";
        text += "IF X3 GT 0\r\n  X3 = X3-1\r\nELSE\r\n  P \"DONE\"\r\nENDIF\r\n";
        text += "VMAX = 3000\r\n";
    }
    while (text.count('\n') > kLines) text.chop(text.size() - text.lastIndexOf("\r\n", text.size() - 3) - 2);
    return text;
}

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    return values[values.size() / 2];
}
} // namespace

int main(int argc, char** argv) {
    QApplication application(argc, argv);
    QStandardPaths::setTestModeEnabled(true);
    QTemporaryDir dir;
    qputenv("SERVODESK_RECOVERY_DIR", dir.filePath(QStringLiteral("recovery")).toUtf8());
    const QString path = dir.filePath(QStringLiteral("BIG.BDS"));
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly)) return 1;
    const QByteArray bytes = program();
    file.write(bytes);
    file.close();

    app::MainWindow window;
    app::EditorArea* area = window.editorArea();
    std::vector<double> openMs;
    std::vector<double> sizeUs;
    std::vector<double> autosaveMs;
    for (int run = 0; run < kRuns; ++run) {
        QElapsedTimer timer;
        timer.start();
        area->documents()->openFile(path);
        editor::ProgramEditor* editor = area->currentEditor();
        editor->SendScintilla(QsciScintilla::SCI_COLOURISE, 0, -1); // highlight all of it, not just the view
        openMs.push_back(timer.nsecsElapsed() / 1e6);

        timer.restart();
        const auto size = editor::measureText(editor->text(), true);
        const QString status = area->sizeStatusText();
        sizeUs.push_back(timer.nsecsElapsed() / 1e3);
        if (size.lines != kLines || status.isEmpty()) return 1;

        editor->append(QStringLiteral("B\r\n"));
        timer.restart();
        area->autosaver()->flush();
        autosaveMs.push_back(timer.nsecsElapsed() / 1e6);
        editor->setModified(false);
        area->tabs()->removeEditor(editor);
    }
    QTextStream out(stdout);
    out << "editor tabs bench: " << kLines << " lines, " << bytes.size() << " bytes, median of " << kRuns << " runs\n";
    out << QStringLiteral("  open in a new tab + highlight all: %1 ms (goal < 50 ms)\n").arg(median(openMs), 0, 'f', 2);
    out << QStringLiteral("  size figures per keystroke:        %1 us\n").arg(median(sizeUs), 0, 'f', 1);
    out << QStringLiteral("  autosave write of the buffer:      %1 ms (every 3 s at most while typing)\n")
               .arg(median(autosaveMs), 0, 'f', 2);
    return 0;
}
