// VariableBrowser: views over VariableModel, wired to VariableSync.
#include "variable_browser.h"

#include "theme.h"
#include "variable_model.h"
#include "variable_sync.h"

#include <QApplication>
#include <QCheckBox>
#include <QClipboard>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QPushButton>
#include <QSortFilterProxyModel>
#include <QTabWidget>
#include <QTimer>
#include <QTreeView>
#include <QVBoxLayout>

namespace app {

namespace {
constexpr int kHighlightMs = 3000; // a changed value stays highlighted about this long
}

VariableBrowser::VariableBrowser(SessionHost host, QWidget* parent)
    : QWidget(parent), m_model(new VariableModel(host.family, this)), m_sync(new VariableSync(host, *m_model, this)),
      m_allProxy(new QSortFilterProxyModel(this)), m_watchProxy(new QSortFilterProxyModel(this)) {
    setObjectName(QStringLiteral("variableBrowser"));
    m_allProxy->setSourceModel(m_model);
    m_allProxy->setRecursiveFilteringEnabled(true);
    m_allProxy->setFilterKeyColumn(-1);
    m_allProxy->setFilterCaseSensitivity(Qt::CaseInsensitive);
    m_watchProxy->setSourceModel(m_model);
    m_watchProxy->setRecursiveFilteringEnabled(true);
    m_watchProxy->setFilterRole(VariableModel::PinnedRole);
    m_watchProxy->setFilterFixedString(QStringLiteral("pinned"));

    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    auto* bar = new QHBoxLayout;
    m_search = new QLineEdit(this);
    m_search->setPlaceholderText(tr("Search names and descriptions"));
    m_search->setClearButtonEnabled(true);
    m_live = new QCheckBox(tr("&Live"), this);
    m_live->setChecked(m_model->rules().liveByDefault());
    m_live->setToolTip(tr("Read the values in view from the drive again and again, paced to the link"));
    m_refresh = new QPushButton(tr("&Refresh"), this);
    m_refresh->setToolTip(tr("Read the values in view and the watch list once, now"));
    m_copy = new QPushButton(tr("Copy as %1").arg(m_model->rules().fileKind()), this);
    m_copy->setToolTip(tr("The selected variables (or the Watch list) as the drive's %1, which Send takes back")
                           .arg(m_model->rules().fileKind()));
    bar->addWidget(m_search, 1);
    bar->addWidget(m_live);
    bar->addWidget(m_refresh);
    bar->addWidget(m_copy);
    layout->addLayout(bar);
    m_tabs = new QTabWidget(this);
    m_allView = makeView(m_allProxy);
    m_watchView = makeView(m_watchProxy);
    m_tabs->addTab(m_allView, tr("All"));
    m_tabs->addTab(m_watchView, tr("Watch"));
    layout->addWidget(m_tabs, 1);
    m_status = new QLabel(this);
    m_status->setWordWrap(true);
    m_status->setObjectName(QStringLiteral("variablesStatus"));
    m_pause = new QLabel(this);
    m_pause->setStyleSheet(QStringLiteral("color:#5f6368"));
    layout->addWidget(m_status);
    layout->addWidget(m_pause);
    m_status->setText(m_model->rules().hint());

    connect(m_search, &QLineEdit::textChanged, this, &VariableBrowser::setFilter);
    connect(m_live, &QCheckBox::toggled, m_sync, &VariableSync::setLive);
    connect(m_copy, &QPushButton::clicked, this, &VariableBrowser::copyAsFile);
    connect(m_refresh, &QPushButton::clicked, this, &VariableBrowser::refresh);
    connect(m_model, &VariableModel::editRequested, m_sync, &VariableSync::write);
    connect(m_model, &VariableModel::editRefused, this,
            [this](const QString&, const QString& message) { setStatus(message, true); });
    connect(m_sync, &VariableSync::writeFinished, this, [this](const QString& name, bool accepted, const QString& message) {
        setStatus(message, !accepted);
        emit written(name, accepted);
    });
    connect(m_sync, &VariableSync::pauseReasonChanged, m_pause, &QLabel::setText);
    m_sync->setWanted([this] { return isVisible() ? visibleNames() : QStringList(); });
    auto* fade = new QTimer(this);
    connect(fade, &QTimer::timeout, m_model, &VariableModel::clearChanged);
    fade->start(kHighlightMs);
}

QTreeView* VariableBrowser::makeView(QSortFilterProxyModel* proxy) {
    auto* view = new QTreeView(this);
    view->setModel(proxy);
    view->setUniformRowHeights(true);
    view->setAlternatingRowColors(true);
    view->setSelectionMode(QAbstractItemView::ExtendedSelection);
    view->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed);
    view->setContextMenuPolicy(Qt::CustomContextMenu);
    view->header()->setStretchLastSection(true);
    view->setColumnWidth(VariableModel::Value, 110);
    view->setColumnWidth(VariableModel::Second, 110);
    view->setColumnHidden(VariableModel::Second, m_model->rules().secondTitle().isEmpty());
    view->setColumnWidth(VariableModel::Unit, 60);
    view->setColumnWidth(VariableModel::Limits, 150);
    view->setColumnWidth(VariableModel::Condition, 100);
    // Groups open, their titles across the row; the names as wide as the longest.
    const auto arrange = [view, proxy] {
        view->expandAll();
        for (int g = 0; g < proxy->rowCount(); ++g) view->setFirstColumnSpanned(g, {}, true);
    };
    arrange();
    view->resizeColumnToContents(VariableModel::Name);
    connect(view, &QWidget::customContextMenuRequested, this,
            [this, view](const QPoint& at) { showContextMenu(view, at); });
    connect(proxy, &QAbstractItemModel::rowsInserted, view, arrange);
    connect(proxy, &QAbstractItemModel::rowsRemoved, view, arrange);
    connect(proxy, &QAbstractItemModel::layoutChanged, view, arrange);
    connect(proxy, &QAbstractItemModel::modelReset, view, arrange);
    return view;
}

