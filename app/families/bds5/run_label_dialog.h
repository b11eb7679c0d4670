// RunLabelDialog: Drive > Run Label's choice for the BDS5 — an editable list of the numbered labels of the
// program in the editor ("10$  PROGRAM STARTS HERE"), so a label that is only in the drive can still be
// typed; empty runs RUN alone. Text that names no label keeps Run disabled and says why. It only chooses;
// DriveActions sends. GUI thread only.
#pragma once

#include <QDialog>
#include <QList>

#include <optional>

class QComboBox;
class QLabel;
class QPushButton;

namespace app {

class RunLabelDialog final : public QDialog {
    Q_OBJECT
public:
    // A numbered label of the program (0-500, L3728-3747) and the comment on its line.
    struct Label {
        int number = 0;
        QString comment;
    };
    static constexpr int kRunAlone = -1; // RUN with no label: multitasking only

    explicit RunLabelDialog(const QList<Label>& labels, QWidget* parent = nullptr);

    // The numbered labels of a BDS5 program, in program order (the editor's outline: the drive's own lexer).
    // Dedicated labels (POWER-UP$, A$...) are left out: RUN cannot name them (seed-bds5 §4.5).
    static QList<Label> labelsIn(const QString& programText);
    // As the list shows it: "10$  PROGRAM STARTS HERE".
    static QString itemText(const Label& label);
    // The label a text names: "10", "10$", or a list entry "10$  comment"; kRunAlone for an empty text;
    // nothing when it names no label (a word, a number beyond 500).
    static std::optional<int> labelOf(const QString& text);

    QComboBox* combo() const { return m_combo; }
    QPushButton* runButton() const { return m_run; }
    // What the dialog says under the list: why Run is disabled, or that a typed label is not the editor's.
    QString note() const;

signals:
    // Accepted (Run or Enter) with a label, or kRunAlone.
    void runRequested(int label);

private:
    void check();

    QList<Label> m_labels;
    QComboBox* m_combo;
    QLabel* m_note;
    QPushButton* m_run;
};

} // namespace app
