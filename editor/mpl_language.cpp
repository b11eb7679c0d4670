// MplLanguage: lexer, folding and the program check wired into one .mpl editor; F1 help and the key
// handling are LanguageSupport's, fed with the PMC-960 catalog's help.
#include "mpl_language.h"

#include "mpl_help.h"
#include "mpl_lexer.h"
#include "mpl_line_styler.h"
#include "mpl_outline.h"
#include "program_editor.h"

#include <Qsci/qscistyle.h>

namespace editor {

namespace {
QsciStyle annotationStyle(const QFont& base) {
    QFont font = base;
    font.setPointSizeF(font.pointSizeF() * 0.9);
    return QsciStyle(-1, QStringLiteral("MPL check"), QColor(0x9f, 0x1c, 0x24), QColor(0xff, 0xf0, 0xef), font, true);
}
} // namespace

MplLanguage::MplLanguage(ProgramEditor& editor)
    : LanguageSupport(
          editor,
          {&mplTopicAt, &mplHelpHtml, tr("<b>%1</b> &nbsp;is not an MPL command, parameter or error code."), false},
          {&mplOutline, tr("No routines (@<label> lines) in this program yet.")}, false),
      m_lexer(new MplLexer) {
    m_editor.setLanguageLexer(m_lexer);
    m_lexer->applyStyles(m_editor.font());
    m_editor.setFolding(QsciScintilla::BoxedTreeFoldStyle, kFoldMargin);
    m_editor.setAnnotationDisplay(QsciScintilla::AnnotationIndented);
    m_check.setSingleShot(true);
    m_check.setInterval(kCheckDelayMs);
    connect(&m_check, &QTimer::timeout, this, &MplLanguage::checkNow);
    connect(&m_editor, &QsciScintilla::textChanged, &m_check, qOverload<>(&QTimer::start));
    m_check.start();
}

void MplLanguage::detach() {
    m_check.stop();
    m_editor.clearAnnotations();
    m_editor.setFolding(QsciScintilla::NoFoldStyle, kFoldMargin);
    LanguageSupport::detach();
}

int MplLanguage::checkNow() {
    m_check.stop();
    m_editor.clearAnnotations();
    const QList<MplDiagnostic> found = checkMplProgram(m_editor.text().toLatin1());
    const QsciStyle style = annotationStyle(m_editor.font());
    for (const MplDiagnostic& d : found) {
        const QString others = m_editor.annotation(d.line);
        const QString text = tr("col %1: %2").arg(d.column + 1).arg(d.message);
        m_editor.annotate(d.line, others.isEmpty() ? text : others + QLatin1Char('\n') + text, style);
    }
    return int(found.size());
}

} // namespace editor
