// The resources compiled into ServoDesk, and the call that registers them. A static library's resources
// are only linked in when something references them: call resources::initialize() once from main().
#pragma once

#include <QString>

namespace resources {

// Registers the ":/" files of this library with Qt. Idempotent; call before the first QFile(":/...").
void initialize();

// The sample program the IDE opens with (a BDS5 .BDS file).
inline const QString kSampleProgram = QStringLiteral(":/samples/hello.bds");
// The application icon (SVG; shown where Qt's SVG image plugin is installed).
inline const QString kAppIcon = QStringLiteral(":/icons/servodesk.svg");

} // namespace resources
