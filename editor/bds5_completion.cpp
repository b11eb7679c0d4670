// BDS5 completion rows from the catalog: commands (not the resident editor's own) and variables (not the
// factory internals), each with a short note.
#include "bds5_completion.h"

#include "drive_core/catalog/bds5_catalog.h"

#include <QRegularExpression>
#include <QSet>
#include <QStringList>

#include <algorithm>

namespace editor {

namespace cat = drive_core::catalog::bds5;

namespace {

QString str(std::string_view s) {
    return QString::fromUtf8(s.data(), qsizetype(s.size()));
}

// The first phrase of a description: "User variables X1-X250, initially 0." -> "User variables X1-X250".
QString firstPhrase(std::string_view description) {
    QString text = str(description);
    const qsizetype cut = text.indexOf(QRegularExpression(QStringLiteral("[.,:;(]")));
    if (cut > 0) text.truncate(cut);
    if (text.size() > 48) text = text.left(45) + QStringLiteral("...");
    return text;
}

QString variableNote(const cat::VariableInfo& v) {
    if (v.name == "ON" || v.name == "Y") return QStringLiteral("constant 1");
    if (v.name == "OFF" || v.name == "N") return QStringLiteral("constant 0");
    QStringList parts;
    if (!v.units.empty()) parts << str(v.units);
    if (v.isSwitch || v.limits == cat::LimitClass::Switch)
        parts << QStringLiteral("switch");
    else if (v.limits != cat::LimitClass::None && v.limits != cat::LimitClass::Long)
        parts << QStringLiteral("%1..%2").arg(cat::minimumOf(v)).arg(cat::maximumOf(v));
    switch (v.write) {
    case cat::WriteCondition::Always: break;
    case cat::WriteCondition::Disabled: parts << QStringLiteral("when disabled"); break;
    case cat::WriteCondition::NoMotion: parts << QStringLiteral("no motion"); break;
    case cat::WriteCondition::Never: parts << QStringLiteral("read-only"); break;
    case cat::WriteCondition::Factory: parts << QStringLiteral("factory"); break;
    }
    if (parts.isEmpty() || (parts.size() == 1 && v.firstIndex > 0)) parts.prepend(firstPhrase(v.description));
    return parts.join(QStringLiteral(", "));
}

QString commandNote(const cat::CommandInfo& c) {
    // The syntax without the command word: "MA <pos> [vel]" -> "<pos> [vel]".
    QString syntax = str(c.syntax);
    if (syntax.startsWith(str(c.name) + QLatin1Char(' ')))
        syntax = syntax.mid(c.name.size() + 1);
    else if (syntax == str(c.name))
        syntax.clear();
    const QString longName = str(c.longName);
    return syntax.isEmpty() ? longName : longName + QLatin1Char(' ') + syntax;
}

} // namespace

std::vector<Bds5Completion> bds5Completions(const QString& prefix) {
    const QString upper = prefix.toUpper();
    std::vector<Bds5Completion> out;
    QSet<QString> seen;
    auto add = [&](const QString& insert, const QString& shown, const QString& note) {
        if (!shown.startsWith(upper) || seen.contains(shown)) return;
        seen.insert(shown);
        out.push_back({insert, shown + kBds5CompletionSeparator + note});
    };
    for (const cat::CommandInfo& c : cat::commands()) {
        if ((c.modes & (cat::kProgram | cat::kInteractive | cat::kMonitor)) == 0) continue;
        const QString name = str(c.name);
        if (name.isEmpty() || !name.front().isLetter()) continue; // ; $ = ? <BDS >BDS are typed, not completed
        add(name, name, commandNote(c));
    }
    for (const cat::VariableInfo& v : cat::variables()) {
        if (v.group == cat::VariableGroup::Internal) continue;
        const QString name = str(v.name);
        const QString shown =
            v.firstIndex > 0 ? QStringLiteral("%1%2..%1%3").arg(name).arg(v.firstIndex).arg(v.lastIndex) : name;
        add(name, shown, variableNote(v));
        if (v.extendedLastIndex > v.lastIndex) // v3: X251..X750 exist only while EXTDX is on
            add(name, QStringLiteral("%1%2..%1%3").arg(name).arg(v.lastIndex + 1).arg(v.extendedLastIndex),
                QStringLiteral("with %1 on (v3)").arg(str(v.extendedBy)));
    }
    std::sort(out.begin(), out.end(),
              [](const Bds5Completion& a, const Bds5Completion& b) { return a.display < b.display; });
    return out;
}

} // namespace editor
