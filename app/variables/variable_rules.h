// VariableRules: what the variable browser asks of a drive family — how values are read and written on its
// line, how an edit is checked before it goes (as the drive checks it, naming the drive's error), how the
// catalog is grouped and its limits read. The browser itself (VariableModel, VariableSync, VariableBrowser)
// is family-neutral over the common catalog (drive_core/catalog/drive_catalog.h) and the DriveSession.
// One implementation a family, in app/families/<f>/; make() picks. Pure: no I/O.
#pragma once

#include "drive_core/catalog/drive_catalog.h"
#include "serialport/drive_session.h"

#include <QCoreApplication>
#include <QList>
#include <QPair>
#include <QString>
#include <QStringList>

#include <functional>
#include <memory>
#include <optional>

namespace app {

class VariableRules {
    Q_DECLARE_TR_FUNCTIONS(VariableRules)

public:
    // What the rules know of the drive: a value read last, nullopt while it is not known.
    struct Context {
        std::function<std::optional<double>(const QString& name)> valueOf;
    };
    struct Verdict {
        bool ok = false;
        QStringList lines; // what goes to the drive, in order, when ok ("VMAX 3000"; "SW1", "TGP20", "SW0")
        QString message;   // why not, in the drive's terms ("ERR 83 BAD OR OUT OF RANGE: ...")
    };

    virtual ~VariableRules() = default;
    static std::unique_ptr<VariableRules> make(drive_core::DriveFamily family);

    virtual drive_core::DriveFamily family() const = 0;
    // The groups shown, in order; a parameter whose group is not listed is left out. Empty: every group, in
    // the catalog's order.
    virtual QStringList groupOrder() const { return {}; }
    virtual QString groupOf(const drive_core::catalog::Parameter& p) const;
    // The Limits column; the generic one prints the catalog's range.
    virtual QString limitsText(const QString& name, const drive_core::catalog::Parameter& p, const Context& c) const;
    // Whether the user may change it here; the generic one: unless the catalog says read only or factory.
    virtual bool editable(const QString& name, const drive_core::catalog::Parameter& p) const;
    // A value as shown (a BDS5 switch's 1 as ON); the generic one shows it as the drive printed it.
    virtual QString displayValue(const drive_core::catalog::Parameter& p, const QString& printed) const;
    virtual Verdict check(const QString& name, const QString& text, const Context& c) const = 0;
    // A name whose value changes the limits of others (the BDS5's NUM/DEN).
    virtual bool scalesLimits(const QString&) const { return false; }
    // Names read with the rows in view although no view shows them (what limits and checks depend on).
    virtual QStringList alsoRead(const Context&) const { return {}; }

    // Reading: up to batch() names in one line ("" when the drive has no way to show it); values() takes
    // them from its answer (one per name, or empty when the answer does not fit); unreadable() names those
    // the drive refused to print.
    virtual int batch() const { return 1; }
    // The least time between two polls, however fast the drive answers.
    virtual int pollIntervalMs() const { return 40; }
    virtual QString readLine(const QStringList& names) const = 0;
    virtual QStringList values(const QStringList& names, const serialport::LineAnswer& answer) const = 0;
    virtual QStringList unreadable(const QStringList& names, const serialport::LineAnswer& answer) const;
    // The status line before anything happened.
    virtual QString hint() const = 0;
    // The Value column's title; and a second value the drive keeps beside it (the PMC-960's in-use "!"
    // beside its stored "?"): its column's title ("" for none) and the line that reads it ("" for none).
    virtual QString valueTitle() const { return tr("Value"); }
    virtual QString secondTitle() const { return {}; }
    virtual QString secondReadLine(const QString&) const { return {}; }
    // Read the rows in view over and over (false: when asked — Refresh, a connection, after a write).
    virtual bool liveByDefault() const { return true; }

    // Copy as: the family's own variable file, which its Send (and `servodesk-cli vars send`) takes back.
    struct FileText {
        QString text;
        int count = 0; // the values it holds; the others cannot go in such a file (a read-only variable)
    };
    // What the file is called in "Copy as …": ".VAR", ".PRM", "MPL lines".
    virtual QString fileKind() const = 0;
    // The file's text for these names and their values as the browser shows them.
    virtual FileText fileText(const QList<QPair<QString, QString>>& values) const = 0;

    // The generic check of the common schema: read only, a number (integer where it must be), within range.
    static std::optional<QString> schemaProblem(const QString& name, const drive_core::catalog::Parameter& p,
                                                const QString& text);
    static QString text(std::string_view view);
};

} // namespace app
