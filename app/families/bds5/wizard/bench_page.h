// BenchPage: a setup-wizard page for testing rather than setting — buttons that send commands (EN, J,
// TUNE, ...) with optional fields, a live readout of variables (switches as lamps; writable switches such
// as O1-O8 as toggles that act at once, since toggling them is the test), and the drive's answers.
// GUI thread; everything goes through the session.
#pragma once

#include "wizard_context.h"

#include "serialport/bds5_session.h"

#include <QHash>
#include <QPointer>
#include <QWizardPage>

class QLabel;
class QLineEdit;
class QPlainTextEdit;
class QPushButton;

namespace app {

class BenchPage final : public QWizardPage {
    Q_OBJECT
public:
    struct Field {
        QString label;
        QString initial;
    };
    struct Action {
        QString label;
        QString command; // "%1", "%2" are replaced by the fields' values
        QList<Field> fields;
    };

    BenchPage(WizardContext context, const QString& title, const QString& text, QList<Action> actions,
              const QStringList& readout, QWidget* parent = nullptr);

    // The readout's variables: the wizard polls them while this page is shown.
    const QStringList& liveNames() const { return m_readout; }
    QPushButton* actionButton(const QString& label) const;
    QPushButton* toggleFor(const QString& name) const;
    QString log() const;
    // What the readout shows for a number ("BAUD  9600"), as text without its markup; empty for a lamp.
    QString readoutText(const QString& name) const;

private:
    QWidget* makeReadout();
    void run(const QString& line);
    void onFinished(quint64 id, const serialport::Bds5Response& response);
    void showValue(const QString& name);

    WizardContext m_context;
    QStringList m_readout;
    QHash<QString, QLabel*> m_values;
    QHash<QString, QPushButton*> m_toggles;
    QHash<QString, QPushButton*> m_actions;
    QPlainTextEdit* m_log;
    QPointer<serialport::Bds5Session> m_session;
    QList<quint64> m_pending;
};

} // namespace app
