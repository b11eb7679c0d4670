// WizardChanges: pending edits of the setup wizard.
#include "wizard_changes.h"

#include "serialport/bds5_variable_file.h"

namespace app {

void WizardChanges::setOriginal(const QString& name, const QString& value) {
    Change& c = m_changes[name];
    if (c.original == value) return;
    c.original = value;
    if (c.edited == value) c.edited.clear();
    emit changed();
}

void WizardChanges::setEdited(const QString& name, const QString& value) {
    Change& c = m_changes[name];
    const QString edited = value == c.original ? QString() : value;
    if (c.edited == edited) return;
    c.edited = edited;
    emit changed();
}

void WizardChanges::markApplied(const QString& name) {
    auto it = m_changes.find(name);
    if (it == m_changes.end() || it->edited.isEmpty()) return;
    it->original = it->edited;
    it->edited.clear();
    emit changed();
}

void WizardChanges::discard() {
    for (Change& c : m_changes) c.edited.clear();
    emit changed();
}

QStringList WizardChanges::changedNames() const {
    QStringList names;
    for (auto it = m_changes.cbegin(); it != m_changes.cend(); ++it)
        if (!it->edited.isEmpty()) names << it.key();
    return names;
}

QString WizardChanges::valueOf(const QString& name) const {
    const Change c = m_changes.value(name);
    return c.edited.isEmpty() ? c.original : c.edited;
}

QString WizardChanges::toVar() const {
    QString text;
    for (const QString& name : changedNames())
        text += name + QLatin1Char(' ') + m_changes.value(name).edited + QLatin1Char('\n');
    const serialport::Bds5VariableFile file = serialport::Bds5VariableFile::parse(text);
    return file.toText({QStringLiteral("Variables changed in the ServoDesk setup wizard")});
}

} // namespace app
