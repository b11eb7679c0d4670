// DocumentController: the File menu's work on the program editor — new, open, save, save as, and asking
// about unsaved edits. All dialogs are opened non-blocking (open(), never exec()); results arrive later.
// GUI thread only.
#pragma once

#include <QObject>
#include <QString>

#include <functional>

namespace editor {
class ProgramEditor;
}

namespace app {

class DocumentController final : public QObject {
    Q_OBJECT
public:
    // dialogParent: the window the file and question dialogs belong to.
    DocumentController(editor::ProgramEditor& editor, QWidget* dialogParent);

    // Opens a read-only file (such as a resource) as an unnamed document called displayName.
    void openTemplate(const QString& path, const QString& displayName);
    void newDocument();
    void open();
    void save();
    void saveAs();
    // Calls proceed once unsaved edits are saved or discarded; never if the user cancels.
    void whenSafeToDiscard(std::function<void()> proceed);

    // "hello.bds", "untitled.bds" or the file's name.
    QString displayName() const;

signals:
    void documentChanged(); // a different document (or name) is in the editor
    void statusMessage(const QString& message);

private:
    void saveThen(std::function<void()> then);
    void saveAsThen(std::function<void()> then);
    bool writeTo(const QString& path);
    void loadFrom(const QString& path);
    void showError(const QString& message);

    editor::ProgramEditor& m_editor;
    QWidget* m_dialogParent;
    QString m_untitledName;
};

} // namespace app
