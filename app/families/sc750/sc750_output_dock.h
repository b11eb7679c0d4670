// Sc750OutputDock: Motion Dialogue's Output window (F4, L2788-L2794): the running program's serial PRINT
// output as it arrives, and a line the user types for the program's INPUT (sent with CR on Enter).
// GUI thread only.
#pragma once

#include <QDockWidget>

class QLineEdit;
class QPlainTextEdit;

namespace app {

class Sc750OutputDock final : public QDockWidget {
    Q_OBJECT
public:
    static constexpr int kMaxBlocks = 5000; // lines kept; older ones scroll away

    explicit Sc750OutputDock(QWidget* parent = nullptr);

    // Bytes from the program (CR LF and lone CR end a line).
    void display(const QByteArray& bytes);
    void clear();
    QString text() const;
    void focusInput();
    QLineEdit* input() const { return m_input; }

signals:
    // What the user typed for INPUT, with its CR.
    void inputTyped(const QByteArray& bytes);
    // Ctrl C with no text selected: stop the program (L2692).
    void stopRequested();

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    QPlainTextEdit* m_view;
    QLineEdit* m_input;
    bool m_pendingCr = false;
};

} // namespace app
