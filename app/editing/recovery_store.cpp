// RecoveryStore: session folders, buffer files and orphan detection.
#include "recovery_store.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSaveFile>
#include <QStandardPaths>

#include <algorithm>
#include <cerrno>
#include <csignal>

namespace app {

namespace {
const QString kFormat = QStringLiteral("servodesk-recovery/1");
const QString kOwnerFile = QStringLiteral("owner");
const QString kSessionPrefix = QStringLiteral("session-");

// A process that exists (even one we may not signal) is alive.
bool processIsRunning(qint64 pid) {
    if (pid <= 0) return false;
    return ::kill(pid_t(pid), 0) == 0 || errno == EPERM;
}

qint64 ownerOf(const QString& sessionDir) {
    QFile file(QDir(sessionDir).filePath(kOwnerFile));
    if (!file.open(QIODevice::ReadOnly)) return 0;
    return file.readAll().trimmed().toLongLong();
}
} // namespace

QString RecoveryStore::defaultRoot() {
    const QString fromEnvironment = qEnvironmentVariable("SERVODESK_RECOVERY_DIR");
    if (!fromEnvironment.isEmpty()) return fromEnvironment;
    return QDir(QStandardPaths::writableLocation(QStandardPaths::AppLocalDataLocation))
        .filePath(QStringLiteral("recovery"));
}

RecoveryStore::RecoveryStore(QString root) : m_root(std::move(root)) {
    m_session = QDir(m_root).filePath(QStringLiteral("%1%2-%3")
                                          .arg(kSessionPrefix)
                                          .arg(QCoreApplication::applicationPid())
                                          .arg(QDateTime::currentMSecsSinceEpoch()));
}

bool RecoveryStore::write(const QString& id, const QString& originalPath, const QString& displayName,
                          const QString& text) {
    if (!ensureSession()) return false;
    const QJsonObject object{{QStringLiteral("format"), kFormat},
                             {QStringLiteral("originalPath"), originalPath},
                             {QStringLiteral("displayName"), displayName},
                             {QStringLiteral("savedAt"), QDateTime::currentDateTimeUtc().toString(Qt::ISODateWithMs)},
                             {QStringLiteral("text"), text}};
    QSaveFile file(QDir(m_session).filePath(id + QStringLiteral(".json")));
    if (!file.open(QIODevice::WriteOnly)) return false;
    file.write(QJsonDocument(object).toJson(QJsonDocument::Compact));
    return file.commit();
}

void RecoveryStore::remove(const QString& id) {
    if (m_sessionReady) QFile::remove(QDir(m_session).filePath(id + QStringLiteral(".json")));
}

void RecoveryStore::removeSession() {
    if (m_sessionReady) QDir(m_session).removeRecursively();
    m_sessionReady = false;
}

QList<RecoveredBuffer> RecoveryStore::orphans() const {
    QList<RecoveredBuffer> buffers;
    for (const QString& session : orphanSessions()) {
        const QDir dir(session);
        for (const QString& name : dir.entryList({QStringLiteral("*.json")}, QDir::Files)) {
            QFile file(dir.filePath(name));
            if (!file.open(QIODevice::ReadOnly)) continue;
            const QJsonObject object = QJsonDocument::fromJson(file.readAll()).object();
            if (object.value(QStringLiteral("format")).toString() != kFormat) continue;
            buffers.append(
                {object.value(QStringLiteral("originalPath")).toString(),
                 object.value(QStringLiteral("displayName")).toString(),
                 object.value(QStringLiteral("text")).toString(),
                 QDateTime::fromString(object.value(QStringLiteral("savedAt")).toString(), Qt::ISODateWithMs),
                 file.fileName()});
        }
    }
    std::sort(buffers.begin(), buffers.end(),
              [](const RecoveredBuffer& a, const RecoveredBuffer& b) { return a.savedAt < b.savedAt; });
    return buffers;
}

void RecoveryStore::discardOrphans() {
    for (const QString& session : orphanSessions()) QDir(session).removeRecursively();
}

bool RecoveryStore::ensureSession() {
    if (m_sessionReady) return true;
    // The folder appears under its session name only with its owner file inside (built under another
    // name, then renamed), so no other instance ever sees a session without an owner.
    const QFileInfo session(m_session);
    const QString building = QDir(session.absolutePath()).filePath(QStringLiteral("new-") + session.fileName());
    if (!QDir().mkpath(building)) return false;
    QSaveFile owner(QDir(building).filePath(kOwnerFile));
    if (!owner.open(QIODevice::WriteOnly)) return false;
    owner.write(QByteArray::number(QCoreApplication::applicationPid()) + '\n');
    if (!owner.commit() || !QDir().rename(building, m_session)) return false;
    m_sessionReady = true;
    return true;
}

QStringList RecoveryStore::orphanSessions() const {
    QStringList sessions;
    const QDir root(m_root);
    for (const QString& name : root.entryList({kSessionPrefix + QLatin1Char('*')}, QDir::Dirs | QDir::NoDotAndDotDot)) {
        const QString path = root.filePath(name);
        if (QDir(path) == QDir(m_session)) continue;
        if (!processIsRunning(ownerOf(path))) sessions.append(path);
    }
    return sessions;
}

} // namespace app
