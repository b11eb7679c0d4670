#include "cli_files.h"

#include <QFile>
#include <QSaveFile>

namespace app::cli {

std::optional<QString> readTextFile(const QString& path, QString& error) {
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) {
        error = QStringLiteral("cannot read %1: %2").arg(path, f.errorString());
        return std::nullopt;
    }
    return QString::fromLatin1(f.readAll());
}

bool writeBinaryFile(const QString& path, const QByteArray& bytes, QString& error) {
    QSaveFile f(path);
    if (!f.open(QIODevice::WriteOnly) || f.write(bytes) < 0 || !f.commit()) {
        error = QStringLiteral("cannot write %1: %2").arg(path, f.errorString());
        return false;
    }
    return true;
}

bool writeTextFile(const QString& path, const QString& text, QString& error) {
    return writeBinaryFile(path, text.toLatin1(), error);
}

std::vector<std::string> programLines(const QString& text) {
    std::vector<std::string> lines;
    for (QString line : text.split(QLatin1Char('\n'))) {
        if (line.endsWith(QLatin1Char('\r'))) line.chop(1);
        lines.push_back(line.toStdString());
    }
    if (!lines.empty() && lines.back().empty()) lines.pop_back();
    return lines;
}

} // namespace app::cli