void VariableBrowser::setFilter(const QString& text) {
    if (m_search->text() != text) return m_search->setText(text); // comes back here through textChanged
    m_allProxy->setFilterFixedString(text);
}

void VariableBrowser::setLive(bool live) {
    m_live->setChecked(live);
}

void VariableBrowser::refresh() {
    m_sync->readNow(visibleNames());
}

void VariableBrowser::readAll() {
    QStringList names;
    for (int g = 0; g < m_model->rowCount(); ++g) {
        const QModelIndex group = m_model->index(g, 0);
        for (int r = 0; r < m_model->rowCount(group); ++r)
            names << m_model->index(r, 0, group).data(VariableModel::NameRole).toString();
    }
    m_sync->readNow(names);
}

// The rows a user can see, the watch list (always live), and what the family's limits depend on.
QStringList VariableBrowser::visibleNames() const {
    auto* view = qobject_cast<QTreeView*>(m_tabs->currentWidget());
    QStringList names;
    if (!view) return names;
    const QRect area = view->viewport()->rect();
    for (QModelIndex at = view->indexAt(QPoint(1, 1)); at.isValid(); at = view->indexBelow(at)) {
        if (view->visualRect(at).top() > area.bottom()) break;
        const QString name = at.data(VariableModel::NameRole).toString();
        if (!name.isEmpty()) names << name;
    }
    for (const QString& name : m_model->pinned())
        if (!names.contains(name)) names << name;
    for (const QString& name : m_model->rules().alsoRead(m_model->validationContext()))
        if (!names.contains(name)) names << name;
    return names;
}

void VariableBrowser::showContextMenu(QTreeView* view, const QPoint& at) {
    const QString name = view->indexAt(at).data(VariableModel::NameRole).toString();
    QMenu menu(this);
    if (!name.isEmpty()) {
        const bool pinned = m_model->isPinned(name);
        menu.addAction(pinned ? tr("Remove %1 from Watch").arg(name) : tr("Watch %1").arg(name), this,
                       [this, name, pinned] { m_model->setPinned(name, !pinned); });
        if (!m_listAction.isEmpty())
            menu.addAction(m_listAction.arg(name), this, [this, name] { emit listRequested(name); });
        menu.addAction(tr("Read %1 now").arg(name), this, [this, name] { m_sync->readNow({name}); });
        menu.addAction(tr("Edit %1").arg(name), this,
                       [view, at] { view->edit(view->indexAt(at).siblingAtColumn(VariableModel::Value)); });
    }
    menu.addAction(m_copy->text(), this, &VariableBrowser::copyAsFile);
    menu.exec(view->viewport()->mapToGlobal(at));
}

VariableRules::FileText VariableBrowser::selectionAsFile() const {
    auto* view = qobject_cast<QTreeView*>(m_tabs->currentWidget());
    QStringList names;
    if (view)
        for (const QModelIndex& index : view->selectionModel()->selectedRows())
            if (const QString name = index.data(VariableModel::NameRole).toString(); !name.isEmpty()) names << name;
    if (names.isEmpty()) names = m_model->pinned();
    return m_model->rules().fileText(m_model->namedValues(names));
}

void VariableBrowser::copyAsFile() {
    const VariableRules::FileText file = selectionAsFile();
    const QString kind = m_model->rules().fileKind();
    if (file.count == 0) {
        setStatus(tr("Nothing to copy: select variables that have a value and belong in a %1").arg(kind), true);
        return;
    }
    QApplication::clipboard()->setText(file.text);
    setStatus(tr("Copied %n value(s) as %1", nullptr, file.count).arg(kind), false);
}

bool VariableBrowser::editValue(const QString& name, const QString& text) {
    const QModelIndex index = m_model->indexOf(name, VariableModel::Value);
    if (!index.isValid()) {
        setStatus(tr("%1 is not a variable of this drive.").arg(name), true);
        return false;
    }
    const VariableRules::Verdict verdict = m_model->rules().check(name, text, m_model->validationContext());
    m_model->setData(index, text, Qt::EditRole); // checked again there, and sent or refused
    if (verdict.ok) setStatus(tr("Writing %1 = %2\u2026").arg(name.toUpper(), text.trimmed()), false);
    return verdict.ok;
}

QString VariableBrowser::value(const QString& name) const {
    return m_model->value(name);
}

bool VariableBrowser::isChanged(const QString& name) const {
    return m_model->isChanged(name);
}

void VariableBrowser::reveal(const QString& name) {
    const QModelIndex index = m_allProxy->mapFromSource(m_model->indexOf(name));
    m_tabs->setCurrentWidget(m_allView);
    m_allView->scrollTo(index.parent(), QAbstractItemView::PositionAtTop); // its group's title too, where it fits
    m_allView->scrollTo(index, QAbstractItemView::EnsureVisible);
    m_allView->setCurrentIndex(index);
}

void VariableBrowser::showWatchList(bool watch) {
    m_tabs->setCurrentWidget(watch ? m_watchView : m_allView);
}

QString VariableBrowser::statusText() const {
    return m_status->text();
}

void VariableBrowser::setStatus(const QString& text, bool problem) {
    Theme::showStatus(*m_status, text, problem);
}

} // namespace app
