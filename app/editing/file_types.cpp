// File types by extension.
#include "file_types.h"

#include "resources/resources.h"

#include <QCoreApplication>
#include <QFileInfo>

namespace app {

namespace {
QString tr(const char* text) {
    return QCoreApplication::translate("app::FileTypes", text);
}

QString filterFor(FileType type) {
    switch (type) {
    case FileType::Program: return tr("BDS5 programs (*.bds *.BDS)");
    case FileType::Variables: return tr("Variable sets (*.var *.VAR)");
    case FileType::Capture: return tr("Captured communications (*.cap *.CAP)");
    case FileType::Sc750Program: return tr("ServoBASIC programs (*.bas *.BAS)");
    case FileType::MplProgram: return tr("PMC-960 MPL programs (*.mpl *.MPL)");
    case FileType::Other: break;
    }
    return tr("All files (*)");
}
} // namespace

FileType fileTypeOf(const QString& path) {
    const QString suffix = QFileInfo(path).suffix().toLower();
    if (suffix == QLatin1String("bds")) return FileType::Program;
    if (suffix == QLatin1String("var")) return FileType::Variables;
    if (suffix == QLatin1String("cap")) return FileType::Capture;
    if (suffix == QLatin1String("bas")) return FileType::Sc750Program;
    if (suffix == QLatin1String("mpl")) return FileType::MplProgram;
    return FileType::Other;
}

QString fileTypeIcon(FileType type) {
    switch (type) {
    case FileType::Program:
    case FileType::MplProgram: return resources::kProgramFileIcon;
    case FileType::Sc750Program: return resources::kProgramFileIcon;
    case FileType::Variables: return resources::kVariableFileIcon;
    case FileType::Capture: return resources::kCaptureFileIcon;
    case FileType::Other: break;
    }
    return resources::kOtherFileIcon;
}

QString fileTypeName(FileType type) {
    switch (type) {
    case FileType::Program: return tr("BDS5 program");
    case FileType::Variables: return tr("Variable set");
    case FileType::Capture: return tr("Captured communications");
    case FileType::Sc750Program: return tr("ServoBASIC program");
    case FileType::MplProgram: return tr("PMC-960 MPL program");
    case FileType::Other: break;
    }
    return tr("Text file");
}

QString defaultSuffix(FileType type) {
    switch (type) {
    case FileType::Program: return QStringLiteral("bds");
    case FileType::Variables: return QStringLiteral("var");
    case FileType::Capture: return QStringLiteral("cap");
    case FileType::Sc750Program: return QStringLiteral("bas");
    case FileType::MplProgram: return QStringLiteral("mpl");
    case FileType::Other: break;
    }
    return QString();
}

QString untitledName(FileType type) {
    const QString suffix = defaultSuffix(type);
    return suffix.isEmpty() ? QStringLiteral("untitled.txt") : QStringLiteral("untitled.") + suffix;
}

QString openFilter() {
    return tr("Motion Link files (*.bds *.var *.cap *.BDS *.VAR *.CAP)") + QStringLiteral(";;") +
           filterFor(FileType::Program) + QStringLiteral(";;") + filterFor(FileType::Variables) + QStringLiteral(";;") +
           filterFor(FileType::Capture) + QStringLiteral(";;") + filterFor(FileType::Sc750Program) + QStringLiteral(";;") + filterFor(FileType::MplProgram) + QStringLiteral(";;") +
           filterFor(FileType::Other);
}

QString saveFilter(FileType type) {
    QStringList filters{filterFor(type)};
    for (FileType other : {FileType::Program, FileType::Variables, FileType::Capture, FileType::Sc750Program, FileType::MplProgram, FileType::Other})
        if (other != type) filters << filterFor(other);
    return filters.join(QStringLiteral(";;"));
}

} // namespace app
