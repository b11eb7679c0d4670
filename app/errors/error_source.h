// ErrorSource: where one drive family's error log rows come from — its session's reported errors, and the
// drive's own record read on demand — kept in that family's ErrorLogModel. The Error Log dock shows the
// source of the family chosen in Drive > Connect; each family names (or hides) the dock's Read button and
// says what Clear does. GUI thread only.
#pragma once

#include "error_log_model.h"

#include <QObject>

#include <utility>

namespace app {

class ErrorSource : public QObject {
    Q_OBJECT
public:
    // The dock's buttons in the family's words: the Read button's text (empty hides it: the family keeps
    // no record) and tool tip, and what Clear does.
    struct Buttons {
        QString readText;
        QString readToolTip;
        QString clearToolTip;
    };

    ErrorSource(drive_core::DriveFamily family, Buttons buttons, QObject* parent = nullptr)
        : QObject(parent), m_model(new ErrorLogModel(family, this)), m_buttons(std::move(buttons)) {}

    drive_core::DriveFamily family() const { return m_model->family(); }
    ErrorLogModel& model() const { return *m_model; }
    QString statusText() const { return m_status; }

    const Buttons& buttons() const { return m_buttons; }
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
    Buttons m_buttons;
    QString m_status;
};

} // namespace app
