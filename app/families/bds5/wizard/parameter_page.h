// ParameterPage: a setup-wizard page that lists catalog variables — name, an editor chosen by the
// variable's kind (switch or number), unit, limits, description — read from the drive when the page is
// shown. Edits are validated and recorded in WizardChanges; nothing is sent from here (VESC Tool's lesson:
// parameters described as data, rendered by one generic editor). GUI thread.
#pragma once

#include "wizard_context.h"

#include <QHash>
#include <QWizardPage>

#include <functional>

class QLabel;
class QVBoxLayout;
class QWidget;

namespace app {

class ParameterPage final : public QWizardPage {
    Q_OBJECT
public:
    // A line under the form computed from the values shown (the units page's conversion preview).
    using Preview = std::function<QString(const std::function<double(const QString&)>& valueOf)>;

    ParameterPage(WizardContext context, const QString& title, const QString& subTitle, const QStringList& names,
                  QWidget* parent = nullptr);

    void setPreview(Preview preview);
    // A widget of the page's own between the variables and the preview (the Motor Setup page's motor list).
    void addWidget(QWidget* widget);
    // Reads the page's variables from the drive again (after the simulated motor was swapped).
    void readAgain();
    const QStringList& names() const { return m_names; }
    // What the page's editor for name shows ("7500", "ON"); setText() types into it as a user would.
    QString text(const QString& name) const;
    void setText(const QString& name, const QString& text);
    QString previewText() const;

    void initializePage() override;

private:
    void addRow(const QString& name);
    void showRead(const QString& name);
    void edited(const QString& name, const QString& text);
    void updatePreview();

    WizardContext m_context;
    QStringList m_names;
    QHash<QString, QWidget*> m_editors;
    QHash<QString, QLabel*> m_problems;
    QLabel* m_preview = nullptr;
    QVBoxLayout* m_outer = nullptr;
    Preview m_previewFunction;
};

} // namespace app
