// HelpBrowser: list, search and pages.
#include "help_browser.h"

#include "family_topics.h"

#include "app/drive/connection_choice.h"

#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QMainWindow>
#include <QSplitter>
#include <QTextBrowser>
#include <QTreeWidget>
#include <QVBoxLayout>

namespace app {

namespace {
constexpr int kIndexRole = Qt::UserRole; // the topic's index in FamilyTopics::of(family)
} // namespace

const ReferenceTopic& HelpBrowser::topicOf(const QTreeWidgetItem* item) const {
    return m_topics->at(item->data(0, kIndexRole).toInt());
}

void HelpBrowser::setFamily(drive_core::DriveFamily family) {
    if (family == m_family) return;
    m_family = family;
    m_topics = &FamilyTopics::of(family);
    setWindowTitle(tr("%1 Reference").arg(ConnectionChoice::familyName(family)));
    m_search->blockSignals(true);
    m_search->clear();
    m_search->blockSignals(false);
    m_list->clear();
    fill();
    m_currentKey.clear();
    if (m_list->topLevelItemCount() > 0) { // the family's introduction page comes first
        m_list->setCurrentItem(m_list->topLevelItem(0));
        select(m_list->currentItem());
    }
}

HelpBrowser::HelpBrowser(QWidget* parent)
    : QDockWidget(tr("BDS5 Reference"), parent), m_search(new QLineEdit), m_list(new QTreeWidget),
      m_page(new QTextBrowser), m_count(new QLabel), m_topics(&ReferenceTopics::all()) {
    setObjectName(QStringLiteral("helpBrowser"));
    m_search->setObjectName(QStringLiteral("helpSearch"));
    m_search->setPlaceholderText(tr("Search commands, variables, errors..."));
    m_search->setClearButtonEnabled(true);
    m_list->setObjectName(QStringLiteral("helpTopics"));
    m_list->setHeaderHidden(true);
    m_list->setUniformRowHeights(true);
    m_page->setObjectName(QStringLiteral("helpPage"));
    m_page->setOpenLinks(false);
    m_count->setContentsMargins(2, 0, 2, 0);

    auto* left = new QWidget;
    auto* leftLayout = new QVBoxLayout(left);
    leftLayout->setContentsMargins(0, 0, 0, 0);
    leftLayout->addWidget(m_search);
    leftLayout->addWidget(m_list);
    leftLayout->addWidget(m_count);
    m_splitter = new QSplitter(Qt::Horizontal);
    m_splitter->addWidget(left);
    m_splitter->addWidget(m_page);
    m_splitter->setStretchFactor(0, 2);
    m_splitter->setStretchFactor(1, 3);
    setWidget(m_splitter);
    connect(this, &QDockWidget::topLevelChanged, this, &HelpBrowser::fitLayout);
    connect(this, &QDockWidget::dockLocationChanged, this, &HelpBrowser::fitLayout);

    fill();
    connect(m_search, &QLineEdit::textChanged, this, &HelpBrowser::filter);
    connect(m_list, &QTreeWidget::currentItemChanged, this, [this](QTreeWidgetItem* item) { select(item); });
    showTopic(QStringLiteral("intro"));
}

void HelpBrowser::fill() {
    QTreeWidgetItem* groups[4] = {};
    const QStringList names = FamilyTopics::groupNames(m_family);
    const QList<ReferenceTopic>& topics = *m_topics;
    for (int index = 0; index < topics.size(); ++index) {
        const ReferenceTopic& topic = topics[index];
        const int g = int(topic.kind);
        if (topic.kind == ReferenceTopic::Kind::Page) {
            auto* item = new QTreeWidgetItem(m_list, {topic.title});
            item->setData(0, kIndexRole, index);
            continue;
        }
        if (!groups[g]) {
            groups[g] = new QTreeWidgetItem(m_list, {names[g]});
            groups[g]->setFlags(Qt::ItemIsEnabled);
            QFont bold = groups[g]->font(0);
            bold.setBold(true);
            groups[g]->setFont(0, bold);
        }
        auto* item = new QTreeWidgetItem(groups[g], {topic.title});
        item->setData(0, kIndexRole, index);
        item->setToolTip(0, topic.summary.left(200));
    }
    filter(QString());
}

void HelpBrowser::filter(const QString& text) {
    int shown = 0;
    for (int g = 0; g < m_list->topLevelItemCount(); ++g) {
        QTreeWidgetItem* group = m_list->topLevelItem(g);
        int inGroup = 0;
        for (int i = 0; i < group->childCount(); ++i) {
            QTreeWidgetItem* item = group->child(i);
            const bool match = ReferenceTopics::matches(topicOf(item), text);
            item->setHidden(!match);
            inGroup += match;
        }
        if (group->childCount() > 0) {
            group->setHidden(inGroup == 0);
            group->setExpanded(!text.trimmed().isEmpty());
            group->setText(0, group->text(0).section(QLatin1String(" ("), 0, 0) + QStringLiteral(" (%1)").arg(inGroup));
        }
        shown += inGroup;
    }
    m_count->setText(tr("%n topic(s)", nullptr, shown));
}

int HelpBrowser::visibleTopicCount() const {
    int shown = 0;
    for (int g = 0; g < m_list->topLevelItemCount(); ++g) {
        const QTreeWidgetItem* group = m_list->topLevelItem(g);
        for (int i = 0; i < group->childCount(); ++i) shown += !group->child(i)->isHidden();
    }
    return shown;
}

void HelpBrowser::setSearch(const QString& text) {
    m_search->setText(text);
}

void HelpBrowser::placeFirstTime() {
    if (std::exchange(m_placed, true) || !parentWidget()) return;
    // chosen: a reference is read beside the program, not squeezed into a side dock.
    setFloating(true);
    const QRect over = parentWidget()->geometry();
    const QSize size(std::min(960, over.width() - 80), std::min(620, over.height() - 80));
    setGeometry(QRect(over.center() - QPoint(size.width() / 2, size.height() / 2), size));
}

void HelpBrowser::fitLayout() {
    // Side by side when there is room (floating, or docked at the top or bottom), stacked in a side dock.
    const auto* window = qobject_cast<QMainWindow*>(parentWidget());
    const Qt::DockWidgetArea area = window ? window->dockWidgetArea(this) : Qt::NoDockWidgetArea;
    const bool side = !isFloating() && (area == Qt::LeftDockWidgetArea || area == Qt::RightDockWidgetArea);
    m_splitter->setOrientation(side ? Qt::Vertical : Qt::Horizontal);
}

bool HelpBrowser::showTopic(const QString& name) {
    if (isHidden()) placeFirstTime();
    show();
    raise();
    const auto topic = FamilyTopics::find(m_family, name);
    if (!topic) {
        setSearch(name);
        m_page->setHtml(tr("<p>The %1 has no command, variable or error <b>%2</b>. Topics that mention it "
                           "are listed on the left.</p>")
                            .arg(ConnectionChoice::familyName(m_family), name.toHtmlEscaped()));
        m_currentKey.clear();
        return false;
    }
    if (!ReferenceTopics::matches(*topic, m_search->text())) m_search->clear();
    for (QTreeWidgetItemIterator it(m_list); *it; ++it) {
        const QVariant index = (*it)->data(0, kIndexRole);
        if (!index.isNull() && topicOf(*it).key == topic->key && topicOf(*it).kind == topic->kind) {
            if ((*it)->parent()) (*it)->parent()->setExpanded(true);
            m_list->setCurrentItem(*it);
            m_list->scrollToItem(*it);
            break;
        }
    }
    select(m_list->currentItem());
    return true;
}

void HelpBrowser::select(QTreeWidgetItem* item) {
    if (!item || item->data(0, kIndexRole).isNull()) return;
    const ReferenceTopic& topic = topicOf(item);
    m_currentKey = topic.key;
    m_page->setHtml(FamilyTopics::html(topic));
}

QString HelpBrowser::pageText() const {
    return m_page->toPlainText();
}

} // namespace app
