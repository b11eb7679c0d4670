// MachineProject: the machine.sdm file, read and written.
#include "machine_project.h"

#include "serialport/axis_link.h"
#include "variable_transfer.h"

#include "drive_core/drive_factory.h"

#include <QDir>
#include <QFile>
#include <QRegularExpression>

namespace app::machine {

using drive_core::DriveFamily;

namespace {
QString familyWord(DriveFamily family) {
    const std::string_view name = drive_core::familyName(family);
    return QString::fromLatin1(name.data(), qsizetype(name.size()));
}
} // namespace

QString MachineProject::programSuffix(DriveFamily family) {
    switch (family) {
    case DriveFamily::Bds5: return QStringLiteral("bds");
    case DriveFamily::Sc750: return QStringLiteral("bas");
    case DriveFamily::Pmc960: return QStringLiteral("mpl");
    }
    return QStringLiteral("txt");
}

MachineAxis MachineProject::axisNamed(const QString& id, DriveFamily family) {
    const QString stem = QStringLiteral("axis-") + id;
    return {id, family, stem + QLatin1Char('.') + programSuffix(family),
            stem + QLatin1Char('.') + VariableTransfer::fileSuffix(family)};
}

std::optional<MachineProject> MachineProject::parse(const QString& text, QString& error) {
    MachineProject p;
    bool hasFamily = false;
    const QStringList lines = text.split(QLatin1Char('\n'));
    const auto bad = [&error](int line, const QString& why) {
        error = QStringLiteral("line %1: %2").arg(line).arg(why);
        return std::nullopt;
    };
    for (int i = 0; i < lines.size(); ++i) {
        const QString line = lines[i].trimmed();
        const int n = i + 1;
        if (line.isEmpty() || line.startsWith(QLatin1Char('#'))) continue;
        const QStringList words = line.split(QRegularExpression(QStringLiteral("\\s+")));
        const QString& key = words[0];
        if (key == QLatin1String("machine")) {
            p.name = line.mid(key.size()).trimmed();
        } else if (key == QLatin1String("port")) {
            if (words.size() < 2 || words.size() > 3) return bad(n, QStringLiteral("port needs a name and maybe a baud rate"));
            p.port = words[1];
            bool number = true;
            if (words.size() == 3) p.baud = words[2].toInt(&number);
            if (!number || p.baud <= 0) return bad(n, QStringLiteral("\"%1\" is not a baud rate").arg(words[2]));
        } else if (key == QLatin1String("backed-up")) {
            p.backedUp = words.value(1);
        } else if (key == QLatin1String("axis")) {
            if (words.size() != 5) return bad(n, QStringLiteral("an axis line is: axis ID FAMILY PROGRAM-FILE VARIABLE-FILE"));
            const auto family = drive_core::familyFromName(words[2].toLower().toStdString());
            if (!family) return bad(n, QStringLiteral("unknown family \"%1\" (bds5, sc750 or pmc960)").arg(words[2]));
            if (hasFamily && *family != p.family())
                return bad(n, QStringLiteral("one line carries one family: axis %1 is %2, the axes before it %3")
                                  .arg(words[1], words[2], familyWord(p.family())));
            const QString problem = serialport::axisIdProblem(*family, words[1]);
            if (!problem.isEmpty()) return bad(n, problem);
            if (p.axis(words[1])) return bad(n, QStringLiteral("axis %1 is named twice").arg(words[1]));
            p.axes.append({words[1], *family, words[3] == QLatin1String("-") ? QString() : words[3], words[4]});
            hasFamily = true;
        } else {
            return bad(n, QStringLiteral("\"%1\" is not a machine project word (machine, port, backed-up, axis)").arg(key));
        }
    }
    if (p.axes.isEmpty()) return bad(int(lines.size()), QStringLiteral("the project names no axis"));
    return p;
}

QString MachineProject::toText() const {
    QString t = QStringLiteral("# ServoDesk machine project: the axes on one line, each with its program and variable\n"
                               "# files beside this one. Lines: machine NAME, port PORT BAUD, backed-up WHEN,\n"
                               "# axis ID FAMILY PROGRAM-FILE VARIABLE-FILE (a program file \"-\" when none is kept).\n");
    if (!name.isEmpty()) t += QStringLiteral("machine %1\n").arg(name);
    if (!port.isEmpty()) t += QStringLiteral("port %1 %2\n").arg(port).arg(baud);
    if (!backedUp.isEmpty()) t += QStringLiteral("backed-up %1\n").arg(backedUp);
    for (const MachineAxis& a : axes)
        t += QStringLiteral("axis %1 %2 %3 %4\n")
                 .arg(a.id, familyWord(a.family),
                      a.programFile.isEmpty() ? QStringLiteral("-") : a.programFile, a.variablesFile);
    return t;
}

DriveFamily MachineProject::family() const {
    return axes.isEmpty() ? DriveFamily::Bds5 : axes.front().family;
}

const MachineAxis* MachineProject::axis(const QString& id) const {
    for (const MachineAxis& a : axes)
        if (a.id == id) return &a;
    return nullptr;
}

std::optional<MachineProject> readMachineProject(const QString& dir, QString& error) {
    const QString path = QDir(dir).filePath(MachineProject::fileName());
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) {
        error = QStringLiteral("%1: %2").arg(path, f.errorString());
        return std::nullopt;
    }
    QString why;
    auto p = MachineProject::parse(QString::fromUtf8(f.readAll()), why);
    if (!p) error = QStringLiteral("%1:%2").arg(path, why.mid(QStringLiteral("line ").size()));
    return p;
}

} // namespace app::machine
