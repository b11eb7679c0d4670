// Controller Set Up, Manual (seed-sc750 §2.10, L2530-L2553) against the simulated SC750: the "Controller
// Set Up Data" screen pre-filled from the motor, the computed values following an edit of it, a bad value
// refused, and OK writing the computed value into the program's PARAMS block and the controller.
#include "family_window.h"
#include "app/main_window.h"
#include "families/sc750/sc750_controller_menu.h"
#include "families/sc750/sc750_setup_data_table.h"
#include "families/sc750/sc750_setup_dialog.h"
#include "families/sc750/sc750_variables_dock.h"
#include "families/sc750/sc750_workspace.h"

#include "editor/program_editor.h"

#include <QDialogButtonBox>
#include <QPushButton>
#include <QRadioButton>
#include <QSettings>
#include <QStandardPaths>
#include <QTableWidget>
#include <QTest>

using app::MainWindow;
using app::Sc750Workspace;
using drive_core::DriveFamily;

namespace {
constexpr int kTimeoutMs = 20000;

// The computed table's value for a parameter, as the user reads it.
QString computed(const app::Sc750SetupDialog& dialog, const QString& name) {
    const QList<QTableWidgetItem*> found = dialog.table()->findItems(name, Qt::MatchExactly);
    return found.isEmpty() ? QString() : dialog.table()->item(found.front()->row(), 1)->text();
}

QRadioButton* radio(const QWidget& dialog, const QString& text) {
    for (QRadioButton* button : dialog.findChildren<QRadioButton*>())
        if (button->text() == text) return button;
    return nullptr;
}
} // namespace

class Sc750SetupTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QCoreApplication::setOrganizationName(QStringLiteral("ServoDesk"));
        QCoreApplication::setApplicationName(QStringLiteral("ServoDeskSc750SetupTest"));
        QSettings().clear();
    }

    // Manual: a load as heavy as the R45G's rotor doubles KVP (0.062053 -> 0.124106) in the computed
    // values; OK puts that KVP in the program's PARAMS block and into the controller.
    void manualLoadInertiaChangesKvpAndOkWritesIt() {
        MainWindow window;
        window.show();
        auto& ws = family_window::connectSc750(window);
        QTRY_VERIFY_WITH_TIMEOUT(ws.isConnected(), kTimeoutMs);
        auto* menu = qobject_cast<app::Sc750ControllerMenu*>(ws.menus().at(1));
        menu->createProgram();
        auto* setup = qobject_cast<app::Sc750SetupDialog*>(menu->controllerSetUp());
        QVERIFY(setup);
        QTRY_COMPARE_WITH_TIMEOUT(setup->controllerModel(), 752, kTimeoutMs);
        setup->setMotorPart(QStringLiteral("R45G"));
        app::Sc750SetupDataTable* data = setup->setupDataTable();
        QVERIFY(!data->isVisible()); // Auto: no data screen
        QCOMPARE(computed(*setup, QStringLiteral("KVP")), QStringLiteral("0.062053"));

        radio(*setup, QStringLiteral("&Manual"))->click();
        QVERIFY(data->isVisible());
        QCOMPARE(data->valueItem(QStringLiteral("Rotor inertia"))->text(), QStringLiteral("1.84313"));
        QCOMPARE(data->valueItem(QStringLiteral("Load inertia"))->text(), QStringLiteral("0"));
        QCOMPARE(computed(*setup, QStringLiteral("KVP")), QStringLiteral("0.062053")); // same data, same values
        QVERIFY(setup->table()->item(0, 1)->flags() & Qt::ItemIsEditable);

        data->valueItem(QStringLiteral("Load inertia"))->setText(QStringLiteral("1.84313"));
        QCOMPARE(computed(*setup, QStringLiteral("KVP")), QStringLiteral("0.124106"));

        // A torque constant of 0 is refused: the cell goes red, the status says why, OK waits.
        QPushButton* ok = setup->findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Ok);
        data->valueItem(QStringLiteral("Torque constant (Kt)"))->setText(QStringLiteral("0"));
        QVERIFY(!ok->isEnabled());
        QVERIFY(setup->status().contains(QStringLiteral("Torque constant")));
        QCOMPARE(data->valueItem(QStringLiteral("Torque constant (Kt)"))->background().color(),
                 QColor(0xf9, 0xde, 0xdc));
        data->valueItem(QStringLiteral("Torque constant (Kt)"))->setText(QStringLiteral("0.97"));
        QVERIFY(ok->isEnabled());
        QCOMPARE(computed(*setup, QStringLiteral("KVP")), QStringLiteral("0.124106"));

        ok->click();
        const QString program = window.editor()->text();
        QVERIFY(program.contains(QStringLiteral("' Motor R45G, Stiff/High Bandwidth\nPARAMS START\n")));
        QVERIFY(program.contains(QStringLiteral("\nKVP = 0.124106\n")));
        QVERIFY(program.contains(QStringLiteral("\nILC = 59\n")));
        ws.variablesDock()->readVariable(QStringLiteral("KVP"));
        QTRY_COMPARE_WITH_TIMEOUT(ws.variablesDock()->value(QStringLiteral("KVP")), QStringLiteral(".124106"),
                                  kTimeoutMs);
    }
};

QTEST_MAIN(Sc750SetupTest)
#include "sc750_setup_test.moc"
