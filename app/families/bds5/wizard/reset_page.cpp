// ResetPage: STANDARD.VAR as pending changes.
#include "reset_page.h"

#include "variables/variable_sync.h"
#include "wizard_changes.h"

#include "resources/resources.h"
#include "serialport/bds5_variable_file.h"

#include <QFile>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

namespace app {

ResetPage::ResetPage(WizardContext context, QWidget* parent) : QWizardPage(parent), m_context(context) {
    setTitle(tr("Reset Variables"));
    setSubTitle(tr("Return the drive's variables to the factory set, STANDARD.VAR."));
    auto* layout = new QVBoxLayout(this);
    auto* text = new QLabel(tr("This puts every value of STANDARD.VAR on the next page as a change. Review "
                               "them there: nothing is sent until you press Send to Drive."),
                            this);
    text->setWordWrap(true);
    layout->addWidget(text);
    m_load = new QPushButton(tr("Load STANDARD.VAR"), this);
    layout->addWidget(m_load, 0, Qt::AlignLeft);
    m_result = new QLabel(this);
    layout->addWidget(m_result);
    layout->addStretch(1);
    connect(m_load, &QPushButton::clicked, this, &ResetPage::loadStandard);
}

void ResetPage::loadStandard() {
    QFile file(resources::kStandardVariables);
    if (!file.open(QIODevice::ReadOnly)) {
        m_result->setText(tr("STANDARD.VAR is missing from this build."));
        return;
    }
    const auto set = serialport::Bds5VariableFile::parse(QString::fromLatin1(file.readAll()));
    QStringList names;
    for (const serialport::Bds5Assignment& a : set.assignments()) {
        if (a.value.isEmpty()) continue; // CLEARX
        m_context.changes.setEdited(a.name, a.value);
        names << a.name;
    }
    m_context.sync.readNow(names); // values the drive already holds drop off the list as they arrive
    m_result->setText(
        tr("%n value(s) from STANDARD.VAR loaded; the drive's values are being read.", nullptr, int(names.size())));
}

} // namespace app
