// WizardChanges: what the setup wizard's pages have changed and not yet sent — per variable the value read
// from the drive and the value the user chose. Nothing here talks to the drive. Pure; no widgets.
#pragma once

#include <QMap>
#include <QObject>
#include <QString>
#include <QStringList>

namespace app {

class WizardChanges final : public QObject {
    Q_OBJECT
public:
    using QObject::QObject;

    struct Change {
        QString original; // as read from the drive ("" if never read)
        QString edited;   // as the user set it ("" = unchanged)
    };

    void setOriginal(const QString& name, const QString& value);
    // Records the user's value; the same as the original (or "") removes the change.
    void setEdited(const QString& name, const QString& value);
    // The drive now holds the edited value: it becomes the original.
    void markApplied(const QString& name);
    void discard();

    QStringList changedNames() const;
    Change change(const QString& name) const { return m_changes.value(name); }
    QString valueOf(const QString& name) const; // edited if changed, else original
    // "NAME value" lines (Motion Link .VAR) of the changes, after a comment header.
    QString toVar() const;

signals:
    void changed();

private:
    QMap<QString, Change> m_changes; // sorted by name: the summary and .VAR list them in this order
};

} // namespace app
