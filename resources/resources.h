// The resources compiled into ServoDesk, and the call that registers them. A static library's resources
// are only linked in when something references them: call resources::initialize() once from main().
#pragma once

#include <QString>

namespace resources {

// Registers the ":/" files of this library with Qt. Idempotent; call before the first QFile(":/...").
void initialize();

// The sample program the IDE opens with (a BDS5 .BDS file), and those of the other families, opened instead
// when the IDE starts with that family (servodesk --drive sc750|pmc960): ServoBASIC Plus and MPL.
inline const QString kSampleProgram = QStringLiteral(":/samples/hello.bds");
inline const QString kSc750SampleProgram = QStringLiteral(":/samples/hello.bas");
inline const QString kPmc960SampleProgram = QStringLiteral(":/samples/hello.mpl");
// STANDARD.VAR: the BDS5 factory variable set (.VAR), generated from the drive catalog at build time.
inline const QString kStandardVariables = QStringLiteral(":/variables/STANDARD.VAR");
// The application icon (SVG; shown where Qt's SVG image plugin is installed).
inline const QString kAppIcon = QStringLiteral(":/icons/servodesk.svg");
// Tab icons per file type (16x16 SVG): program .BDS, variable set .VAR, capture .CAP, anything else.
inline const QString kProgramFileIcon = QStringLiteral(":/icons/file-bds.svg");
inline const QString kVariableFileIcon = QStringLiteral(":/icons/file-var.svg");
inline const QString kCaptureFileIcon = QStringLiteral(":/icons/file-cap.svg");
inline const QString kOtherFileIcon = QStringLiteral(":/icons/file-other.svg");
// The classic (Motion Link / WordStar) key table, as plain text for Help.
inline const QString kClassicKeymapHelp = QStringLiteral(":/help/keymap-classic.txt");

} // namespace resources
