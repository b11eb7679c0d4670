// FindBar: the non-modal find and replace bar under the editor (Motion Link's FIND A STRING, REPEAT LAST
// FIND and change; manual L1154-1156). It works on whichever editor it is given; the last search stays
// for "repeat last find" even while the bar is hidden. GUI thread only.
#pragma once

#include <QWidget>

#include <optional>

class QCheckBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QsciScintilla;

namespace editor {

class FindBar final : public QWidget {
    Q_OBJECT
public:
    explicit FindBar(QWidget* parent = nullptr);

    // The editor searched from now on (nullptr: none).
    void setEditor(QsciScintilla* editor);

    // Shows the bar for finding (replace row hidden) or for replacing, with the selected text (one
    // line) as the search, and puts the keyboard in the search field.
    void showFind();
    void showReplace();

    void setSearchText(const QString& text);
    QString searchText() const;
    void setReplaceText(const QString& text);
    void setMatchCase(bool on);
    void setWholeWords(bool on);
    void setRegularExpression(bool on);

    // Selects the next (previous) match after (before) the selection, wrapping at the end (start).
    // False when the text has no match. This is "repeat last find" when the bar is hidden.
    bool findNext();
    bool findPrevious();
    // Replaces the selected match and finds the next; when the selection is not a match, only finds.
    bool replaceCurrent();
    // Replaces every match as one undo step; returns how many.
    int replaceAll();

    // What the bar tells the user: "Match 2 of 5", "Not found", "Replaced 3".
    QString statusText() const;

signals:
    void closed();

protected:
    void keyPressEvent(QKeyEvent* event) override;

private:
    struct Match {
        long start = 0;
        long end = 0;
    };
    std::optional<Match> searchRange(long from, long to) const;
    int searchFlags() const;
    QByteArray needle() const;
    bool select(const std::optional<Match>& match, bool wrapped);
    int countBefore(long position, int* total) const;
    void showStatus(const QString& text, bool bad = false);
    void closeBar();

    QsciScintilla* m_editor = nullptr;
    QLineEdit* m_find;
    QLineEdit* m_replace;
    QLabel* m_replaceLabel;
    QPushButton* m_replaceButton;
    QPushButton* m_replaceAllButton;
    QCheckBox* m_matchCase;
    QCheckBox* m_wholeWords;
    QCheckBox* m_regex;
    QLabel* m_status;
};

} // namespace editor
