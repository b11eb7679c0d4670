// CaptureDock: the Capture view (object name "captureDock") — start/stop capturing, the captured text as
// the .CAP file holds it or both directions with times, its size, and Open/Save of .CAP files. Also owns
// the actions of the Capture menu. File dialogs are opened without blocking.
#pragma once

#include <QDockWidget>

class QAction;
class QComboBox;
class QLabel;
class QMenu;
class QPlainTextEdit;
class QTimer;

namespace app {

class CaptureLog;

class CaptureDock final : public QDockWidget {
    Q_OBJECT
public:
    CaptureDock(CaptureLog& log, QWidget* parent = nullptr);

    enum class View { AsSaved, Transcript };
    void setView(View view);
    // Fills the Capture menu: Start, Stop, View, Open..., Save As...
    void addToMenu(QMenu* menu);

    QAction* startAction() const { return m_start; }
    QAction* stopAction() const { return m_stop; }
    // What the view shows now, and its size line ("1,234 bytes received ...").
    QString shownText() const;
    QString sizeText() const;
    // The non-blocking file dialogs behind Open... and Save As...
    void openCap();
    void saveCapAs();

private:
    void refresh();
    void scheduleRefresh();
    void updateActions();

    CaptureLog& m_log;
    QAction* m_start;
    QAction* m_stop;
    QAction* m_clear;
    QAction* m_open;
    QAction* m_save;
    QComboBox* m_viewChoice;
    QPlainTextEdit* m_text;
    QLabel* m_size;
    QTimer* m_refresh;
};

} // namespace app
