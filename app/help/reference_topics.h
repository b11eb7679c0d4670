// ReferenceTopics: the BDS5 reference as help topics — every command, variable and error of the
// drive_core catalog, and the introduction page — with the HTML the help browser shows for each.
// Pure functions; the catalog is the only source.
#pragma once

#include <QList>
#include <QString>

#include <optional>

namespace app {

struct ReferenceTopic {
    enum class Kind { Page, Command, Variable, Error };
    Kind kind = Kind::Page;
    QString key;     // how showTopic() names it: "MA", "VMAX", "X" (the family of X1-X250), "ERR 25", "intro"
    QString title;   // the list's text: "MA — MOVE ABSOLUTE", "ERR 25 PE OVERFLOW"
    QString summary; // searched with the key and title: description or meaning
    QString html;    // the page, when made with the topic (other families); else ReferenceTopics::html
};

class ReferenceTopics {
public:
    static const QList<ReferenceTopic>& all();
    // "VMAX", "vmax", "X12" (-> X), "ERR 25", "ERR25", "25" (-> ERR 25), "MA", "intro". Commands win over
    // variables of the same name; nullopt when the catalog has no such entry.
    static std::optional<ReferenceTopic> find(const QString& name);
    // Whether a topic matches what the user typed in the search box (key prefix, or a word of its text).
    static bool matches(const ReferenceTopic& topic, const QString& search);
    static QString html(const ReferenceTopic& topic);
    static QString introHtml();
};

} // namespace app
