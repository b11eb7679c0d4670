// Completion of BDS5 commands and variables from the drive_core catalog, with what a user needs to pick
// one: a command's long name and syntax, a variable's units, range and write condition
// (`VMAX — VEL, factory`, `X1..X250 — user variables`). Pure; any thread.
#pragma once

#include <QString>

#include <vector>

namespace editor {

struct Bds5Completion {
    QString insert;  // what replaces the typed prefix: "VMAX", "MA", "X" for the X1..X250 family
    QString display; // the list row: "VMAX — VEL, factory"
};

// Every command usable in a program and every documented variable whose name starts with prefix (any case),
// sorted by display text. An empty prefix lists everything.
std::vector<Bds5Completion> bds5Completions(const QString& prefix);

// The row separator between a name and its note in Bds5Completion::display.
inline const QString kBds5CompletionSeparator = QStringLiteral(" \u2014 ");

} // namespace editor
