// Sc750VariableBrowser: the catalog tree, its live G reads and its checked P writes.
#include "sc750_variable_browser.h"

#include "sc750_debugger.h"
#include "sc750_variable_groups.h"
#include "sc750_workspace.h"
#include "theme.h"

#include "drive_core/catalog/sc750_catalog.h"
#include "serialport/sc750_session.h"

#include <QCheckBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QTreeWidget>
#include <QVBoxLayout>

namespace app {

namespace catalog = drive_core::catalog::sc750;

namespace {
constexpr int kInfoRole = Qt::UserRole + 1;    // the row's catalog index
constexpr int kChangedRole = Qt::UserRole + 2; // the value differs from the read before
const QColor kChanged(0xff, 0xf4, 0xce);

QString text(std::string_view s) {
    return QString::fromUtf8(s.data(), qsizetype(s.size()));
}

const catalog::VariableInfo& infoOf(const QTreeWidgetItem* item) {
    return catalog::variables()[std::size_t(item->data(Sc750VariableBrowser::NameColumn, kInfoRole).toInt())];
}

QString accessText(catalog::Access access) {
    switch (access) {
    case catalog::Access::ReadWrite: return QObject::tr("read/write");
    case catalog::Access::ReadOnly: return QObject::tr("read only");
    case catalog::Access::Parameter: return QObject::tr("parameter (NV)");
    }
    return {};
}
} // namespace

Sc750VariableBrowser::Sc750VariableBrowser(Sc750Workspace& workspace, QWidget* parent)
    : QWidget(parent), m_workspace(workspace), m_filter(new QLineEdit(this)), m_live(new QCheckBox(tr("&Live"), this)),
      m_tree(new QTreeWidget(this)), m_message(new QLabel(this)) {
    setObjectName(QStringLiteral("sc750VariableBrowser"));
    m_filter->setPlaceholderText(tr("Search variables by name or description"));
    m_filter->setClearButtonEnabled(true);
    m_live->setChecked(true);
    m_live->setToolTip(tr("Read the rows in view again and again with G frames"));
    auto* top = new QHBoxLayout;
    top->addWidget(m_filter, 1);
    top->addWidget(m_live);
    m_tree->setColumnCount(ColumnCount);
    m_tree->setHeaderLabels({tr("Name"), tr("Value"), tr("Unit"), tr("Range"), tr("Access"), tr("Description")});
    m_tree->setAlternatingRowColors(true);
    m_tree->setUniformRowHeights(true);
    m_tree->setEditTriggers(QAbstractItemView::NoEditTriggers); // the Value column only, on double-click
    m_tree->setContextMenuPolicy(Qt::CustomContextMenu);
    m_message->setWordWrap(true);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 4, 0, 0);
    layout->addLayout(top);
    layout->addWidget(m_tree, 1);
    layout->addWidget(m_message);

    QHash<QString, QTreeWidgetItem*> groups;
    for (const QString& title : sc750VariableGroups()) {
        auto* group = new QTreeWidgetItem(m_tree, {title});
        QFont bold = group->font(0);
        bold.setBold(true);
        group->setFont(0, bold);
        group->setFirstColumnSpanned(true);
        groups.insert(title, group);
    }
    m_filling = true;
    const auto all = catalog::variables();
    for (std::size_t i = 0; i < all.size(); ++i) {
        const catalog::VariableInfo& v = all[i];
        auto* item = new QTreeWidgetItem(
            groups.value(sc750VariableGroup(v)),
            {text(v.name), QString(), text(v.units), sc750RangeText(v), accessText(v.access), text(v.description)});
        item->setData(NameColumn, kInfoRole, int(i));
        item->setTextAlignment(ValueColumn, Qt::AlignRight | Qt::AlignVCenter);
        item->setToolTip(DescriptionColumn,
                         tr("%1 (%2)%3")
                             .arg(text(v.description), text(v.manualLines),
                                  v.chosen ? tr("; range chosen: the manual gives none") : QString()));
        if (v.access != catalog::Access::ReadOnly) item->setFlags(item->flags() | Qt::ItemIsEditable);
        m_items.insert(text(v.name), item);
    }
    m_filling = false;
    for (QTreeWidgetItem* group : groups) {
        if (group->childCount() == 0)
            delete group; // "Other" when every variable has its group
        else
            group->setExpanded(true);
    }
    m_tree->header()->setSectionResizeMode(QHeaderView::Interactive);
    m_tree->header()->setStretchLastSection(true);
    m_tree->resizeColumnToContents(NameColumn);
    m_tree->setColumnWidth(ValueColumn, 90);
    m_tree->resizeColumnToContents(UnitColumn);
    m_tree->resizeColumnToContents(RangeColumn);
    m_tree->resizeColumnToContents(AccessColumn);
    showMessage(tr("Double-click a value to change it; the SC750 takes changes while no program executes."), false);

