// shotFacts: a walk over each layer's visible widgets, one fact per thing a user can read on them.
#include "shot_facts.h"

#include <Qsci/qsciscintilla.h>
#include <qcustomplot.h>

#include <QAbstractButton>
#include <QCheckBox>
#include <QComboBox>
#include <QDockWidget>
#include <QGroupBox>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QListView>
#include <QPlainTextEdit>
#include <QRadioButton>
#include <QStatusBar>
#include <QTabBar>
#include <QTableView>
#include <QTextBlock>
#include <QTextDocumentFragment>
#include <QTextEdit>
#include <QToolButton>
#include <QTreeView>

namespace app {

namespace {

constexpr int kMaxRows = 40;  // rows of a table, tree or list, from the top of its viewport
constexpr int kMaxLines = 40; // lines of a text view or code editor, from the top of its viewport
constexpr int kMaxChars = 160;

QString withoutMnemonic(QString text) {
    return text.replace(QLatin1String("&&"), QStringLiteral("\x01"))
        .remove(QLatin1Char('&'))
        .replace(QLatin1Char('\x01'), QLatin1Char('&'));
}

QString checkMark(bool checked) {
    return checked ? QStringLiteral("[x] ") : QStringLiteral("[ ] ");
}

class FactWriter {
public:
    explicit FactWriter(const TourShot& shot) : m_shot(shot), m_ratio(shot.picture.devicePixelRatio()) {}

    QStringList facts() const { return m_facts; }

    void layer(const TourShot::Layer& layer) {
        QWidget* root = layer.widget;
        if (!root) return;
        if (root->isWindow()) {
            QString title = root->windowTitle();
            add(QStringLiteral("window"),
                title.replace(QLatin1String("[*]"), root->isWindowModified() ? QStringLiteral("*") : QString()));
        }
        widget(root, layer);
        for (QWidget* child : root->findChildren<QWidget*>()) {
            // Only what this picture shows: shown, inside the grabbed window, not clipped away, not cropped off.
            if (!child->isVisible() || child->window() != root->window() || child->visibleRegion().isEmpty() ||
                !inPicture(child, layer))
                continue;
            widget(child, layer);
        }
    }

private:
    bool inPicture(QWidget* w, const TourShot::Layer& layer) const {
        const QRect logical(QPoint(0, 0), m_shot.picture.deviceIndependentSize().toSize());
        return logical.intersects(QRect(w->mapTo(layer.widget, QPoint(0, 0)) + layer.at, w->size()));
    }

    void add(const QString& kind, const QString& text) {
        for (const QString& line : text.split(QLatin1Char('\n'))) {
            const QString fact = line.simplified().left(kMaxChars);
            if (!fact.isEmpty()) m_facts << kind + QStringLiteral(": ") + fact;
        }
    }

    void widget(QWidget* w, const TourShot::Layer& layer) {
        if (auto* dock = qobject_cast<QDockWidget*>(w)) {
            add(QStringLiteral("dock"), withoutMnemonic(dock->windowTitle()));
        } else if (auto* tabs = qobject_cast<QTabBar*>(w)) {
            QStringList all;
            for (int i = 0; i < tabs->count(); ++i) all << withoutMnemonic(tabs->tabText(i));
            if (tabs->currentIndex() >= 0) add(QStringLiteral("tab"), all.value(tabs->currentIndex()));
            add(QStringLiteral("tabs"), all.join(QStringLiteral(" | ")));
        } else if (auto* label = qobject_cast<QLabel*>(w)) {
            const bool rich = label->textFormat() == Qt::RichText ||
                              (label->textFormat() == Qt::AutoText && Qt::mightBeRichText(label->text()));
            const QString text = rich ? QTextDocumentFragment::fromHtml(label->text()).toPlainText() : label->text();
            add(QStringLiteral("label"), label->buddy() ? withoutMnemonic(text) : text); // '&' underlines then
        } else if (auto* button = qobject_cast<QAbstractButton*>(w)) {
            this->button(button);
        } else if (auto* group = qobject_cast<QGroupBox*>(w)) {
            add(QStringLiteral("group"),
                (group->isCheckable() ? checkMark(group->isChecked()) : QString()) + withoutMnemonic(group->title()));
        } else if (auto* edit = qobject_cast<QLineEdit*>(w)) {
            add(QStringLiteral("edit"), edit->text());
        } else if (auto* combo = qobject_cast<QComboBox*>(w)) {
            add(QStringLiteral("combo"), combo->currentText());
        } else if (auto* status = qobject_cast<QStatusBar*>(w)) {
            add(QStringLiteral("status"), status->currentMessage());
        } else if (auto* plot = qobject_cast<QCustomPlot*>(w)) {
            this->plot(plot, layer);
        } else if (auto* code = qobject_cast<QsciScintilla*>(w)) {
            this->code(code);
        } else if (auto* plain = qobject_cast<QPlainTextEdit*>(w)) {
            text(plain->cursorForPosition(QPoint(0, 0)).block(),
                 plain->cursorForPosition(QPoint(plain->viewport()->width(), plain->viewport()->height())).block());
        } else if (auto* rich = qobject_cast<QTextEdit*>(w)) {
            text(rich->cursorForPosition(QPoint(0, 0)).block(),
                 rich->cursorForPosition(QPoint(rich->viewport()->width(), rich->viewport()->height())).block());
        } else if (auto* view = qobject_cast<QAbstractItemView*>(w); view && !qobject_cast<QHeaderView*>(w)) {
            items(view); // a header is read with its view
        }
    }

