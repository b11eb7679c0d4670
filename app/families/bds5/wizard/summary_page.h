// SummaryPage: "Send Variables" — every change the wizard's pages hold, old and new value side by side;
// nothing reaches the drive until the user presses Send, and the set can be saved as a .VAR file.
// GUI thread.
#pragma once

#include "wizard_context.h"

#include <QHash>
#include <QWizardPage>

class QLabel;
class QPushButton;
class QTreeWidget;

namespace app {

class SummaryPage final : public QWizardPage {
    Q_OBJECT
public:
    explicit SummaryPage(WizardContext context, QWidget* parent = nullptr);

    void initializePage() override;
    void send();                       // each change as "NAME value", each read back
    bool saveVar(const QString& path); // the changes as .VAR
    QPushButton* sendButton() const { return m_send; }
    QTreeWidget* table() const { return m_table; }
    QString statusOf(const QString& name) const { return m_status.value(name); }

private:
    void refresh();
    void saveWithDialog();

    WizardContext m_context;
    QTreeWidget* m_table;
    QPushButton* m_send;
    QLabel* m_note;
    QHash<QString, QString> m_status; // per variable: sent, or the drive's refusal
    QStringList m_shown;
};

} // namespace app
