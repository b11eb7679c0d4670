// SetupWizard: the pages, built from catalog names.
#include "setup_wizard.h"

#include "session_host.h"
#include "bench_page.h"
#include "motor_choice.h"
#include "parameter_page.h"
#include "reset_page.h"
#include "summary_page.h"
#include "variables/variable_model.h"
#include "variables/variable_sync.h"
#include "wizard_changes.h"

namespace app {

namespace {
QStringList numbered(const QString& stem, int first, int last) {
    QStringList names;
    for (int i = first; i <= last; ++i) names << stem + QString::number(i);
    return names;
}
} // namespace

SetupWizard::SetupWizard(DriveConnection& connection, QWidget* parent)
    : QWizard(parent), m_model(new VariableModel(drive_core::DriveFamily::Bds5, this)), m_changes(new WizardChanges(this)) {
    setObjectName(QStringLiteral("setupWizard"));
    setWindowTitle(tr("BDS5 Setup"));
    setWizardStyle(QWizard::ModernStyle);
    setOption(QWizard::NoBackButtonOnStartPage);
    resize(860, 600);
    m_sync = new VariableSync(SessionHost::of(connection), *m_model, this);
    m_context = std::make_unique<WizardContext>(WizardContext{connection, *m_model, *m_sync, *m_changes});
    m_sync->setWanted([this] { return liveNames(); });
    connect(m_model, &QAbstractItemModel::dataChanged, this, [this](const QModelIndex& first) {
        const QString name = first.data(VariableModel::NameRole).toString();
        if (!name.isEmpty()) m_changes->setOriginal(name, m_model->value(name));
    });
    addBenchPages();
    addParameterPages();
    m_reset = new ResetPage(*m_context, this);
    addPage(m_reset);
    m_summary = new SummaryPage(*m_context, this);
    addPage(m_summary);
    numberPages();
}

SetupWizard::~SetupWizard() = default;

SetupWizard* SetupWizard::openFor(DriveConnection& connection, QWidget* parent) {
    auto* wizard = new SetupWizard(connection, parent);
    wizard->setAttribute(Qt::WA_DeleteOnClose);
    wizard->open();
    return wizard;
}

void SetupWizard::addBenchPages() {
    using Action = BenchPage::Action;
    auto add = [this](const QString& title, const QString& text, QList<Action> actions, const QStringList& readout) {
        auto* page = new BenchPage(*m_context, title, text, std::move(actions), readout, this);
        m_benchPages << page;
        addPage(page);
    };
    add(tr("Communicate with the BDS5"),
        tr("ServoDesk talks to the drive through the connection chosen under Drive > Connect. Press Test: "
           "the drive should answer with its baud rate and address."),
        {{tr("Test"), QStringLiteral("P BAUD ADDR"), {}}}, {QStringLiteral("BAUD"), QStringLiteral("ADDR")});
    add(tr("Resolver Zeroing Test"),
        tr("With the drive disabled, turn the motor shaft by hand: PFB should count up clockwise and return to "
           "the same value after one turn. PRD is the resolver position within one turn."),
        {{tr("Disable"), QStringLiteral("DIS"), {}}}, {QStringLiteral("PFB"), QStringLiteral("PRD")});
    add(tr("Tune Drive"),
        tr("TUNE sets the loop gains for a bandwidth (Hz) and a stability factor. The motor moves: make sure "
           "it is free to turn."),
        {{tr("Tune"),
          QStringLiteral("TUNE %1 %2"),
          {{tr("Bandwidth"), QStringLiteral("50")}, {tr("Stability"), QStringLiteral("1")}}}},
        {QStringLiteral("KP"), QStringLiteral("KV"), QStringLiteral("KVI")});
    add(tr("Drive Test"), tr("Enable the drive, jog at a low speed and stop. ACTIVE shows the power stage."),
        {{tr("Enable"), QStringLiteral("EN"), {}},
         {tr("Jog"), QStringLiteral("J %1"), {{tr("Speed"), QStringLiteral("100")}}},
         {tr("Stop"), QStringLiteral("S"), {}},
         {tr("Disable"), QStringLiteral("DIS"), {}}},
        {QStringLiteral("ACTIVE"), QStringLiteral("VFB"), QStringLiteral("PFB")});
    add(tr("Drive Feedback"), tr("Position, velocity and resolver feedback, read live from the drive."), {},
        {QStringLiteral("PFB"), QStringLiteral("VFB"), QStringLiteral("PRD")});
    add(tr("Input Test"), tr("Switch the inputs one by one: each lamp should follow its input."), {},
        numbered(QStringLiteral("I"), 1, 16));
    add(tr("Output Test"), tr("Each button switches one output on the drive at once and shows what it reads back."), {},
        numbered(QStringLiteral("O"), 1, 8));
}

ParameterPage* SetupWizard::addParameterPage(const QString& title, const QString& subTitle, const QStringList& names) {
    auto* page = new ParameterPage(*m_context, title, subTitle, names, this);
    m_parameterPages << page;
    addPage(page);
    return page;
}

void SetupWizard::addParameterPages() {
    auto s = [](const char* list) { return QString::fromLatin1(list).split(QLatin1Char(' ')); };
    ParameterPage* units = addParameterPage(tr("Machine Setup \u2014 Units"),
                                            tr("User units: the drive scales every value by NUM/DEN (L1521-1560)."),
                                            s("PNUM PDEN VNUM VDEN ANUM ADEN INUM IDEN PXNUM PXDEN VXNUM VXDEN"));
    units->setPreview([](const std::function<double(const QString&)>& v) {
        auto ratio = [&v](const char* num, const char* den) {
            const double d = v(QString::fromLatin1(den));
            return d != 0 ? v(QString::fromLatin1(num)) / d : 0.0;
        };
        return tr("Preview: 1 position unit = %1 counts \u00b7 1 velocity unit = %2 RPM \u00b7 1 acceleration "
                  "unit = %3 RPM/s \u00b7 1 current unit = %4 % of drive amps")
            .arg(ratio("PNUM", "PDEN"), 0, 'g', 6)
            .arg(ratio("VNUM", "VDEN") / 4473.9, 0, 'g', 6)
            .arg(ratio("ANUM", "ADEN") / 4.474, 0, 'g', 6)
            .arg(ratio("INUM", "IDEN") / 40.95, 0, 'g', 6);
    });
    addParameterPage(tr("Machine Setup \u2014 Limits"), tr("Travel, speed, acceleration and current limits."),
                     s("PMAX PMIN PLIM VMAX AMAX ILIM IMAX PEMAX VOSPD"));
    ParameterPage* motor = addParameterPage(tr("Motor Setup"), tr("The motor and its current and protection settings."),
                                            s("ICONT IFOLD FOLD VMAX VOSPD KP KV KVI"));
    m_motorChoice = new MotorChoice(m_context->connection, motor);
    motor->addWidget(m_motorChoice);
    connect(m_motorChoice, &MotorChoice::motorChanged, motor, &ParameterPage::readAgain);
    addParameterPage(tr("BDS5 Modes"), tr("Operating mode switches."),
                     s("PL PROP TQ GEAR EXTLOOP RAMP ROTARY ZERO CLAMP DIR"));
    addParameterPage(tr("Communications"), tr("Serial line settings. A new BAUD takes effect at once."),
                     s("BAUD ADDR ABAUD WATCH PROMPT MULTI ECHO"));
    addParameterPage(tr("Other"), tr("Remaining dedicated switches."),
                     s("DEP FAULT STATMODE TRIP CAP CAPDIR REG GATEMODE"));
}

// "Step 3 of 15 — ..." heads every page's subtitle. A subtitle on every page also gives every page QWizard's
// one header: a page without one shows its title in the page body instead, in another style.
void SetupWizard::numberPages() {
    const QList<int> ids = pageIds();
    for (qsizetype i = 0; i < ids.size(); ++i) {
        QWizardPage* p = page(ids[i]);
        const QString step = tr("Step %1 of %2").arg(i + 1).arg(ids.size());
        p->setSubTitle(p->subTitle().isEmpty() ? step : tr("%1 \u2014 %2").arg(step, p->subTitle()));
    }
}

int SetupWizard::pageIdOf(const QString& title) const {
    for (const int id : pageIds())
        if (page(id)->title() == title) return id;
    return -1;
}

QStringList SetupWizard::liveNames() const {
    if (!isVisible()) return {};
    for (const BenchPage* bench : m_benchPages)
        if (bench == currentPage()) return bench->liveNames();
    return {};
}

} // namespace app
