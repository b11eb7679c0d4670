// RecentFiles: the File > Open Recent list, newest first, at most kMaxFiles, kept in QSettings under
// kSettingsKey so it survives restarts. GUI thread only.
#pragma once

#include <QObject>
#include <QStringList>

class QMenu;

namespace app {

class RecentFiles final : public QObject {
    Q_OBJECT
public:
    static constexpr int kMaxFiles = 10;
    static inline const QString kSettingsKey = QStringLiteral("files/recent");

    explicit RecentFiles(QObject* parent = nullptr);

    QStringList files() const;
    // Moves path to the top (absolute path; duplicates removed).
    void add(const QString& path);
    void remove(const QString& path);
    void clear();

    // Fills menu with "&1 name" entries (tool tip: the full path) and "Clear Menu"; choosing an entry
    // emits openRequested.
    void fillMenu(QMenu* menu);

signals:
    void openRequested(const QString& path);

private:
    void store(const QStringList& files);
};

} // namespace app
