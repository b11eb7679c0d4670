// SetupWizard: Motion Link's Setup Program (manual L1213-1233) as a QWizard — communicate, resolver
// zeroing, tune, drive test, feedback, input and output tests, machine units and limits, motor, modes,
// communications, other, reset and send variables. Its pages read and write only through the session;
// parameter pages hold their edits until the Send Variables page sends them. Every page has the same header:
// its title, and "Step N of M — what it is for". GUI thread; opened modeless.
#pragma once

#include "wizard_context.h"

#include <QWizard>

#include <memory>

namespace app {

class BenchPage;
class MotorChoice;
class ParameterPage;
class ResetPage;
class SummaryPage;
class WizardChanges;

class SetupWizard final : public QWizard {
    Q_OBJECT
public:
    explicit SetupWizard(DriveConnection& connection, QWidget* parent = nullptr);
    ~SetupWizard() override;

    // Tools > Setup Wizard: a new wizard, shown without blocking, deleted when closed.
    static SetupWizard* openFor(DriveConnection& connection, QWidget* parent);

    const QList<ParameterPage*>& parameterPages() const { return m_parameterPages; }
    const QList<BenchPage*>& benchPages() const { return m_benchPages; }
    SummaryPage* summaryPage() const { return m_summary; }
    ResetPage* resetPage() const { return m_reset; }
    MotorChoice* motorChoice() const { return m_motorChoice; } // on the Motor Setup page
    WizardChanges& changes() const { return *m_changes; }
    VariableModel& model() const { return *m_model; }
    // The id of the page with this title, -1 if none.
    int pageIdOf(const QString& title) const;

private:
    void addBenchPages();
    void addParameterPages();
    ParameterPage* addParameterPage(const QString& title, const QString& subTitle, const QStringList& names);
    QStringList liveNames() const;
    void numberPages();

    VariableModel* m_model;
    VariableSync* m_sync;
    WizardChanges* m_changes;
    std::unique_ptr<WizardContext> m_context;
    QList<ParameterPage*> m_parameterPages;
    QList<BenchPage*> m_benchPages;
    SummaryPage* m_summary = nullptr;
    ResetPage* m_reset = nullptr;
    MotorChoice* m_motorChoice = nullptr;
};

} // namespace app
