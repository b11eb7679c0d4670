// The files Motion Link kept (manual L1195-1203): .BDS programs, .VAR variable sets, .CAP captured
// communications — their icons, file-dialog filters and default extensions. Any thread.
#pragma once

#include <QString>

namespace app {

// MplProgram: a PMC-960 MPL program (.mpl, issue 9).
// Sc750Program: a ServoBASIC Plus program for the SC750 (.bas, issue 8).
enum class FileType { Program, Variables, Capture, Sc750Program, MplProgram, Other };

// By extension, case-insensitively; anything unknown is Other (still opened as text).
FileType fileTypeOf(const QString& path);
// The tab icon's resource path.
QString fileTypeIcon(FileType type);
// "BDS5 program", "Variable set", ...
QString fileTypeName(FileType type);
// The extension Save As adds when the user types none ("bds").
// chosen: Motion Link "automatically determines the proper file extension" (L1203); we add it only
// when the name has none, so a user's own extension is kept.
QString defaultSuffix(FileType type);
// "untitled.bds", "untitled.var", ...
QString untitledName(FileType type);
// The Open dialog's filters: all Motion Link files first, then each type, then all files.
QString openFilter();
// The Save dialog's filters with type's own first.
QString saveFilter(FileType type);

} // namespace app
