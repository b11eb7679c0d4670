// ProgramPrinter: PRINT (^P, manual L1140) — a QsciPrinter that prints the editor's text in its colours
// with the file's name and the page number at the top of each page. printToPdf() is the same output
// written to a PDF file (File > Print to PDF, and tests). GUI thread only.
#pragma once

#include "program_editor.h"

#include <Qsci/qsciprinter.h>

#include <QString>

namespace editor {

class ProgramPrinter final : public QsciPrinter {
public:
    // title: what each page's header names ("hello.bds").
    explicit ProgramPrinter(const QString& title, QPrinter::PrinterMode mode = QPrinter::HighResolution);

    // Prints all of editor; returns false when nothing could be printed.
    bool printEditor(QsciScintillaBase& editor);

    void formatPage(QPainter& painter, bool drawing, QRect& area, int pageNumber) override;

private:
    QString m_title;
};

// Prints editor to a PDF file at path.
FileResult printToPdf(QsciScintillaBase& editor, const QString& title, const QString& path);

} // namespace editor
