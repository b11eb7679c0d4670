// VariablesDock: views over VariableModel, wired to VariableSync.
#include "variables_dock.h"

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

VariablesDock::VariablesDock(DriveConnection& connection, QWidget* parent)
    : QDockWidget(tr("Variables"), parent), m_model(new VariableModel(this)),
      m_sync(new VariableSync(connection, *m_model, this)), m_allProxy(new QSortFilterProxyModel(this)),
      m_watchProxy(new QSortFilterProxyModel(this)) {
    setObjectName(QStringLiteral("variablesDock"));
    m_allProxy->setSourceModel(m_model);
    m_allProxy->setRecursiveFilteringEnabled(true);
    m_allProxy->setFilterKeyColumn(-1);
    m_allProxy->setFilterCaseSensitivity(Qt::CaseInsensitive);
    m_watchProxy->setSourceModel(m_model);
    m_watchProxy->setRecursiveFilteringEnabled(true);
    m_watchProxy->setFilterRole(VariableModel::PinnedRole);
    m_watchProxy->setFilterFixedString(QStringLiteral("pinned"));

    auto* body = new QWidget(this);
    auto* layout = new QVBoxLayout(body);
    layout->setContentsMargins(4, 4, 4, 4);
    auto* bar = new QHBoxLayout;
    m_search = new QLineEdit(body);
    m_search->setPlaceholderText(tr("Search names and descriptions"));
    m_search->setClearButtonEnabled(true);
    m_live = new QCheckBox(tr("Live"), body);
    m_live->setChecked(true);
    m_live->setToolTip(tr("Read the values in view from the drive, paced to the link"));
    auto* copy = new QPushButton(tr("Copy as .VAR"), body);
    bar->addWidget(m_search, 1);
    bar->addWidget(m_live);
    bar->addWidget(copy);
    layout->addLayout(bar);
    m_tabs = new QTabWidget(body);
    m_allView = makeView(m_allProxy);
    m_watchView = makeView(m_watchProxy);
    m_tabs->addTab(m_allView, tr("All"));
    m_tabs->addTab(m_watchView, tr("Watch"));
    layout->addWidget(m_tabs, 1);
    m_status = new QLabel(body);
    m_status->setWordWrap(true);
    m_status->setObjectName(QStringLiteral("variablesStatus"));
    m_pause = new QLabel(body);
    m_pause->setStyleSheet(QStringLiteral("color:#5f6368"));
    layout->addWidget(m_status);
    layout->addWidget(m_pause);
    setWidget(body);

    connect(m_search, &QLineEdit::textChanged, this, &VariablesDock::applyFilter);
    connect(m_live, &QCheckBox::toggled, m_sync, &VariableSync::setLive);
    connect(copy, &QPushButton::clicked, this, &VariablesDock::copyAsVar);
    connect(m_model, &VariableModel::editRequested, m_sync, &VariableSync::write);
    connect(m_model, &VariableModel::editRefused, this,
            [this](const QString&, const QString& message) { setStatus(message, true); });
    connect(m_sync, &VariableSync::writeFinished, this,
            [this](const QString&, bool accepted, const QString& message) { setStatus(message, !accepted); });
    connect(m_sync, &VariableSync::pauseReasonChanged, m_pause, &QLabel::setText);
    m_sync->setWanted([this] { return isVisible() ? visibleNames() : QStringList(); });
    auto* fade = new QTimer(this);
    connect(fade, &QTimer::timeout, m_model, &VariableModel::clearChanged);
    fade->start(kHighlightMs);
}

QTreeView* VariablesDock::makeView(QSortFilterProxyModel* proxy) {
    auto* view = new QTreeView(this);
    view->setModel(proxy);
    view->setUniformRowHeights(true);
    view->setAlternatingRowColors(true);
    view->setSelectionMode(QAbstractItemView::ExtendedSelection);
    view->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed);
    view->setContextMenuPolicy(Qt::CustomContextMenu);
    view->header()->setStretchLastSection(true);
    view->setColumnWidth(VariableModel::Name, 150);
    view->setColumnWidth(VariableModel::Value, 90);
    view->setColumnWidth(VariableModel::Unit, 60);
    view->setColumnWidth(VariableModel::Limits, 150);
    view->setColumnWidth(VariableModel::Condition, 100);
    view->expandAll();
    connect(view, &QWidget::customContextMenuRequested, this,
            [this, view](const QPoint& at) { showContextMenu(view, at); });
    connect(proxy, &QAbstractItemModel::rowsInserted, view, [view] { view->expandAll(); });
    connect(proxy, &QAbstractItemModel::layoutChanged, view, [view] { view->expandAll(); });
    return view;
}