    void button(QAbstractButton* button) {
        if (auto* tool = qobject_cast<QToolButton*>(button);
            tool && tool->toolButtonStyle() == Qt::ToolButtonIconOnly && !tool->icon().isNull())
            return; // the text is a tool tip, not on screen
        const QString text = withoutMnemonic(button->text());
        if (text.trimmed().isEmpty()) return;
        if (qobject_cast<QCheckBox*>(button) || qobject_cast<QRadioButton*>(button))
            add(QStringLiteral("check"), checkMark(button->isChecked()) + text);
        else
            add(QStringLiteral("button"), (button->isCheckable() ? checkMark(button->isChecked()) : QString()) + text);
    }

    // The document lines on screen (folds and annotations make screen lines differ), each with its annotation.
    void code(QsciScintilla* code) {
        const long top = code->firstVisibleLine();
        const long screen = code->SendScintilla(QsciScintilla::SCI_LINESONSCREEN);
        const int first = int(code->SendScintilla(QsciScintilla::SCI_DOCLINEFROMVISIBLE, top));
        const int last = int(code->SendScintilla(QsciScintilla::SCI_DOCLINEFROMVISIBLE, top + screen - 1));
        for (int line = first; line <= std::min({last, first + kMaxLines - 1, code->lines() - 1}); ++line) {
            add(QStringLiteral("code"), code->text(line));
            add(QStringLiteral("note"), code->annotation(line));
        }
    }

    void text(QTextBlock block, const QTextBlock& last) {
        for (int n = 0; block.isValid() && n < kMaxLines; block = block.next(), ++n) {
            add(QStringLiteral("text"), block.text());
            if (block == last) break;
        }
    }

    static QString cell(const QModelIndex& index) {
        const QVariant check = index.data(Qt::CheckStateRole);
        const QString mark = check.isValid() ? checkMark(check.toInt() != Qt::Unchecked) : QString();
        return mark + index.data(Qt::DisplayRole).toString().simplified();
    }

    // The header and the rows in view from the top; a list gives one item per row.
    void items(QAbstractItemView* view) {
        const QAbstractItemModel* model = view->model();
        if (!model) return;
        auto* table = qobject_cast<QTableView*>(view);
        auto* tree = qobject_cast<QTreeView*>(view);
        QHeaderView* header = table ? table->horizontalHeader() : tree ? tree->header() : nullptr;
        QList<int> columns;
        if (header) {
            QStringList titles;
            for (int visual = 0; visual < header->count(); ++visual) {
                const int logical = header->logicalIndex(visual);
                if (header->isSectionHidden(logical)) continue;
                columns << logical;
                titles << model->headerData(logical, Qt::Horizontal).toString().simplified();
            }
            if (!header->isHidden()) add(QStringLiteral("header"), titles.join(QStringLiteral(" | ")));
        }
        const int bottom = view->viewport()->height();
        QModelIndex index = view->indexAt(QPoint(1, 1));
        for (int n = 0; index.isValid() && n < kMaxRows && view->visualRect(index).top() < bottom; ++n) {
            if (columns.isEmpty()) {
                add(QStringLiteral("item"), cell(index));
            } else {
                QStringList cells;
                if (table && table->verticalHeader()->isVisible())
                    cells << model->headerData(index.row(), Qt::Vertical).toString().simplified();
                for (int column : columns) cells << cell(index.siblingAtColumn(column));
                add(QStringLiteral("row"), cells.join(QStringLiteral(" | ")));
            }
            index = tree ? tree->indexBelow(index) : index.siblingAtRow(index.row() + 1);
        }
    }

    void plot(QCustomPlot* plot, const TourShot::Layer& layer) {
        const QRect picture(QPoint(0, 0), m_shot.picture.size());
        for (QCPAxisRect* area : plot->axisRects()) {
            if (!area->realVisibility()) continue;
            const QRect inner = area->rect();
            const QPoint at = plot->mapTo(layer.widget, inner.topLeft()) + layer.at;
            const QRect pixels = QRect(at * m_ratio, inner.size() * m_ratio).intersected(picture);
            if (!pixels.isEmpty())
                add(QStringLiteral("plot"), QStringLiteral("%1,%2 %3x%4")
                                                .arg(pixels.x())
                                                .arg(pixels.y())
                                                .arg(pixels.width())
                                                .arg(pixels.height()));
            // One side after another: axes() alone comes out of a hash, in an order that changes per run.
            for (const QCPAxis::AxisType side : {QCPAxis::atLeft, QCPAxis::atBottom, QCPAxis::atRight, QCPAxis::atTop})
                for (QCPAxis* axis : area->axes(side))
                    if (axis->visible()) add(QStringLiteral("axis"), axis->label());
        }
        if (plot->legend && plot->legend->realVisibility())
            for (int i = 0; i < plot->legend->itemCount(); ++i)
                if (auto* item = qobject_cast<QCPPlottableLegendItem*>(plot->legend->item(i));
                    item && item->realVisibility())
                    add(QStringLiteral("legend"), item->plottable()->name());
        for (QCPLayoutElement* element : plot->plotLayout()->elements(true))
            if (auto* title = qobject_cast<QCPTextElement*>(element); title && title->realVisibility())
                add(QStringLiteral("plot-text"), title->text());
        for (int i = 0; i < plot->itemCount(); ++i)
            if (auto* text = qobject_cast<QCPItemText*>(plot->item(i)); text && text->realVisibility())
                add(QStringLiteral("plot-text"), text->text());
    }

    const TourShot& m_shot;
    const qreal m_ratio;
    QStringList m_facts;
};

} // namespace

QStringList shotFacts(const TourShot& shot) {
    FactWriter writer(shot);
    for (const TourShot::Layer& layer : shot.layers) writer.layer(layer);
    return writer.facts();
}

} // namespace app
