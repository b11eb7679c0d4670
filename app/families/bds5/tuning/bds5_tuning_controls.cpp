// The BDS5's Tuning panel: TUNE, the soft-limits question, the read on connecting.
#include "bds5_tuning_controls.h"

#include "tuning_runner.h"

#include "app/tuning/tuning_frame.h"
#include "app/tuning/tuning_panel.h"
#include "families/bds5/drive_connection.h"

#include <QComboBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QLabel>
#include <QMessageBox>
#include <QPointer>
#include <QPushButton>

namespace app {

namespace {
const int kBandwidths[] = {5, 10, 15, 20, 25, 30, 40, 50}; // Hz, the values TUNE allows (L6283)

const QString kName = QStringLiteral("bds5SoftLimitsAsker");

// Keeps the open question, a child of the panel so that softLimitsQuestion() finds it.
class SoftLimitsAsker final : public QObject {
public:
    SoftLimitsAsker(TuningPanel& panel, TuningRunner& runner) : QObject(&panel), m_panel(panel), m_runner(runner) {
        setObjectName(kName);
        connect(&runner, &TuningRunner::softLimitsInTheWay, this, &SoftLimitsAsker::ask);
        connect(&runner, &Tuner::stateChanged, this, [this] {
            if (m_box && !m_runner.isWaitingForAnswer()) m_box->close(); // Stop answered it
        });
    }
    QMessageBox* box() const { return m_box; }

private:
    // Non-modal: the run waits in the runner until the answer (or Stop) comes.
    void ask(const QString& why) {
        auto* box = new QMessageBox(QMessageBox::Warning, tr("Software Travel Limits"),
                                    why + QStringLiteral("\n\n") +
                                        tr("At power-up PMAX and PMIN are only +-100 counts. Set them for the machine "
                                           "to keep the limits on, or turn the limits off for this test: ServoDesk "
                                           "sends PLIM=0 before the run and PLIM=1 once it is over."),
                                    QMessageBox::Cancel, m_panel.window());
        box->setObjectName(QStringLiteral("softLimitsQuestion"));
        QPushButton* off = box->addButton(tr("Turn off the soft limits (PLIM=0) for the test"), QMessageBox::AcceptRole);
        box->setDefaultButton(QMessageBox::Cancel);
        box->setAttribute(Qt::WA_DeleteOnClose);
        m_box = box;
        connect(box, &QMessageBox::finished, this, [this, box, off](int) {
            if (!m_runner.isWaitingForAnswer()) return; // stopped meanwhile
            if (box->clickedButton() == off) return m_runner.runWithoutSoftLimits();
            m_runner.stop();
            m_panel.setStatus(tr("Not run: the test move would pass the software travel limits. Set PMAX and PMIN "
                                 "for the machine, or run again and turn the limits off for the test."));
        });
        m_panel.setStatus(tr("Waiting: the test move would pass the software travel limits (PMAX/PMIN)."));
        box->open();
    }

    TuningPanel& m_panel;
    TuningRunner& m_runner;
    QPointer<QMessageBox> m_box;
};

QWidget* tuneGroup(TuningPanel& panel, TuningRunner& runner) {
    const auto [box, form] = addControlGroup(&panel, QObject::tr("TUNE (self-tuning)"));
    auto* bandwidth = new QComboBox(box);
    for (const int hz : kBandwidths) bandwidth->addItem(QObject::tr("%1 Hz").arg(hz), hz);
    bandwidth->setCurrentIndex(5); // 30 Hz, the manual's example
    auto* stability = new QComboBox(box);
    stability->addItem(QObject::tr("1 \u2014 slightly overdamped"), 1);
    stability->addItem(QObject::tr("2 \u2014 critically damped"), 2);
    stability->addItem(QObject::tr("3 \u2014 slightly underdamped"), 3);
    stability->setCurrentIndex(1);
    form->addRow(QObject::tr("Bandwidth"), bandwidth);
    form->addRow(QObject::tr("Stability"), stability);
    auto* warning =
        new QLabel(QObject::tr("<b>Warning:</b> the drive will be enabled and the motor will turn. TUNE shakes the "
                               "motor vigorously at about 15 Hz and full torque: secure the motor, and reduce ILIM "
                               "first if the machine could be damaged or overspeed (restore it afterwards)."),
                   box);
    warning->setWordWrap(true);
    form->addRow(warning);
    auto* tune = new QPushButton(QObject::tr("TUNE"), box);
    QObject::connect(tune, &QPushButton::clicked, &runner, [&runner, bandwidth, stability] {
        runner.tune(bandwidth->currentData().toInt(), stability->currentData().toInt());
    });
    form->addRow(tune);
    return box;
}
} // namespace

TuningPanel* makeBds5TuningPanel(DriveConnection& connection, QWidget* parent) {
    auto* runner = new TuningRunner(connection);
    auto* panel = new TuningPanel(runner, parent);
    panel->addControls(tuneGroup(*panel, *runner));
    new SoftLimitsAsker(*panel, *runner);
    // The editors show the drive's gains from the start (the read waits in the session's queue).
    QObject::connect(&connection, &DriveConnection::connectedChanged, runner, [runner](bool connected) {
        if (connected) runner->readGains();
    });
    return panel;
}

QMessageBox* softLimitsQuestion(const TuningPanel& panel) {
    // Not a Q_OBJECT: found by name, and only this file makes one.
    const auto* asker = static_cast<const SoftLimitsAsker*>(panel.findChild<QObject*>(kName, Qt::FindDirectChildrenOnly));
    return asker ? asker->box() : nullptr;
}

void setTestMove(TuningPanel& panel, const TestMove& move) {
    panel.setMove(int(move.kind), move.amplitude, move.durationMs);
    panel.runner<TuningRunner>().useMoveVelocity(move.moveVelocity);
}

} // namespace app
