// HelpPopup: the tooltip-like box F1 shows under the word it explains. A frameless tool-tip window, not a
// dialog: it takes no focus and its owner hides it on the next key, click, scroll or focus change.
#pragma once

#include <QFrame>

class QLabel;

namespace editor {

class HelpPopup final : public QFrame {
    Q_OBJECT
public:
    static constexpr int kMaxWidth = 560; // pixels

    explicit HelpPopup(QWidget* parent);

    // Shows html with its top-left corner at global, kept on the screen (above `avoidTop` when it would
    // run off the bottom: the line the help is about stays visible).
    void showHtml(const QString& html, const QPoint& global, int avoidTop);
    QString html() const;
    void setDarkTheme(bool dark);

private:
    QLabel* m_label;
};

} // namespace editor
