// CaptureDock: the capture view and its actions.
#include "capture_dock.h"

#include "capture_log.h"

#include <QAction>
#include <QComboBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFontDatabase>
#include <QLabel>
#include <QLocale>
#include <QMenu>
#include <QPlainTextEdit>
#include <QScrollBar>
#include <QStyle>
#include <QTimer>
#include <QToolBar>
#include <QVBoxLayout>

namespace app {

namespace {
constexpr int kRefreshMs = 200; // coalesce redraws while bytes stream in
const QString kFilter = QObject::tr("Capture files (*.cap *.CAP);;All files (*)");

// The .CAP text as a terminal would show it: CR LF and LF end lines, other control characters dropped.
QString capText(const QByteArray& bytes) {
    QString text;
    text.reserve(bytes.size());
    for (const char byte : bytes) {
        const auto c = uchar(byte);
        if (c == '\n' || c == '\t' || (c >= 0x20 && c != 0x7f)) text += QChar(char16_t(c));
    }
    return text;
}
} // namespace

CaptureDock::CaptureDock(CaptureLog& log, QWidget* parent)
    : QDockWidget(tr("Capture"), parent), m_log(log), m_viewChoice(new QComboBox),
      m_text(new QPlainTextEdit), m_size(new QLabel), m_refresh(new QTimer(this)) {
    setObjectName(QStringLiteral("captureDock"));
    QStyle* s = style();
    m_start = new QAction(s->standardIcon(QStyle::SP_MediaPlay), tr("&Start Capture"), this);
    m_start->setToolTip(tr("Clear the capture and start logging everything sent to and received from the drive"));
    m_stop = new QAction(s->standardIcon(QStyle::SP_MediaStop), tr("S&top Capture"), this);
    m_clear = new QAction(s->standardIcon(QStyle::SP_DialogResetButton), tr("C&lear"), this);
    m_open = new QAction(s->standardIcon(QStyle::SP_DialogOpenButton), tr("&Open .CAP..."), this);
    m_save = new QAction(s->standardIcon(QStyle::SP_DialogSaveButton), tr("Save .CAP &As..."), this);
    connect(m_start, &QAction::triggered, &m_log, &CaptureLog::start);
    connect(m_stop, &QAction::triggered, &m_log, &CaptureLog::stop);
    connect(m_clear, &QAction::triggered, &m_log, &CaptureLog::clear);
    connect(m_open, &QAction::triggered, this, &CaptureDock::openCap);
    connect(m_save, &QAction::triggered, this, &CaptureDock::saveCapAs);

    auto* bar = new QToolBar;
    bar->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    bar->addActions({m_start, m_stop, m_clear});
    bar->addSeparator();
    bar->addActions({m_open, m_save});
    bar->addSeparator();
    m_viewChoice->setObjectName(QStringLiteral("captureView"));
    m_viewChoice->addItem(tr("Text as saved (.CAP)"));
    m_viewChoice->addItem(tr("Both directions, timed"));
    bar->addWidget(m_viewChoice);

    m_text->setObjectName(QStringLiteral("captureText"));
    m_text->setReadOnly(true);
    m_text->setLineWrapMode(QPlainTextEdit::NoWrap);
    m_text->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    m_size->setObjectName(QStringLiteral("captureSize"));
    m_size->setContentsMargins(4, 2, 4, 2);

    auto* body = new QWidget;
    auto* layout = new QVBoxLayout(body);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(2);
    layout->addWidget(bar);
    layout->addWidget(m_text);
    layout->addWidget(m_size);
    setWidget(body);

    m_refresh->setSingleShot(true);
    m_refresh->setInterval(kRefreshMs);
    connect(m_refresh, &QTimer::timeout, this, &CaptureDock::refresh);
    connect(&m_log, &CaptureLog::changed, this, &CaptureDock::scheduleRefresh);
    connect(&m_log, &CaptureLog::capturingChanged, this, &CaptureDock::updateActions);
    connect(m_viewChoice, &QComboBox::currentIndexChanged, this, &CaptureDock::refresh);
    connect(this, &QDockWidget::visibilityChanged, this, [this](bool visible) {
        if (visible) refresh();
    });
    updateActions();
    refresh();
}

void CaptureDock::setView(View view) {
    m_viewChoice->setCurrentIndex(view == View::AsSaved ? 0 : 1);
}

void CaptureDock::addToMenu(QMenu* menu) {
    menu->addActions({m_start, m_stop, m_clear});
    menu->addSeparator();
    QAction* show = toggleViewAction();
    show->setText(tr("&View Capture"));
    menu->addAction(show);
    menu->addActions({m_open, m_save});
}

QString CaptureDock::shownText() const {
    return m_text->toPlainText();
}

QString CaptureDock::sizeText() const {
    return m_size->text();
}

void CaptureDock::scheduleRefresh() {
    if (!m_refresh->isActive()) m_refresh->start();
}

void CaptureDock::refresh() {
    m_refresh->stop();
    const QLocale locale;
    m_size->setText(tr("%1%2 bytes received, %3 sent (kept in full: no 16 KB limit as in Motion Link)")
                        .arg(m_log.isCapturing() ? tr("Capturing \u2014 ") : QString())
                        .arg(locale.toString(m_log.receivedBytes()))
                        .arg(locale.toString(m_log.sentBytes())));
    if (!isVisible()) return; // redrawn when shown
    QScrollBar* bar = m_text->verticalScrollBar();
    const bool followTail = bar->value() >= bar->maximum() - 1;
    m_text->setPlainText(m_viewChoice->currentIndex() == 0 ? capText(m_log.capBytes()) : m_log.transcript());
    if (followTail) bar->setValue(bar->maximum());
}

void CaptureDock::updateActions() {
    m_start->setEnabled(!m_log.isCapturing());
    m_stop->setEnabled(m_log.isCapturing());
    scheduleRefresh();
}

void CaptureDock::openCap() {
    auto* dialog = new QFileDialog(this, tr("Open Capture"), QString(), kFilter);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->setAcceptMode(QFileDialog::AcceptOpen);
    dialog->setFileMode(QFileDialog::ExistingFile);
    connect(dialog, &QFileDialog::fileSelected, this, [this](const QString& path) {
        const QString error = m_log.loadCap(path);
        m_size->setText(error.isEmpty() ? m_size->text() : error);
        if (error.isEmpty()) setWindowTitle(tr("Capture \u2014 %1").arg(QFileInfo(path).fileName()));
    });
    dialog->open();
}

void CaptureDock::saveCapAs() {
    auto* dialog = new QFileDialog(this, tr("Save Capture"), QStringLiteral("capture.cap"), kFilter);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->setAcceptMode(QFileDialog::AcceptSave);
    dialog->setDefaultSuffix(QStringLiteral("cap"));
    connect(dialog, &QFileDialog::fileSelected, this, [this](const QString& path) {
        const QString error = m_log.saveCap(path);
        if (!error.isEmpty()) m_size->setText(error);
        else setWindowTitle(tr("Capture \u2014 %1").arg(QFileInfo(path).fileName()));
    });
    dialog->open();
}

} // namespace app
