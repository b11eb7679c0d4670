// FindBar: layout and Scintilla target searches.
#include "find_bar.h"

#include <Qsci/qsciscintilla.h>

#include <QCheckBox>
#include <QGridLayout>
#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QToolButton>

namespace editor {

FindBar::FindBar(QWidget* parent)
    : QWidget(parent), m_find(new QLineEdit(this)), m_replace(new QLineEdit(this)),
      m_replaceLabel(new QLabel(tr("Replace with:"), this)), m_replaceButton(new QPushButton(tr("&Replace"), this)),
      m_replaceAllButton(new QPushButton(tr("Replace &All"), this)),
      m_matchCase(new QCheckBox(tr("Match &case"), this)), m_wholeWords(new QCheckBox(tr("&Whole words"), this)),
      m_regex(new QCheckBox(tr("Regular e&xpression"), this)), m_status(new QLabel(this)) {
    setObjectName(QStringLiteral("findBar"));
    m_find->setObjectName(QStringLiteral("findText"));
    m_replace->setObjectName(QStringLiteral("replaceText"));
    m_status->setObjectName(QStringLiteral("findStatus"));
    m_find->setPlaceholderText(tr("Find"));
    m_replace->setPlaceholderText(tr("Replace with"));
    m_find->setClearButtonEnabled(true);
    m_find->setMinimumWidth(fontMetrics().horizontalAdvance(QLatin1Char('M')) * 24);
    m_replace->setMinimumWidth(m_find->minimumWidth());
    m_status->setMinimumWidth(fontMetrics().horizontalAdvance(QStringLiteral("Match 9999 of 9999")));

    auto* previous = new QPushButton(tr("&Previous"), this);
    auto* next = new QPushButton(tr("&Next"), this);
    auto* closeButton = new QToolButton(this);
    closeButton->setText(QStringLiteral("\u2715"));
    closeButton->setAutoRaise(true);
    closeButton->setToolTip(tr("Close the find bar (Esc)"));

    auto* layout = new QGridLayout(this);
    layout->setContentsMargins(6, 4, 6, 4);
    layout->addWidget(new QLabel(tr("Find:"), this), 0, 0);
    layout->addWidget(m_find, 0, 1);
    layout->addWidget(previous, 0, 2);
    layout->addWidget(next, 0, 3);
    layout->addWidget(m_matchCase, 0, 4);
    layout->addWidget(m_wholeWords, 0, 5);
    layout->addWidget(m_regex, 0, 6);
    layout->addWidget(m_status, 0, 7);
    layout->addWidget(closeButton, 0, 8, Qt::AlignRight);
    layout->addWidget(m_replaceLabel, 1, 0);
    layout->addWidget(m_replace, 1, 1);
    layout->addWidget(m_replaceButton, 1, 2);
    layout->addWidget(m_replaceAllButton, 1, 3);
    layout->setColumnStretch(1, 1);
    layout->setColumnStretch(7, 1);

    connect(next, &QPushButton::clicked, this, &FindBar::findNext);
    connect(previous, &QPushButton::clicked, this, &FindBar::findPrevious);
    connect(m_replaceButton, &QPushButton::clicked, this, &FindBar::replaceCurrent);
    connect(m_replaceAllButton, &QPushButton::clicked, this, &FindBar::replaceAll);
    connect(closeButton, &QToolButton::clicked, this, &FindBar::closeBar);
    connect(m_find, &QLineEdit::returnPressed, this, &FindBar::findNext);
    connect(m_replace, &QLineEdit::returnPressed, this, &FindBar::replaceCurrent);
    connect(m_find, &QLineEdit::textEdited, this, [this] {
        // Incremental: search again from the start of the current match as the user types.
        if (!m_editor) return;
        const long from = m_editor->SendScintilla(QsciScintilla::SCI_GETSELECTIONSTART);
        m_editor->SendScintilla(QsciScintilla::SCI_SETEMPTYSELECTION, from);
        if (!m_find->text().isEmpty()) findNext();
    });
    hide();
}

void FindBar::setEditor(QsciScintilla* editor) {
    m_editor = editor;
    m_status->clear();
}

void FindBar::showFind() {
    if (m_editor && m_editor->hasSelectedText() && !m_editor->selectedText().contains(QLatin1Char('\n')))
        m_find->setText(m_editor->selectedText());
    for (QWidget* w : {static_cast<QWidget*>(m_replaceLabel), static_cast<QWidget*>(m_replace),
                       static_cast<QWidget*>(m_replaceButton), static_cast<QWidget*>(m_replaceAllButton)})
        w->setVisible(false);
    show();
    m_find->setFocus();
    m_find->selectAll();
}

void FindBar::showReplace() {
    showFind();
    for (QWidget* w : {static_cast<QWidget*>(m_replaceLabel), static_cast<QWidget*>(m_replace),
                       static_cast<QWidget*>(m_replaceButton), static_cast<QWidget*>(m_replaceAllButton)})
        w->setVisible(true);
    if (!m_find->text().isEmpty()) m_replace->setFocus();
}

void FindBar::setSearchText(const QString& text) {
    m_find->setText(text);
}
QString FindBar::searchText() const {
    return m_find->text();
}
void FindBar::setReplaceText(const QString& text) {
    m_replace->setText(text);
}
void FindBar::setMatchCase(bool on) {
    m_matchCase->setChecked(on);
}
void FindBar::setWholeWords(bool on) {
    m_wholeWords->setChecked(on);
}
void FindBar::setRegularExpression(bool on) {
    m_regex->setChecked(on);
}
QString FindBar::statusText() const {
    return m_status->text();
}

bool FindBar::findNext() {
    if (!m_editor || m_find->text().isEmpty()) return false;
    const long length = m_editor->SendScintilla(QsciScintilla::SCI_GETLENGTH);
    const long from = m_editor->SendScintilla(QsciScintilla::SCI_GETSELECTIONEND);
    if (auto match = searchRange(from, length)) return select(match, false);
    return select(searchRange(0, from), true);
}

bool FindBar::findPrevious() {
    if (!m_editor || m_find->text().isEmpty()) return false;
    const long length = m_editor->SendScintilla(QsciScintilla::SCI_GETLENGTH);
    const long from = m_editor->SendScintilla(QsciScintilla::SCI_GETSELECTIONSTART);
    if (auto match = searchRange(from, 0)) return select(match, false);
    return select(searchRange(length, from), true);
}

bool FindBar::replaceCurrent() {
    if (!m_editor || m_find->text().isEmpty()) return false;
    const long start = m_editor->SendScintilla(QsciScintilla::SCI_GETSELECTIONSTART);
    const long end = m_editor->SendScintilla(QsciScintilla::SCI_GETSELECTIONEND);
    const auto match = searchRange(start, end);
    if (match && match->start == start && match->end == end && end > start) {
        const QByteArray with = m_replace->text().toUtf8();
        m_editor->SendScintilla(QsciScintilla::SCI_SETTARGETSTART, start);
        m_editor->SendScintilla(QsciScintilla::SCI_SETTARGETEND, end);
        const int message =
            m_regex->isChecked() ? QsciScintilla::SCI_REPLACETARGETRE : QsciScintilla::SCI_REPLACETARGET;
        const long replaced = m_editor->SendScintilla(message, with.size(), with.constData());
        m_editor->SendScintilla(QsciScintilla::SCI_SETEMPTYSELECTION, start + replaced);
    }
    return findNext();
}

int FindBar::replaceAll() {
    if (!m_editor || m_find->text().isEmpty()) return 0;
    const QByteArray with = m_replace->text().toUtf8();
    const int message = m_regex->isChecked() ? QsciScintilla::SCI_REPLACETARGETRE : QsciScintilla::SCI_REPLACETARGET;
    int count = 0;
    long from = 0;
    m_editor->beginUndoAction();
    while (auto match = searchRange(from, m_editor->SendScintilla(QsciScintilla::SCI_GETLENGTH))) {
        m_editor->SendScintilla(QsciScintilla::SCI_SETTARGETSTART, match->start);
        m_editor->SendScintilla(QsciScintilla::SCI_SETTARGETEND, match->end);
        const long replaced = m_editor->SendScintilla(message, with.size(), with.constData());
        from = match->start + replaced + (match->end == match->start ? 1 : 0); // never loop on an empty match
        ++count;
    }
    m_editor->endUndoAction();
    showStatus(count ? tr("Replaced %n", nullptr, count) : tr("Not found"), count == 0);
    return count;
}

std::optional<FindBar::Match> FindBar::searchRange(long from, long to) const {
    const QByteArray text = needle();
    m_editor->SendScintilla(QsciScintilla::SCI_SETSEARCHFLAGS, searchFlags());
    m_editor->SendScintilla(QsciScintilla::SCI_SETTARGETSTART, from);
    m_editor->SendScintilla(QsciScintilla::SCI_SETTARGETEND, to);
    const long found = m_editor->SendScintilla(QsciScintilla::SCI_SEARCHINTARGET, text.size(), text.constData());
    if (found < 0) return std::nullopt;
    return Match{found, long(m_editor->SendScintilla(QsciScintilla::SCI_GETTARGETEND))};
}

int FindBar::searchFlags() const {
    int flags = 0;
    if (m_matchCase->isChecked()) flags |= QsciScintilla::SCFIND_MATCHCASE;
    if (m_wholeWords->isChecked()) flags |= QsciScintilla::SCFIND_WHOLEWORD;
    if (m_regex->isChecked()) flags |= QsciScintilla::SCFIND_REGEXP | QsciScintilla::SCFIND_CXX11REGEX;
    return flags;
}

QByteArray FindBar::needle() const {
    return m_editor->isUtf8() ? m_find->text().toUtf8() : m_find->text().toLatin1();
}

bool FindBar::select(const std::optional<Match>& match, bool wrapped) {
    if (!match) {
        showStatus(tr("Not found"), true);
        return false;
    }
    m_editor->SendScintilla(QsciScintilla::SCI_SETSEL, match->start, match->end);
    m_editor->SendScintilla(QsciScintilla::SCI_SCROLLCARET);
    int total = 0;
    const int index = countBefore(match->start, &total) + 1;
    QString text = tr("Match %1 of %2").arg(index).arg(total);
    if (wrapped) text += tr(" (wrapped)");
    showStatus(text);
    return true;
}

int FindBar::countBefore(long position, int* total) const {
    int before = 0;
    *total = 0;
    long from = 0;
    const long length = m_editor->SendScintilla(QsciScintilla::SCI_GETLENGTH);
    while (from <= length) {
        const auto match = searchRange(from, length);
        if (!match) break;
        if (match->start < position) ++before;
        ++*total;
        from = match->end > match->start ? match->end : match->end + 1;
    }
    return before;
}

void FindBar::showStatus(const QString& text, bool bad) {
    m_status->setText(text);
    m_status->setStyleSheet(bad ? QStringLiteral("color: #b3261e;") : QString());
    m_find->setStyleSheet(bad && !m_find->text().isEmpty() ? QStringLiteral("background: #fde7e9;") : QString());
}

void FindBar::keyPressEvent(QKeyEvent* event) {
    if (event->key() == Qt::Key_Escape) {
        closeBar();
        return;
    }
    if (event->key() == Qt::Key_Return && (event->modifiers() & Qt::ShiftModifier)) {
        findPrevious();
        return;
    }
    QWidget::keyPressEvent(event);
}

void FindBar::closeBar() {
    hide();
    if (m_editor) m_editor->setFocus();
    emit closed();
}

} // namespace editor
