// Bds5Diagnostics: debounce, check, and the three ways a diagnostic shows (marker, squiggle, annotation).
// A check whose result equals the one on screen changes nothing, so typing inside a comment never flickers.
#include "bds5_diagnostics.h"

#include <Qsci/qsciscintilla.h>

#include <QImage>
#include <QPainter>
#include <QPainterPath>

#include <algorithm>

namespace editor {

namespace dbds5 = drive_core::bds5;

namespace {

constexpr int kMarkerSize = 14; // pixels; the margin is a little wider

bool sameDiagnostics(const std::vector<dbds5::Diagnostic>& a, const std::vector<dbds5::Diagnostic>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (a[i].line != b[i].line || a[i].column != b[i].column || a[i].length != b[i].length ||
            a[i].code != b[i].code || a[i].entry != b[i].entry || a[i].message != b[i].message)
            return false;
    return true;
}

// A filled circle with a white cross (error) or an amber triangle with a "!" (advice).
QImage markerImage(bool error) {
    QImage image(kMarkerSize, kMarkerSize, QImage::Format_ARGB32_Premultiplied);
    image.fill(Qt::transparent);
    QPainter p(&image);
    p.setRenderHint(QPainter::Antialiasing);
    const QRectF box(1, 1, kMarkerSize - 2, kMarkerSize - 2);
    if (error) {
        p.setPen(Qt::NoPen);
        p.setBrush(QColor(0xd1, 0x24, 0x2f));
        p.drawEllipse(box);
        p.setPen(QPen(Qt::white, 1.8, Qt::SolidLine, Qt::RoundCap));
        const qreal m = 4.2;
        p.drawLine(QPointF(box.left() + m, box.top() + m), QPointF(box.right() - m, box.bottom() - m));
        p.drawLine(QPointF(box.right() - m, box.top() + m), QPointF(box.left() + m, box.bottom() - m));
    } else {
        QPainterPath triangle;
        triangle.moveTo(box.center().x(), box.top());
        triangle.lineTo(box.right(), box.bottom());
        triangle.lineTo(box.left(), box.bottom());
        triangle.closeSubpath();
        p.setPen(Qt::NoPen);
        p.setBrush(QColor(0xd4, 0x8a, 0x00));
        p.drawPath(triangle);
        p.setPen(QPen(Qt::white, 1.6, Qt::SolidLine, Qt::RoundCap));
        p.drawLine(QPointF(box.center().x(), box.top() + 4), QPointF(box.center().x(), box.bottom() - 4.5));
        p.drawPoint(QPointF(box.center().x(), box.bottom() - 2));
    }
    return image;
}

} // namespace

Bds5Diagnostics::Bds5Diagnostics(QsciScintilla& editor) : QObject(&editor), m_editor(editor) {
    m_timer.setSingleShot(true);
    m_timer.setInterval(kDebounceMs);
    connect(&m_timer, &QTimer::timeout, this, &Bds5Diagnostics::checkNow);
    connect(&m_editor, &QsciScintilla::textChanged, &m_timer, qOverload<>(&QTimer::start));
    defineMarkers();
    setDarkTheme(false);
    m_timer.start();
}

void Bds5Diagnostics::clear() {
    m_timer.stop();
    show({});
}

void Bds5Diagnostics::defineMarkers() {
    m_editor.markerDefine(markerImage(true), kErrorMarker);
    m_editor.markerDefine(markerImage(false), kAdviceMarker);
    m_editor.setMarginType(kMarkerMargin, QsciScintilla::SymbolMargin);
    m_editor.setMarginWidth(kMarkerMargin, kMarkerSize + 4);
    m_editor.setMarginMarkerMask(kMarkerMargin,
                                 m_editor.marginMarkerMask(kMarkerMargin) | (1 << kErrorMarker) | (1 << kAdviceMarker));
    m_editor.setMarginSensitivity(kMarkerMargin, false);
    m_editor.indicatorDefine(QsciScintilla::SquiggleLowIndicator, kErrorIndicator);
    m_editor.indicatorDefine(QsciScintilla::SquiggleLowIndicator, kAdviceIndicator);
    m_editor.setIndicatorForegroundColor(QColor(0xd1, 0x24, 0x2f), kErrorIndicator);
    m_editor.setIndicatorForegroundColor(QColor(0xd4, 0x8a, 0x00), kAdviceIndicator);
    m_editor.setAnnotationDisplay(QsciScintilla::AnnotationIndented);
}

void Bds5Diagnostics::setDarkTheme(bool dark) {
    QFont font = m_editor.font();
    font.setPointSizeF(font.pointSizeF() * 0.9);
    m_errorStyle =
        QsciStyle(m_errorStyle.style(), tr("Diagnostic"), dark ? QColor(0xff, 0xa1, 0x98) : QColor(0x9f, 0x1c, 0x24),
                  dark ? QColor(0x3c, 0x1f, 0x1f) : QColor(0xff, 0xf0, 0xef), font, true);
    m_adviceStyle =
        QsciStyle(m_adviceStyle.style(), tr("Advice"), dark ? QColor(0xe6, 0xc0, 0x6a) : QColor(0x7a, 0x4d, 0x00),
                  dark ? QColor(0x3a, 0x30, 0x14) : QColor(0xff, 0xf8, 0xe1), font, true);
    if (m_checkedOnce) { // repaint the annotations on screen in the new colours
        auto shown = std::move(m_diagnostics);
        m_diagnostics.clear();
        show(std::move(shown));
    }
}

QString Bds5Diagnostics::annotationText(const dbds5::Diagnostic& d) {
    if (d.code == 0) return QString::fromStdString(d.message);
    QString text = QStringLiteral("ERR %1").arg(d.code);
    if (!d.entry.empty()) text += QStringLiteral(" '%1'").arg(QString::fromStdString(d.entry));
    return text + QStringLiteral("  ") + QString::fromStdString(d.message);
}

std::vector<std::string> Bds5Diagnostics::programLines(const QString& text) {
    std::vector<std::string> lines;
    const QStringList split = text.split(QLatin1Char('\n'));
    lines.reserve(std::size_t(split.size()));
    for (const QString& line : split) {
        QByteArray bytes = line.toUtf8();
        if (bytes.endsWith('\r')) bytes.chop(1);
        lines.emplace_back(bytes.constData(), std::size_t(bytes.size()));
    }
    return lines;
}

void Bds5Diagnostics::checkNow() {
    m_timer.stop();
    show(dbds5::checkProgram(programLines(m_editor.text())));
}

void Bds5Diagnostics::show(std::vector<dbds5::Diagnostic> diagnostics) {
    // RUN's program-wide checks come last from checkProgram; the annotations want line order.
    std::stable_sort(diagnostics.begin(), diagnostics.end(),
                     [](const dbds5::Diagnostic& a, const dbds5::Diagnostic& b) { return a.line < b.line; });
    if (m_checkedOnce && sameDiagnostics(diagnostics, m_diagnostics)) return;
    m_checkedOnce = true;
    m_diagnostics = std::move(diagnostics);
    removeShownAnnotations();
    m_editor.markerDeleteAll(kErrorMarker);
    m_editor.markerDeleteAll(kAdviceMarker);
    const long length = m_editor.SendScintilla(QsciScintilla::SCI_GETLENGTH);
    for (const int indicator : {kErrorIndicator, kAdviceIndicator}) {
        m_editor.SendScintilla(QsciScintilla::SCI_SETINDICATORCURRENT, indicator);
        m_editor.SendScintilla(QsciScintilla::SCI_INDICATORCLEARRANGE, 0, length);
    }

    // Several diagnostics on one line share one annotation, one per row.
    m_errors = 0;
    const int lineCount = m_editor.lines();
    int annotatedLine = -1;
    QString annotation;
    bool annotationIsError = false;
    // The styles go to the editor once per show (a lexer change clears them), not once per annotation.
    m_errorStyle.apply(&m_editor);
    m_adviceStyle.apply(&m_editor);
    auto flush = [&] {
        if (annotatedLine < 0) return;
        // Rows others put there (a drive error after a download) stay, below ours.
        const QString others = m_editor.annotation(annotatedLine);
        m_editor.annotate(annotatedLine, others.isEmpty() ? annotation : annotation + QLatin1Char('\n') + others,
                          (annotationIsError ? m_errorStyle : m_adviceStyle).style());
        const int handle = m_editor.markerAdd(annotatedLine, annotationIsError ? kErrorMarker : kAdviceMarker);
        m_shown.push_back({handle, annotation});
    };
    for (const dbds5::Diagnostic& d : m_diagnostics) {
        const int line = d.line - 1;
        if (line < 0 || line >= lineCount) continue;
        const bool error = d.code != 0;
        m_errors += error ? 1 : 0;

        const long lineStart = m_editor.SendScintilla(QsciScintilla::SCI_POSITIONFROMLINE, line);
        const long lineEnd = m_editor.SendScintilla(QsciScintilla::SCI_GETLINEENDPOSITION, line);
        long from = lineStart + d.column;
        long to = d.length > 0 ? from + d.length : lineEnd;
        if (d.length == 0 && d.column == 0) { // the whole line: from its first non-blank
            from = m_editor.SendScintilla(QsciScintilla::SCI_GETLINEINDENTPOSITION, line);
        }
        from = std::min(from, lineEnd);
        to = std::min(to, lineEnd);
        if (to > from) {
            m_editor.SendScintilla(QsciScintilla::SCI_SETINDICATORCURRENT, error ? kErrorIndicator : kAdviceIndicator);
            m_editor.SendScintilla(QsciScintilla::SCI_INDICATORFILLRANGE, from, to - from);
        }

        if (line != annotatedLine) {
            flush();
            annotatedLine = line;
            annotation.clear();
            annotationIsError = false;
        } else {
            annotation += QLatin1Char('\n');
        }
        annotation += annotationText(d);
        annotationIsError = annotationIsError || error;
    }
    flush();
    emit changed(m_errors, adviceCount());
}

void Bds5Diagnostics::removeShownAnnotations() {
    // Each annotated line carries one of our markers, which moved with the line through any edits.
    for (const auto& [handle, rows] : m_shown) {
        const int line = m_editor.markerLine(handle);
        if (line < 0) continue;
        QStringList kept = m_editor.annotation(line).split(QLatin1Char('\n'));
        for (const QString& row : rows.split(QLatin1Char('\n'))) kept.removeOne(row);
        kept.removeAll(QString());
        if (kept.isEmpty()) {
            m_editor.clearAnnotations(line);
        } else {
            const int style = int(m_editor.SendScintilla(QsciScintilla::SCI_ANNOTATIONGETSTYLE, line));
            m_editor.annotate(line, kept.join(QLatin1Char('\n')), style);
        }
    }
    m_shown.clear();
}

int Bds5Diagnostics::nextLine(int afterLine) const {
    int best = -1;
    for (const dbds5::Diagnostic& d : m_diagnostics)
        if (d.line - 1 > afterLine && (best < 0 || d.line - 1 < best)) best = d.line - 1;
    return best;
}

} // namespace editor
