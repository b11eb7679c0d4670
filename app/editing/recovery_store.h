// RecoveryStore: the crash-recovery folder. Each running ServoDesk owns a session folder under the root
// (QStandardPaths AppLocalDataLocation/recovery, or $SERVODESK_RECOVERY_DIR) holding one JSON file per
// unsaved buffer. A session whose owner process is gone (crash, kill -9) is an orphan whose buffers the
// next start offers to restore. GUI thread only; the files are small and written with QSaveFile.
//
// File format (chosen; no Motion Link equivalent): <root>/session-<pid>-<msecs>/owner holds the owner's
// pid; <id>.json is {"format":"servodesk-recovery/1","originalPath":...,"displayName":...,
// "savedAt":ISO-8601 UTC,"text":...}. JSON keeps any text and line ends exactly.
#pragma once

#include <QDateTime>
#include <QList>
#include <QString>

namespace app {

struct RecoveredBuffer {
    QString originalPath; // empty for a buffer that was never saved
    QString displayName;  // the tab's name ("untitled.bds", "MOTION.BDS")
    QString text;
    QDateTime savedAt;
    QString file; // the JSON file it came from
};

class RecoveryStore {
public:
    static inline const QString kEnvironmentVariable = QStringLiteral("SERVODESK_RECOVERY_DIR");

    // $SERVODESK_RECOVERY_DIR when set, else AppLocalDataLocation/recovery.
    static QString defaultRoot();

    explicit RecoveryStore(QString root = defaultRoot());
    RecoveryStore(const RecoveryStore&) = delete;
    RecoveryStore& operator=(const RecoveryStore&) = delete;

    QString root() const { return m_root; }
    // This process's session folder (created on first write).
    QString sessionDirectory() const { return m_session; }

    // Writes (replaces) buffer id's recovery file. False when the folder cannot be written.
    bool write(const QString& id, const QString& originalPath, const QString& displayName, const QString& text);
    void remove(const QString& id);
    // Removes this session's folder (a clean exit: nothing is left to recover).
    void removeSession();

    // Buffers left by sessions whose process is no longer running, oldest first.
    QList<RecoveredBuffer> orphans() const;
    // Deletes the orphan sessions' folders (after their buffers were restored or discarded).
    void discardOrphans();

private:
    bool ensureSession();
    QStringList orphanSessions() const;

    QString m_root;
    QString m_session;
    bool m_sessionReady = false;
};

} // namespace app
