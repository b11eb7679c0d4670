// FamilyTopics: the help browser's topics for each drive family — the BDS5's ReferenceTopics, and the
// SC750's (statements, functions, predefined variables and parameters, fault codes) and the PMC-960's
// (commands, parameters, #xx error codes) from their catalogs, with the pages the editors' F1 popups show.
// Pure functions; the catalogs are the only source.
#pragma once

#include "reference_topics.h"

#include "drive_core/drive.h"

#include <QStringList>

namespace app {

class FamilyTopics {
public:
    static const QList<ReferenceTopic>& of(drive_core::DriveFamily family);
    // The list's four groups, in ReferenceTopic::Kind order: the introduction, commands, variables, errors.
    static QStringList groupNames(drive_core::DriveFamily family);
    // By key, case-insensitive: "GO.VEL", "FAULT 4", "intro" (SC750); "TGP", "#B6" (PMC-960); the BDS5's
    // ReferenceTopics::find otherwise.
    static std::optional<ReferenceTopic> find(drive_core::DriveFamily family, const QString& name);
    static QString html(const ReferenceTopic& topic);

private:
    static const QList<ReferenceTopic>& sc750();
    static const QList<ReferenceTopic>& pmc960();
};

} // namespace app
