// RunLabelDialog: the program's labels in an editable list, and the check of what is typed.
#include "run_label_dialog.h"

#include "drive_core/bds5/bds5_program.h"
#include "editor/bds5_outline.h"
#include "settings/theme.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QRegularExpression>
#include <QVBoxLayout>

#include <algorithm>

namespace app {

QList<RunLabelDialog::Label> RunLabelDialog::labelsIn(const QString& programText) {
    QList<Label> labels;
    for (const editor::OutlineEntry& entry : editor::bds5Outline(programText)) {
        if (entry.kind != editor::OutlineEntry::Kind::Label) continue;
        const std::optional<int> number = labelOf(entry.name);
        if (number && *number != kRunAlone) labels.append({*number, entry.detail});
    }
    return labels;
}

QString RunLabelDialog::itemText(const Label& label) {
    const QString name = QStringLiteral("%1$").arg(label.number);
    return label.comment.isEmpty() ? name : QStringLiteral("%1  %2").arg(name, label.comment);
}

std::optional<int> RunLabelDialog::labelOf(const QString& text) {
    // label := NUMBER ['$'] — the first word only: a list entry carries its line's comment after it.
    static const QRegularExpression kLabel(QStringLiteral("^(\\d{1,3})\\$?(\\s|$)"));
    const QString trimmed = text.trimmed();
    if (trimmed.isEmpty()) return kRunAlone;
    const QRegularExpressionMatch match = kLabel.match(trimmed);
    if (!match.hasMatch()) return std::nullopt;
    const int number = match.captured(1).toInt();
    if (number > drive_core::bds5::kMaxLabel) return std::nullopt;
    return number;
}

RunLabelDialog::RunLabelDialog(const QList<Label>& labels, QWidget* parent)
    : QDialog(parent), m_labels(labels), m_combo(new QComboBox(this)), m_note(new QLabel(this)) {
    setObjectName(QStringLiteral("runLabelDialog"));
    setWindowTitle(tr("Run Label"));
    setMinimumWidth(440);
    auto* layout = new QVBoxLayout(this);

    auto* heading = new QLabel(this);
    heading->setWordWrap(true);
    heading->setText(labels.isEmpty()
                         ? tr("The program in the editor has no numbered labels (lines such as 10$). Type the "
                              "number of a label in the drive's program, or leave it empty for RUN alone "
                              "(multitasking only).")
                         : tr("Labels of the program in the editor. The drive runs the program it holds: if that "
                              "differs, download it first. Another label number can be typed; empty is RUN alone "
                              "(multitasking only)."));
    layout->addWidget(heading);

    m_combo->setObjectName(QStringLiteral("runLabelCombo"));
    m_combo->setEditable(true);
    m_combo->setInsertPolicy(QComboBox::NoInsert);
    for (const Label& label : labels) m_combo->addItem(itemText(label), label.number);
    m_combo->lineEdit()->setPlaceholderText(tr("Label number, e.g. 10"));
    layout->addWidget(m_combo);

    m_note->setObjectName(QStringLiteral("runLabelNote"));
    m_note->setWordWrap(true);
    layout->addWidget(m_note);

    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Cancel, this);
    m_run = buttons->addButton(tr("&Run"), QDialogButtonBox::AcceptRole);
    m_run->setObjectName(QStringLiteral("runLabelButton"));
    m_run->setDefault(true);
    layout->addWidget(buttons);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(m_combo, &QComboBox::editTextChanged, this, &RunLabelDialog::check); // typed or chosen
    connect(this, &QDialog::accepted, this, [this] {
        if (const std::optional<int> label = labelOf(m_combo->currentText())) emit runRequested(*label);
    });
    check(); // the first label is chosen (an empty text when there is none)
    m_combo->setFocus();
    m_combo->lineEdit()->selectAll();
}

QString RunLabelDialog::note() const {
    return m_note->isHidden() ? QString() : m_note->text();
}

void RunLabelDialog::check() {
    const std::optional<int> label = labelOf(m_combo->currentText());
    m_run->setEnabled(label.has_value());
    QString note;
    bool error = false;
    if (!label) {
        note = tr("\u201c%1\u201d is not a label: type a number from 0 to %2 (10 or 10$), or leave it empty for "
                  "RUN alone.")
                   .arg(m_combo->currentText().trimmed())
                   .arg(drive_core::bds5::kMaxLabel);
        error = true;
    } else if (*label == kRunAlone) {
        note = tr("RUN alone: multitasking starts, no main routine.");
    } else if (std::none_of(m_labels.cbegin(), m_labels.cend(), [&](const Label& l) { return l.number == *label; })) {
        note = tr("%1$ is not in the program in the editor: the drive answers ERR 70 if its program has no such "
                  "label either.")
                   .arg(*label);
    }
    Theme::showStatus(*m_note, note, error);
    m_note->setVisible(!note.isEmpty());
}

} // namespace app
