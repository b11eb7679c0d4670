// ProgramPrinter: page header and PDF output.
#include "program_printer.h"

#include <QCoreApplication>
#include <QFileInfo>
#include <QPainter>

namespace editor {

ProgramPrinter::ProgramPrinter(const QString& title, QPrinter::PrinterMode mode) : QsciPrinter(mode), m_title(title) {
    setDocName(title);
    setWrapMode(QsciScintilla::WrapWord); // long lines wrap instead of running off the page
    setMagnification(-1);                 // a little smaller than on screen: more of the program per page
}

bool ProgramPrinter::printEditor(QsciScintillaBase& editor) {
    return printRange(&editor) > 0;
}

void ProgramPrinter::formatPage(QPainter& painter, bool drawing, QRect& area, int pageNumber) {
    QFont font = painter.font();
    font.setPointSize(9);
    const QFontMetrics metrics(font, painter.device());
    const int headerHeight = metrics.height() * 2;
    if (drawing) {
        painter.save();
        painter.setFont(font);
        painter.setPen(Qt::black);
        const QRect header(area.left(), area.top(), area.width(), metrics.height());
        painter.drawText(header, Qt::AlignLeft | Qt::AlignVCenter, m_title);
        painter.drawText(header, Qt::AlignRight | Qt::AlignVCenter,
                         QCoreApplication::translate("editor", "Page %1").arg(pageNumber));
        const int y = area.top() + metrics.height() + metrics.height() / 4;
        painter.drawLine(area.left(), y, area.right(), y);
        painter.restore();
    }
    area.setTop(area.top() + headerHeight);
}

FileResult printToPdf(QsciScintillaBase& editor, const QString& title, const QString& path) {
    ProgramPrinter printer(title);
    printer.setOutputFormat(QPrinter::PdfFormat);
    printer.setOutputFileName(path);
    if (!printer.printEditor(editor))
        return {false,
                QCoreApplication::translate("editor", "Cannot print %1 to %2").arg(title, QFileInfo(path).fileName())};
    return {};
}

} // namespace editor
