// HelpBrowser: the BDS5 reference (Help > BDS5 Reference) as a dock, object name "helpBrowser": a search
// box, the list of topics (introduction, commands, variables, errors from the catalog) and the selected
// topic's page. showTopic() opens it at a name — the editor's F1 calls it with the word under the cursor.
// The first time it opens as a window of its own, big enough to read; the user may dock it anywhere.
#pragma once

#include "reference_topics.h"

#include "drive_core/drive.h"

#include <QDockWidget>

class QLabel;
class QLineEdit;
class QSplitter;
class QTextBrowser;
class QTreeWidget;
class QTreeWidgetItem;

namespace app {

class HelpBrowser final : public QDockWidget {
    Q_OBJECT
public:
    explicit HelpBrowser(QWidget* parent = nullptr);

    // Shows, raises and selects the topic: "VMAX", "X12", "ERR 25", "25", "MA", "intro" (case-insensitive).
    // Returns false, and shows the search for the name instead, when the catalog has no such entry.
    bool showTopic(const QString& name);
    // Filters the list as if typed in the search box.
    void setSearch(const QString& text);
    // The reference shown: the BDS5's (the default), the SC750's or the PMC-960's. The main window follows
    // the family chosen in Drive > Connect.
    void setFamily(drive_core::DriveFamily family);
    drive_core::DriveFamily family() const { return m_family; }

    QString currentKey() const { return m_currentKey; } // the shown topic's key, "" for none
    QString pageText() const;                           // the shown page as plain text
    int visibleTopicCount() const;                      // topics the search leaves in the list

private:
    void fill();
    const ReferenceTopic& topicOf(const QTreeWidgetItem* item) const;
    void filter(const QString& text);
    void select(QTreeWidgetItem* item);

    void placeFirstTime();
    void fitLayout();

    QLineEdit* m_search;
    QTreeWidget* m_list;
    QTextBrowser* m_page;
    QLabel* m_count;
    QString m_currentKey;
    QSplitter* m_splitter;
    bool m_placed = false;
    drive_core::DriveFamily m_family = drive_core::DriveFamily::Bds5;
    const QList<ReferenceTopic>* m_topics = nullptr;
};

} // namespace app
