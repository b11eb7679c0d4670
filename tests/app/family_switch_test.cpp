// Choosing the drive family: the main window hands a non-BDS5 choice to that family's workspace, which
// reaches the family's simulated drive over its own link (a PMC-960 answers a CR with its "}" prompt),
// shows its menus instead of the BDS5's, and gives the port back when the user returns to the BDS5; nothing
// the BDS5 was still sending reaches the terminal after the switch. The choice survives in the settings and on
// the command line.
#include "app/command_line.h"
#include "app/drive/connection_choice.h"
#include "app/drive/connection_dialog.h"
#include "families/bds5/drive_connection.h"
#include "app/drive/family_workspace.h"
#include "app/drive/terminal_widget.h"
#include "app/main_window.h"
#include "families/sc750/sc750_workspace.h"

#include <QComboBox>
#include <QLabel>
#include <QMenu>
#include <QMenuBar>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTest>
#include <QTimer>

#include <memory>
#include <optional>

using app::ConnectionChoice;
using drive_core::DriveFamily;

namespace {
constexpr int kTimeoutMs = 10000;

// The smallest workspace: opens the choice's link and keeps what the drive sends.
class ProbeWorkspace final : public app::FamilyWorkspace {
public:
    explicit ProbeWorkspace(QWidget* window) : m_menu(new QMenu(QStringLiteral("&Probe"), window)) {}

    DriveFamily family() const override { return DriveFamily::Pmc960; }
    QList<QMenu*> menus() const override { return {m_menu}; }
    QList<QDockWidget*> docks() const override { return {}; }
    void activate(const ConnectionChoice& choice) override {
        ++activations;
        m_link = choice.makeLink();
        connect(m_link.get(), &serialport::Link::bytesReceived, this, [this](const QByteArray& b) { received += b; });
        connect(m_link.get(), &serialport::Link::opened, this, &FamilyWorkspace::statusChanged);
        m_link->open();
    }
    void deactivate() override {
        if (m_link) m_link->close();
        m_link.reset();
        emit statusChanged();
    }
    bool isConnected() const override { return m_link && m_link->isOpen(); }
    QString statusText() const override { return isConnected() ? QStringLiteral("Probe on PMC-960") : QStringLiteral("Probe idle"); }
    void write(const QByteArray& bytes) { m_link->write(bytes); }

    QByteArray received;
    int activations = 0;

private:
    QMenu* m_menu;
    std::unique_ptr<serialport::Link> m_link;
};

// Whether the menu bar shows the menu; no value when there is no such menu at all.
std::optional<bool> menuVisible(const app::MainWindow& window, const QString& title) {
    for (QAction* action : window.menuBar()->actions())
        if (action->text() == title) return action->isVisible();
    return std::nullopt;
}

QString labelText(const app::MainWindow& window, const char* name) {
    const auto* label = window.statusBar()->findChild<QLabel*>(QLatin1String(name));
    return label ? label->text() : QString();
}

bool bds5Ready(const app::MainWindow& window) {
    const auto* session = window.connection().session();
    return session && session->state() == serialport::Bds5Session::State::Ready;
}
} // namespace

class FamilySwitchTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QCoreApplication::setOrganizationName(QStringLiteral("ServoDesk"));
        QCoreApplication::setApplicationName(QStringLiteral("ServoDeskFamilyTest"));
    }

    void aFamilyGetsItsWorkspaceAndTheBds5ComesBack() {
        app::MainWindow window;
        auto* probe = new ProbeWorkspace(&window);
        window.addWorkspace(probe); // stands in for the built-in PMC-960 workspace
        window.connectDrive(ConnectionChoice::simulator());
        window.show();
        QTRY_VERIFY_WITH_TIMEOUT(bds5Ready(window), kTimeoutMs);
        QCOMPARE(menuVisible(window, QStringLiteral("&Program")), true);
        QCOMPARE(menuVisible(window, QStringLiteral("&Probe")), false);

        window.connectDrive(ConnectionChoice::simulator(DriveFamily::Pmc960));
        QCOMPARE(window.activeFamily(), DriveFamily::Pmc960);
        QCOMPARE(probe->activations, 1);
        QCOMPARE(menuVisible(window, QStringLiteral("&Probe")), true);
        QCOMPARE(menuVisible(window, QStringLiteral("&Program")), false);
        QCOMPARE(menuVisible(window, QStringLiteral("S&cope")), false);
        QVERIFY2(!window.connection().isConnected(), "one family on the port at a time");
        QTRY_VERIFY_WITH_TIMEOUT(probe->isConnected(), kTimeoutMs);
        probe->write("\r");
        QTRY_VERIFY2_WITH_TIMEOUT(probe->received.contains('}'), probe->received.constData(), kTimeoutMs);
        QTRY_COMPARE(labelText(window, "linkLabel"), QStringLiteral("Probe on PMC-960"));
        // The shared terminal says where what follows comes from, after the BDS5's text.
        const QString shown = window.terminal()->text();
        const qsizetype bds5 = shown.lastIndexOf(QStringLiteral("Connected to Simulated BDS5"));
        QVERIFY2(bds5 >= 0, qPrintable(shown));
        QVERIFY2(shown.indexOf(QStringLiteral("Connecting to Simulated PMC-960, 9600 baud"), bds5) > bds5, qPrintable(shown));

        window.connectDrive(ConnectionChoice::simulator());
        QCOMPARE(window.activeFamily(), DriveFamily::Bds5);
        QVERIFY(!probe->isConnected());
        QCOMPARE(menuVisible(window, QStringLiteral("&Program")), true);
        QCOMPARE(menuVisible(window, QStringLiteral("&Probe")), false);
        QTRY_VERIFY_WITH_TIMEOUT(bds5Ready(window), kTimeoutMs);
    }

    // Issue 19: what the BDS5 still had on its way when the user switched to the SC750 stays out of the
    // terminal. (The setup wizard's BDS5 Modes page reads "P PL PROP TQ GEAR EXTLOOP RAMP ROTARY ZERO" without
    // showing it; the tail of that echo, queued before the link closed, was delivered after and shown: " RAMP".)
    void aLateBds5AnswerStaysOutOfTheTerminal() {
        app::MainWindow window;
        window.connectDrive(ConnectionChoice::simulator());
        window.show();
        QTRY_VERIFY_WITH_TIMEOUT(bds5Ready(window), kTimeoutMs);
        // The answer streams in at 9600 baud, about a character a millisecond. Once its first bytes are in, the
        // switch comes from the event loop, as a click would; what the drive sends meanwhile is still queued.
        std::optional<QSignalSpy> late;
        bool switched = false;
        auto first = std::make_shared<QMetaObject::Connection>();
        *first = connect(&window.connection(), &app::DriveConnection::rawReceived, &window, [&, first] {
            disconnect(*first);
            QTimer::singleShot(0, &window, [&] {
                window.connectDrive(ConnectionChoice::simulator(DriveFamily::Sc750));
                late.emplace(&window.connection(), &app::DriveConnection::rawReceived);
                switched = true;
            });
        });
        window.connection().session()->send(QStringLiteral("P PL PROP TQ GEAR EXTLOOP RAMP ROTARY ZERO"),
                                            serialport::Bds5Session::Echo::Quiet);
        QTRY_VERIFY_WITH_TIMEOUT(switched, kTimeoutMs);
        // Long after anything queued before the switch: the SC750 has answered the version query.
        const auto* sc750 = static_cast<const app::Sc750Workspace*>(window.workspace(DriveFamily::Sc750));
        QTRY_VERIFY_WITH_TIMEOUT(sc750->statusText().contains(QStringLiteral("SC75")), kTimeoutMs);
        QCOMPARE(late->count(), 0); // nothing from the closed BDS5 link
        const QString shown = window.terminal()->text();
        for (const char* word : {"PROP", "EXTLOOP", "RAMP", "ROTARY", "ZERO"})
            QVERIFY2(!shown.contains(QLatin1String(word)), qPrintable(shown));
    }

    void theFamilyIsRememberedAndChosenInTheDialog() {
        QSettings settings;
        ConnectionChoice chosen = ConnectionChoice::serialPort(QStringLiteral("/dev/ttyUSB0"), 9600);
        chosen.family = DriveFamily::Sc750;
        chosen.save(settings);
        QCOMPARE(ConnectionChoice::load(settings), chosen);
        settings.setValue(QStringLiteral("connection/family"), QStringLiteral("no such drive"));
        QCOMPARE(ConnectionChoice::load(settings).family, DriveFamily::Bds5);

        app::ConnectionDialog dialog;
        dialog.setChoice(ConnectionChoice::simulator(DriveFamily::Pmc960));
        auto* combo = dialog.findChild<QComboBox*>(QStringLiteral("familyCombo"));
        QVERIFY(combo);
        QVERIFY(combo->currentText().contains(QStringLiteral("PMC-960")));
        // The line's settings as the link will open them: RTS/CTS for the PMC-960, three wires for the others.
        auto* line = dialog.findChild<QLabel*>(QStringLiteral("lineNote"));
        QVERIFY(line);
        QVERIFY2(line->text().contains(QStringLiteral("RTS/CTS")), qPrintable(line->text()));
        combo->setCurrentIndex(combo->findData(int(DriveFamily::Sc750)));
        QCOMPARE(dialog.choice().family, DriveFamily::Sc750);
        QVERIFY2(line->text().contains(QStringLiteral("no flow control")), qPrintable(line->text()));
    }

    void theCommandLineChoosesTheFamily() {
        const auto options = app::parseCommandLine({QStringLiteral("servodesk"), QStringLiteral("--drive"),
                                                    QStringLiteral("pmc960")});
        QVERIFY(options);
        QCOMPARE(options->connection.family, DriveFamily::Pmc960);
        QVERIFY(!app::parseCommandLine({QStringLiteral("servodesk"), QStringLiteral("--drive"),
                                        QStringLiteral("bds6")}));
    }

    // `servodesk FILE...` (the desktop entry's Exec=servodesk %F): the files are kept to open, and without
    // --drive the first program's extension chooses the family; --drive still wins.
    void filesOnTheCommandLineChooseTheFamily() {
        const QString exe = QStringLiteral("servodesk");
        auto sc750 = app::parseCommandLine({exe, QStringLiteral("notes.txt"), QStringLiteral("/m/AXIS1.BAS")});
        QVERIFY(sc750);
        QCOMPARE(sc750->files, (QStringList{QStringLiteral("notes.txt"), QStringLiteral("/m/AXIS1.BAS")}));
        QCOMPARE(sc750->connection.family, DriveFamily::Sc750);
        QCOMPARE(app::parseCommandLine({exe, QStringLiteral("cut.mpl")})->connection.family, DriveFamily::Pmc960);
        QCOMPARE(app::parseCommandLine({exe, QStringLiteral("A.BDS"), QStringLiteral("B.BAS")})->connection.family,
                 DriveFamily::Bds5);
        QCOMPARE(app::parseCommandLine({exe, QStringLiteral("--drive"), QStringLiteral("bds5"), QStringLiteral("B.BAS")})
                     ->connection.family,
                 DriveFamily::Bds5);
        QVERIFY(app::parseCommandLine({exe})->files.isEmpty());
    }
};

QTEST_MAIN(FamilySwitchTest)
#include "family_switch_test.moc"
