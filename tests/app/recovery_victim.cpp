// The crash victim for recovery_crash_test: a real ServoDesk main window (the same MainWindow main()
// builds) opens FILE, gets TEXT typed into its editor as key events, and — once the real autosave has
// written the recovery file — prints "AUTOSAVED" and keeps running until the test kills it with SIGKILL.
// usage: recovery_victim FILE TEXT   (SERVODESK_RECOVERY_DIR chooses the recovery folder)
#include "app/editing/autosaver.h"
#include "app/editing/document_controller.h"
#include "app/editing/editor_area.h"
#include "app/main_window.h"

#include "editor/program_editor.h"
#include "resources/resources.h"

#include <QApplication>
#include <QTest>
#include <QTextStream>

int main(int argc, char** argv) {
    QApplication application(argc, argv);
    QCoreApplication::setOrganizationName(QStringLiteral("ServoDesk"));
    QCoreApplication::setApplicationName(QStringLiteral("ServoDeskRecoveryTest"));
    resources::initialize();
    const QStringList args = QCoreApplication::arguments();
    if (args.size() != 3) return 2;

    app::MainWindow window;
    window.show();
    if (!window.editorArea()->documents()->openFile(args[1])) return 3;
    QObject::connect(window.editorArea()->autosaver(), &app::Autosaver::buffersWritten, &window,
                     [] { QTextStream(stdout) << "AUTOSAVED" << Qt::endl; });
    editor::ProgramEditor* editor = window.editor();
    editor->setFocus();
    editor->SendScintilla(QsciScintilla::SCI_DOCUMENTEND);
    QTest::keyClicks(editor, args[2]);
    return QApplication::exec();
}