    connect(m_filter, &QLineEdit::textChanged, this, &Sc750VariableBrowser::setFilter);
    connect(m_live, &QCheckBox::toggled, this, &Sc750VariableBrowser::setLive);
    connect(m_tree, &QTreeWidget::itemDoubleClicked, this, [this](QTreeWidgetItem* item, int) {
        if (item->parent() && (item->flags() & Qt::ItemIsEditable)) m_tree->editItem(item, ValueColumn);
    });
    connect(m_tree, &QTreeWidget::itemChanged, this, [this](QTreeWidgetItem* item, int column) {
        if (m_filling || column != ValueColumn || !item->parent()) return;
        if (!writeValue(item->text(NameColumn), item->text(ValueColumn))) read(item); // put the controller's back
    });
    connect(m_tree, &QTreeWidget::customContextMenuRequested, this, &Sc750VariableBrowser::showContextMenu);
    m_tick.setInterval(kTickMs);
    connect(&m_tick, &QTimer::timeout, this, &Sc750VariableBrowser::readNext);
    m_tick.start();
}

QString Sc750VariableBrowser::value(const QString& name) const {
    const QTreeWidgetItem* item = m_items.value(name.toUpper());
    return item ? item->text(ValueColumn) : QString();
}

bool Sc750VariableBrowser::isChanged(const QString& name) const {
    const QTreeWidgetItem* item = m_items.value(name.toUpper());
    return item && item->data(ValueColumn, kChangedRole).toBool();
}

QString Sc750VariableBrowser::message() const {
    return m_message->text();
}

void Sc750VariableBrowser::setLive(bool live) {
    if (m_live->isChecked() != live) m_live->setChecked(live); // comes back here through toggled
}

void Sc750VariableBrowser::setFilter(const QString& wanted) {
    if (m_filter->text() != wanted) return m_filter->setText(wanted); // comes back here through textChanged
    const QString w = wanted.trimmed();
    for (int g = 0; g < m_tree->topLevelItemCount(); ++g) {
        QTreeWidgetItem* group = m_tree->topLevelItem(g);
        int shown = 0;
        for (int i = 0; i < group->childCount(); ++i) {
            QTreeWidgetItem* item = group->child(i);
            const bool match = w.isEmpty() || item->text(NameColumn).contains(w, Qt::CaseInsensitive) ||
                               item->text(DescriptionColumn).contains(w, Qt::CaseInsensitive);
            item->setHidden(!match);
            shown += match;
        }
        group->setHidden(shown == 0);
    }
}

void Sc750VariableBrowser::reveal(const QString& name) {
    if (QTreeWidgetItem* item = m_items.value(name.toUpper())) {
        m_tree->scrollToItem(item, QAbstractItemView::PositionAtCenter);
        m_tree->setCurrentItem(item);
    }
}

// The rows a user can see: expanded, not filtered away, inside the viewport.
QList<QTreeWidgetItem*> Sc750VariableBrowser::rowsInView() const {
    QList<QTreeWidgetItem*> rows;
    const QRect view = m_tree->viewport()->rect();
    for (int g = 0; g < m_tree->topLevelItemCount(); ++g) {
        QTreeWidgetItem* group = m_tree->topLevelItem(g);
        if (group->isHidden() || !group->isExpanded()) continue;
        for (int i = 0; i < group->childCount(); ++i) {
            QTreeWidgetItem* item = group->child(i);
            if (!item->isHidden() && m_tree->visualItemRect(item).intersects(view)) rows << item;
        }
    }
    return rows;
}

