// servodesk-cli's file helpers: drive files are 7-bit ASCII text (Latin-1 keeps any byte), written
// atomically so a failed write never leaves half a file.
#pragma once

#include <QByteArray>
#include <QString>

#include <optional>
#include <string>
#include <vector>

namespace app::cli {

std::optional<QString> readTextFile(const QString& path, QString& error);
bool writeTextFile(const QString& path, const QString& text, QString& error);
bool writeBinaryFile(const QString& path, const QByteArray& bytes, QString& error);
// The text's lines without their CR LF or LF, and without the empty line after a final line end.
std::vector<std::string> programLines(const QString& text);

} // namespace app::cli
