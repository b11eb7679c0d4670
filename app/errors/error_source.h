// ErrorSource: where one drive family's error log rows come from — its session's reported errors, and the
// drive's own record read on demand — kept in that family's ErrorLogModel. The Error Log dock shows the
// source of the family chosen in Drive > Connect; each family names (or hides) the dock's Read button and
// says what Clear does. GUI thread only.
#pragma once

#include "error_log_model.h"

#include <QObject>

namespace app {

class ErrorSource : public QObject {
    Q_OBJECT
public:
    explicit ErrorSource(drive_core::DriveFamily family, QObject* parent = nullptr)
        : QObject(parent), m_model(new ErrorLogModel(family, this)) {}

    drive_core::DriveFamily family() const { return m_model->family(); }
    ErrorLogModel& model() const { return *m_model; }
    QString statusText() const { return m_status; }

    // The Read button's text and tool tip; an empty text hides the button (the family keeps no record).
    virtual QString readText() const = 0;
    virtual QString readToolTip() const = 0;
    virtual QString clearToolTip() const = 0;
    // Reads the drive's record into the history rows; the outcome arrives in the status line.
    virtual void read() = 0;
    // Empties the log (and the drive's record where the drive has a command for it).
    virtual void clear() = 0;
    // Shows the program line of an activated row (entry.programLine > 0); false leaves it to the dock's owner.
    virtual bool showLine(const ErrorLogModel::Entry& entry) {
        Q_UNUSED(entry);
        return false;
    }

signals:
    void statusChanged(const QString& text);

protected:
    void setStatus(const QString& text) {
        m_status = text;
        emit statusChanged(text);
    }

private:
    ErrorLogModel* m_model;
    QString m_status;
};

} // namespace app