void Sc750VariableBrowser::readNext() {
    if (!m_live->isChecked() || m_reading || !isVisible() || !m_workspace.session() ||
        m_workspace.debugger().state() == Sc750Debugger::State::Downloading)
        return;
    const QList<QTreeWidgetItem*> rows = rowsInView();
    if (rows.isEmpty()) return;
    read(rows[m_cursor++ % rows.size()]);
}

void Sc750VariableBrowser::read(QTreeWidgetItem* item) {
    const QString name = item->text(NameColumn);
    m_reading = m_workspace.send(
        'G', name,
        [this, item](const serialport::Sc750Reply& reply) {
            m_reading = false;
            const qsizetype eq = reply.payload.indexOf(QLatin1Char('='));
            setValue(item, eq < 0 ? reply.payload : reply.payload.mid(eq + 1));
        },
        [this, item, name](const QString& why) {
            m_reading = false;
            item->setToolTip(ValueColumn, tr("Not read: %1").arg(why));
        });
}

void Sc750VariableBrowser::setValue(QTreeWidgetItem* item, const QString& value) {
    m_filling = true;
    const QString before = item->text(ValueColumn);
    const bool changed = !before.isEmpty() && before != value;
    if (changed || item->data(ValueColumn, kChangedRole).toBool() != changed) {
        item->setData(ValueColumn, kChangedRole, changed);
        item->setBackground(ValueColumn, changed ? QBrush(kChanged) : QBrush());
    }
    if (before != value) item->setText(ValueColumn, value);
    m_filling = false;
    emit valueRead(item->text(NameColumn), value);
}

bool Sc750VariableBrowser::writeValue(const QString& name, const QString& typed) {
    QTreeWidgetItem* item = m_items.value(name.toUpper());
    if (!item) {
        showMessage(tr("%1 is not a predefined SC750 variable.").arg(name), true);
        return false;
    }
    if (const std::optional<QString> refusal = sc750CheckValue(infoOf(item), typed)) {
        showMessage(*refusal, true);
        return false;
    }
    const QString upper = name.toUpper(), value = typed.trimmed();
    const bool sent = m_workspace.send(
        'P', QStringLiteral("%1=%2").arg(upper, value),
        [this, item, upper](const serialport::Sc750Reply& reply) {
            const QString now = reply.payload.mid(reply.payload.indexOf(QLatin1Char('=')) + 1);
            setValue(item, now);
            showMessage(tr("%1 set to %2.").arg(upper, now), false);
            emit written(upper, true);
        },
        [this, item, upper, value](const QString& why) {
            const bool refused = !why.isEmpty() && why.at(0).isDigit();
            showMessage(tr("The SC750 refused %1 = %2: %3").arg(upper, value, refused ? QLatin1Char('!') + why : why),
                        true);
            read(item); // the row shows what the controller still holds
            emit written(upper, false);
        });
    if (sent) showMessage(tr("Writing %1 = %2\u2026").arg(upper, value), false);
    return sent;
}

void Sc750VariableBrowser::showContextMenu(const QPoint& at) {
    QTreeWidgetItem* item = m_tree->itemAt(at);
    if (!item || !item->parent()) return;
    const QString name = item->text(NameColumn);
    QMenu menu(this);
    menu.addAction(tr("Add \"%1\" to &Watch").arg(name), this, [this, name] { emit watchRequested(name); });
    QAction* edit = menu.addAction(tr("&Edit Value"), this, [this, item] { m_tree->editItem(item, ValueColumn); });
    edit->setEnabled(item->flags() & Qt::ItemIsEditable);
    menu.exec(m_tree->viewport()->mapToGlobal(at));
}

void Sc750VariableBrowser::showMessage(const QString& text, bool error) {
    Theme::showStatus(*m_message, text, error);
}

} // namespace app