void VariablesDock::applyFilter(const QString& text) {
    m_allProxy->setFilterFixedString(text);
    m_allView->expandAll();
}

QStringList VariablesDock::visibleNames() const {
    auto* view = qobject_cast<QTreeView*>(m_tabs->currentWidget());
    QStringList names;
    if (!view) return names;
    const QRect area = view->viewport()->rect();
    for (QModelIndex at = view->indexAt(QPoint(1, 1)); at.isValid(); at = view->indexBelow(at)) {
        if (view->visualRect(at).top() > area.bottom()) break;
        const QString name = at.data(VariableModel::NameRole).toString();
        if (!name.isEmpty()) names << name;
    }
    for (const QString& name : m_model->pinned()) // the watch list is always live
        if (!names.contains(name)) names << name;
    // The user units scale every limit shown, and ACTIVE decides what may be written: read them too.
    for (const char* unit :
         {"PNUM", "PDEN", "VNUM", "VDEN", "ANUM", "ADEN", "INUM", "IDEN", "PXNUM", "PXDEN", "VXNUM", "VXDEN"})
        if (const QString name = QString::fromLatin1(unit); m_model->value(name).isEmpty() && !names.contains(name))
            names << name;
    if (!names.contains(QStringLiteral("ACTIVE"))) names << QStringLiteral("ACTIVE");
    return names;
}

void VariablesDock::showContextMenu(QTreeView* view, const QPoint& at) {
    const QString name = view->indexAt(at).data(VariableModel::NameRole).toString();
    QMenu menu(this);
    if (!name.isEmpty()) {
        const bool pinned = m_model->isPinned(name);
        menu.addAction(pinned ? tr("Remove %1 from Watch").arg(name) : tr("Watch %1").arg(name), this,
                       [this, name, pinned] { m_model->setPinned(name, !pinned); });
        menu.addAction(tr("Read %1 now").arg(name), this, [this, name] { m_sync->readNow({name}); });
        menu.addAction(tr("Edit %1").arg(name), this,
                       [view, at] { view->edit(view->indexAt(at).siblingAtColumn(VariableModel::Value)); });
    }
    menu.addAction(tr("Copy as .VAR"), this, &VariablesDock::copyAsVar);
    menu.exec(view->viewport()->mapToGlobal(at));
}

QString VariablesDock::selectionAsVar() const {
    auto* view = qobject_cast<QTreeView*>(m_tabs->currentWidget());
    QStringList names;
    if (view)
        for (const QModelIndex& index : view->selectionModel()->selectedRows())
            if (const QString name = index.data(VariableModel::NameRole).toString(); !name.isEmpty()) names << name;
    if (names.isEmpty()) names = m_model->pinned();
    return m_model->varLines(names);
}

void VariablesDock::copyAsVar() {
    const QString lines = selectionAsVar();
    QApplication::clipboard()->setText(lines);
    setStatus(lines.isEmpty() ? tr("Nothing to copy: select variables that have a value")
                              : tr("Copied %n line(s) as .VAR", nullptr, int(lines.count(QLatin1Char('\n')))),
              false);
}

void VariablesDock::editValue(const QString& name, const QString& text) {
    m_model->setData(m_model->indexOf(name, VariableModel::Value), text, Qt::EditRole);
}

void VariablesDock::reveal(const QString& name) {
    const QModelIndex index = m_allProxy->mapFromSource(m_model->indexOf(name));
    m_tabs->setCurrentWidget(m_allView);
    m_allView->scrollTo(index, QAbstractItemView::PositionAtTop);
    m_allView->setCurrentIndex(index);
}

void VariablesDock::showWatchList(bool watch) {
    m_tabs->setCurrentWidget(watch ? m_watchView : m_allView);
}

QString VariablesDock::statusText() const {
    return m_status->text();
}

void VariablesDock::setStatus(const QString& text, bool problem) {
    m_status->setStyleSheet(problem ? QStringLiteral("color:#b3261e") : QStringLiteral("color:#1e8e3e"));
    m_status->setText(text);
}

} // namespace app
