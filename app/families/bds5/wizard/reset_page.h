// ResetPage: "Reset Variables" — puts the factory set STANDARD.VAR on the summary as changes, so the user
// sees what a reset would change before anything is sent. GUI thread.
#pragma once

#include "wizard_context.h"

#include <QWizardPage>

class QLabel;
class QPushButton;

namespace app {

class ResetPage final : public QWizardPage {
    Q_OBJECT
public:
    explicit ResetPage(WizardContext context, QWidget* parent = nullptr);

    void loadStandard();
    QPushButton* loadButton() const { return m_load; }

private:
    WizardContext m_context;
    QPushButton* m_load;
    QLabel* m_result;
};

} // namespace app
