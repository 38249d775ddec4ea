// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/panels/paint_layers_panel.h"

#include <QAction>
#include <QCheckBox>
#include <QColorDialog>
#include <QComboBox>
#include <QDropEvent>
#include <QFormLayout>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QIcon>
#include <QKeySequence>
#include <QLabel>
#include <QLocale>
#include <QMenu>
#include <QMouseEvent>
#include <QPixmap>
#include <QScopedValueRollback>
#include <QSlider>
#include <QSpinBox>
#include <QTimer>
#include <QToolButton>
#include <QTreeWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>

#include "core/base/color.h"
#include "core/document/document.h"
#include "ui/panels/paint_layer_thumbnails.h"
#include "ui/panels/value_spin_box.h"

namespace ui {

namespace {

constexpr int kThumbnail = 32;

/** image as an icon drawn as it is on a selected row too (the style would tint it). */
QIcon thumbnailIcon(const QImage& image) {
    const QPixmap pixmap = QPixmap::fromImage(image);
    QIcon icon(pixmap);
    icon.addPixmap(pixmap, QIcon::Selected);
    return icon;
}
constexpr int kEye = 18;
constexpr int kIdRole = Qt::UserRole;

/**
 * The list of rows. A drop moves nothing itself: it reports which layer went to which row and
 * the panel asks the document (one undo step), then shows the stack again.
 */
class PaintLayerList : public QTreeWidget {
public:
    explicit PaintLayerList(QWidget* parent) : QTreeWidget(parent) {}
    std::function<void(std::uint64_t id, int row)> onDrop;
    /** The keys held at the last click (itemClicked() does not say). */
    Qt::KeyboardModifiers clickModifiers;

protected:
    void mouseReleaseEvent(QMouseEvent* event) override {
        clickModifiers = event->modifiers();
        QTreeWidget::mouseReleaseEvent(event);
    }

    void dropEvent(QDropEvent* event) override {
        QTreeWidgetItem* source = currentItem();
        const std::uint64_t id = source ? source->data(0, kIdRole).toULongLong() : 0;
        QTreeWidgetItem* over = itemAt(event->position().toPoint());
        // The row it goes to among the layer rows (the last row, Base, stays last).
        int row = topLevelItemCount() - 1;
        if (over) {
            row = indexOfTopLevelItem(over);
            const QRect rect = visualItemRect(over);
            if (dropIndicatorPosition() == BelowItem ||
                (dropIndicatorPosition() == OnItem && event->position().y() > rect.center().y()))
                ++row;
        }
        event->setDropAction(Qt::IgnoreAction);
        event->accept();
        if (id == 0 || !onDrop)
            return;
        const int from = indexOfTopLevelItem(source);
        if (row > from)
            --row;
        // Applied after the drag has ended: the rows are made anew then.
        QTimer::singleShot(0, this, [this, id, row] { onDrop(id, row); });
    }
};

QString blendModeText(core::BlendMode mode) {
    switch (mode) {
    case core::BlendMode::Normal:
        return PaintLayersPanel::tr("Normal");
    case core::BlendMode::Multiply:
        return PaintLayersPanel::tr("Multiply");
    case core::BlendMode::Screen:
        return PaintLayersPanel::tr("Screen");
    case core::BlendMode::Overlay:
        return PaintLayersPanel::tr("Overlay");
    case core::BlendMode::SoftLight:
        return PaintLayersPanel::tr("Soft Light");
    case core::BlendMode::Add:
        return PaintLayersPanel::tr("Add");
    case core::BlendMode::Subtract:
        return PaintLayersPanel::tr("Subtract");
    case core::BlendMode::Darken:
        return PaintLayersPanel::tr("Darken");
    case core::BlendMode::Lighten:
        return PaintLayersPanel::tr("Lighten");
    case core::BlendMode::Difference:
        return PaintLayersPanel::tr("Difference");
    }
    return {};
}

} // namespace

PaintLayersPanel::PaintLayersPanel(core::Document& document, QWidget* parent)
    : QWidget(parent), m_document(document) {
    createActions();
    auto* layout = new QVBoxLayout(this);
    m_reason = new QLabel(this);
    m_reason->setObjectName(QStringLiteral("paintLayersReason"));
    m_reason->setWordWrap(true);
    m_reason->hide();
    layout->addWidget(m_reason);

    createTextureSetRow(layout);
    createList();
    layout->addWidget(m_list, 1);
    createSettingsControls();
    layout->addWidget(m_controls);
    layout->addLayout(createOperationButtons());
    refresh();
}

void PaintLayersPanel::createList() {
    auto* list = new PaintLayerList(this);
    m_list = list;
    m_list->setObjectName(QStringLiteral("paintLayersList"));
    m_list->setColumnCount(4);
    m_list->setHeaderHidden(true);
    m_list->setRootIsDecorated(false);
    m_list->setIndentation(0);
    m_list->setUniformRowHeights(true);
    m_list->setIconSize(QSize(kThumbnail, kThumbnail));
    m_list->setSelectionMode(QAbstractItemView::SingleSelection);
    m_list->setEditTriggers(QAbstractItemView::NoEditTriggers); // double-click on the name only
    m_list->setDragDropMode(QAbstractItemView::InternalMove);
    m_list->setDefaultDropAction(Qt::MoveAction);
    m_list->setContextMenuPolicy(Qt::CustomContextMenu);
    m_list->header()->setStretchLastSection(false);
    m_list->header()->setSectionResizeMode(NameColumn, QHeaderView::Stretch);
    for (const int column : {EyeColumn, ThumbnailColumn, MaskColumn})
        m_list->header()->setSectionResizeMode(column, QHeaderView::ResizeToContents);
    m_list->setToolTip(tr("The paint layers, the uppermost on top. Click a row to paint on it, "
                          "its eye to show or hide it, its mask to paint the mask; double-click "
                          "a name to rename it; drag rows to reorder them."));
    list->onDrop = [this](std::uint64_t id, int row) { moveToRow(id, row); };
    connect(m_list, &QTreeWidget::itemClicked, this, &PaintLayersPanel::onItemClicked);
    connect(m_list, &QTreeWidget::itemChanged, this, &PaintLayersPanel::onItemChanged);
    connect(m_list, &QTreeWidget::itemDoubleClicked, this,
            [this](QTreeWidgetItem* item, int column) {
                if (column == NameColumn && item->data(0, kIdRole).toULongLong() != 0)
                    m_list->editItem(item, NameColumn);
            });
    connect(m_list, &QWidget::customContextMenuRequested, this, &PaintLayersPanel::showContextMenu);
}

void PaintLayersPanel::createTextureSetRow(QBoxLayout* layout) {
    m_textureSetRow = new QWidget(this);
    auto* row = new QHBoxLayout(m_textureSetRow);
    row->setContentsMargins(0, 0, 0, 0);
    auto* label = new QLabel(tr("Texture set:"), m_textureSetRow);
    m_textureSet = new QComboBox(m_textureSetRow);
    m_textureSet->setObjectName(QStringLiteral("textureSetBox"));
    m_textureSet->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    m_textureSet->setMinimumContentsLength(12);
    m_textureSet->setToolTip(tr("Each texture the model paints into, with the materials on it, is "
                                "a texture set. The thumbnails show the chosen one's paint; "
                                "strokes paint every texture set they cross."));
    label->setBuddy(m_textureSet);
    row->addWidget(label);
    row->addWidget(m_textureSet, 1);
    connect(m_textureSet, &QComboBox::currentIndexChanged, this, [this] {
        if (!m_updating)
            refresh();
    });
    m_textureSetRow->hide();
    layout->addWidget(m_textureSetRow);
}

void PaintLayersPanel::updateTextureSets() {
    const core::PaintLayerTarget* painted = target();
    const std::size_t pages = painted ? painted->paintLayerStack().pages().size() : 0;
    QStringList names;
    for (std::uint32_t p = 0; p < pages; ++p) {
        QStringList materials;
        const std::vector<core::Material>& all = m_document.mesh().materials;
        for (std::size_t m = 0; m < all.size(); ++m)
            if (painted->materialPage(m) == p && !all[m].name.empty())
                materials << QString::fromStdString(all[m].name);
        const core::PageSize size = painted->paintLayerStack().pages()[p];
        const QString name =
            materials.isEmpty() ? tr("Texture set %1").arg(p + 1) : materials.join(tr(", "));
        names << tr("%1 (%2 × %3)").arg(name).arg(size.width).arg(size.height);
    }
    QStringList shown;
    for (int i = 0; i < m_textureSet->count(); ++i)
        shown << m_textureSet->itemText(i);
    if (shown != names) {
        const int keep = m_textureSet->currentIndex();
        m_textureSet->clear();
        m_textureSet->addItems(names);
        m_textureSet->setCurrentIndex(keep >= 0 && keep < names.size() ? keep : 0);
    }
    m_textureSetRow->setVisible(names.size() > 1);
}

std::uint32_t PaintLayersPanel::shownPage() const {
    return std::uint32_t(std::max(0, m_textureSet->currentIndex()));
}

void PaintLayersPanel::createSettingsControls() {
    // The current layer's settings.
    m_controls = new QWidget(this);
    m_form = new QFormLayout(m_controls);
    m_form->setContentsMargins(0, 0, 0, 0);
    addOpacityRow();
    addBlendRow();
    addLockRow();
    // A fill layer's values: its colour and, for a texture, roughness and metallic; "Off" leaves
    // a channel alone (as the script's and the tool's "fill values" do with null).
    addFillColorRow();
    addFillChannelRows();
}

void PaintLayersPanel::addOpacityRow() {
    m_opacity = new QSlider(Qt::Horizontal, m_controls);
    m_opacity->setObjectName(QStringLiteral("paintLayerOpacity"));
    m_opacity->setRange(0, 100);
    m_opacity->setTracking(false); // one undo step per change, not one per pixel dragged
    m_opacity->setToolTip(tr("How much of the current paint layer shows"));
    m_opacityText = new QLabel(m_controls);
    m_opacityText->setMinimumWidth(fontMetrics().horizontalAdvance(QStringLiteral("100 %")));
    auto* opacityRow = new QHBoxLayout;
    opacityRow->addWidget(m_opacity, 1);
    opacityRow->addWidget(m_opacityText);
    m_form->addRow(tr("&Opacity"), opacityRow);
    if (auto* text = qobject_cast<QLabel*>(m_form->labelForField(opacityRow)))
        text->setBuddy(m_opacity);
    connect(m_opacity, &QSlider::sliderMoved, this,
            [this](int value) { m_opacityText->setText(tr("%1 %").arg(value)); });
    connect(m_opacity, &QSlider::valueChanged, this, [this](int value) {
        m_opacityText->setText(tr("%1 %").arg(value));
        if (!m_updating)
            editSettings(selectedPaintLayer(), [value](core::PaintLayerSettings& settings) {
                settings.opacity = float(value) / 100.0f;
            });
    });
}

void PaintLayersPanel::addBlendRow() {
    m_blend = new QComboBox(m_controls);
    m_blend->setObjectName(QStringLiteral("paintLayerBlend"));
    m_blend->setToolTip(tr("How the current paint layer combines with what lies under it"));
    for (const core::BlendMode mode : core::kBlendModes)
        m_blend->addItem(blendModeText(mode), int(mode));
    m_form->addRow(tr("&Blend mode"), m_blend);
    connect(m_blend, &QComboBox::currentIndexChanged, this, [this](int index) {
        if (m_updating || index < 0)
            return;
        const auto mode = core::BlendMode(m_blend->itemData(index).toInt());
        editSettings(selectedPaintLayer(),
                     [mode](core::PaintLayerSettings& settings) { settings.blend = mode; });
    });
}

void PaintLayersPanel::addLockRow() {
    m_lock = new QCheckBox(tr("Lock &transparency"), m_controls);
    m_lock->setObjectName(QStringLiteral("paintLayerLock"));
    m_lock->setToolTip(
        tr("Painting changes the colour of what is on the paint layer, never where it "
           "is or how much"));
    m_form->addRow(m_lock);
    connect(m_lock, &QCheckBox::toggled, this, [this](bool on) {
        if (!m_updating)
            editSettings(selectedPaintLayer(), [on](core::PaintLayerSettings& settings) {
                settings.lockTransparency = on;
            });
    });
}

void PaintLayersPanel::addFillColorRow() {
    m_fillColorOn = new QCheckBox(m_controls);
    m_fillColorOn->setObjectName(QStringLiteral("paintLayerFillColorOn"));
    m_fillColorOn->setToolTip(tr("Whether the fill layer sets the base colour"));
    m_fillColor = new QToolButton(m_controls);
    m_fillColor->setObjectName(QStringLiteral("paintLayerFillColor"));
    m_fillColor->setToolTip(tr("The fill layer's base colour (click to choose)"));
    m_fillColor->setIconSize(QSize(32, 14));
    m_fillColorRow = new QHBoxLayout;
    m_fillColorRow->addWidget(m_fillColorOn);
    m_fillColorRow->addWidget(m_fillColor);
    m_fillColorRow->addStretch(1);
    m_form->addRow(tr("&Fill colour"), m_fillColorRow);
    if (auto* text = qobject_cast<QLabel*>(m_form->labelForField(m_fillColorRow)))
        text->setBuddy(m_fillColorOn);
    connect(m_fillColorOn, &QCheckBox::toggled, this, [this](bool on) {
        if (m_updating)
            return;
        const QColor shown = m_fillColorValue;
        editSettings(selectedPaintLayer(), [on, shown](core::PaintLayerSettings& settings) {
            settings.fill.baseColor.reset();
            if (on)
                settings.fill.baseColor =
                    glm::vec3(float(shown.redF()), float(shown.greenF()), float(shown.blueF()));
        });
    });
    connect(m_fillColor, &QToolButton::clicked, this, [this] {
        auto* dialog = new QColorDialog(m_fillColorValue, this);
        dialog->setObjectName(QStringLiteral("paintLayerFillColorDialog"));
        dialog->setWindowTitle(tr("Fill Layer Colour"));
        dialog->setAttribute(Qt::WA_DeleteOnClose);
        const std::uint64_t id = selectedPaintLayer();
        connect(dialog, &QColorDialog::colorSelected, this, [this, id](const QColor& color) {
            editSettings(id, [color](core::PaintLayerSettings& settings) {
                settings.fill.baseColor =
                    glm::vec3(float(color.redF()), float(color.greenF()), float(color.blueF()));
            });
        });
        dialog->open();
    });
}

void PaintLayersPanel::addFillChannelRows() {
    const auto channelSpin = [this](const char* name, const QString& label, const QString& tip,
                                    auto set) {
        auto* spin = new UnitSpinBox(m_controls, QString::fromLatin1(name), tip, true);
        m_form->addRow(label, spin);
        connect(spin, &QDoubleSpinBox::valueChanged, this, [this, set](double value) {
            if (m_updating)
                return;
            editSettings(selectedPaintLayer(), [value, set](core::PaintLayerSettings& settings) {
                set(settings.fill,
                    value < 0.0 ? std::optional<float>() : std::optional<float>(float(value)));
            });
        });
        return spin;
    };
    m_fillRoughness =
        channelSpin("paintLayerFillRoughness", tr("&Roughness"),
                    tr("The roughness the fill layer sets; Off leaves roughness alone"),
                    [](core::ChannelValues& fill, std::optional<float> v) { fill.roughness = v; });
    m_fillMetallic =
        channelSpin("paintLayerFillMetallic", tr("&Metallic"),
                    tr("How metallic the fill layer makes the surface; Off leaves metallic alone"),
                    [](core::ChannelValues& fill, std::optional<float> v) { fill.metallic = v; });
}

QGridLayout* PaintLayersPanel::createOperationButtons() {
    // A button for every operation.
    auto* buttons = new QGridLayout;
    buttons->setSpacing(2);
    int slot = 0;
    for (QAction* action : operationActions()) {
        if (!action)
            continue;
        auto* button = new QToolButton(this);
        button->setDefaultAction(action);
        button->setToolButtonStyle(Qt::ToolButtonTextOnly);
        button->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
        buttons->addWidget(button, slot / 4, slot % 4);
        ++slot;
    }
    return buttons;
}

void PaintLayersPanel::createActions() {
    const auto make = [this](const QString& text, const QString& iconText, const QString& name,
                             const QString& tip, const QKeySequence& key = {}) {
        auto* action = new QAction(text, this);
        action->setIconText(iconText);
        action->setObjectName(name);
        action->setShortcut(key);
        action->setShortcutContext(Qt::WindowShortcut);
        action->setStatusTip(tip);
        action->setToolTip(key.isEmpty() ? tip
                                         : QStringLiteral("%1 (%2)").arg(
                                               tip, key.toString(QKeySequence::NativeText)));
        return action;
    };
    m_newLayer = make(tr("&New Paint Layer"), tr("New"), QStringLiteral("actionNewPaintLayer"),
                      tr("Add a paint layer above the current one"),
                      QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_N));
    connect(m_newLayer, &QAction::triggered, this, [this] { addLayer(false); });
    m_newFill =
        make(tr("New F&ill Layer"), tr("Fill"), QStringLiteral("actionNewFillLayer"),
             tr("Add a paint layer of uniform channel values (the brush's) above the current "
                "one"));
    connect(m_newFill, &QAction::triggered, this, [this] { addLayer(true); });
    m_duplicate = make(tr("&Duplicate Paint Layer"), tr("Duplicate"),
                       QStringLiteral("actionDuplicatePaintLayer"),
                       tr("Copy the current paint layer"), QKeySequence(Qt::CTRL | Qt::Key_J));
    connect(m_duplicate, &QAction::triggered, this, [this] {
        core::PaintChanges changes;
        const auto copy = m_document.duplicatePaintLayer(selectedPaintLayer(), changes);
        finish(copy ? core::Status{} : core::Status{core::Error{copy.error()}}, changes);
    });
    m_delete = make(tr("D&elete Paint Layer"), tr("Delete"),
                    QStringLiteral("actionDeletePaintLayer"), tr("Delete the current paint layer"));
    connect(m_delete, &QAction::triggered, this, [this] {
        core::PaintChanges changes;
        finish(m_document.deletePaintLayer(selectedPaintLayer(), changes), changes);
    });
    m_mergeDown = make(tr("&Merge Down"), tr("Merge"), QStringLiteral("actionMergePaintLayerDown"),
                       tr("Merge the current paint layer into the one below"),
                       QKeySequence(Qt::CTRL | Qt::Key_E));
    connect(m_mergeDown, &QAction::triggered, this, [this] {
        core::PaintChanges changes;
        finish(m_document.mergePaintLayerDown(selectedPaintLayer(), changes), changes);
    });
    m_flatten =
        make(tr("&Flatten Paint Layers"), tr("Flatten"), QStringLiteral("actionFlattenPaintLayers"),
             tr("Merge every visible paint layer into one"));
    connect(m_flatten, &QAction::triggered, this, [this] {
        core::PaintChanges changes;
        finish(m_document.flattenPaintLayers(tr("Flattened").toStdString(), changes), changes);
    });
    m_addMask = make(tr("Add M&ask"), tr("Mask"), QStringLiteral("actionAddPaintLayerMask"),
                     tr("Give the current paint layer a mask (black hides, white shows)"));
    connect(m_addMask, &QAction::triggered, this, [this] {
        core::PaintChanges changes;
        finish(m_document.addPaintLayerMask(selectedPaintLayer(), changes), changes);
    });
    m_deleteMask =
        make(tr("Delete Mas&k"), tr("No Mask"), QStringLiteral("actionDeletePaintLayerMask"),
             tr("Remove the current paint layer's mask"));
    connect(m_deleteMask, &QAction::triggered, this, [this] {
        core::PaintChanges changes;
        finish(m_document.deletePaintLayerMask(selectedPaintLayer(), changes), changes);
    });
    m_rename = new QAction(tr("&Rename…"), this);
    m_rename->setObjectName(QStringLiteral("actionRenamePaintLayer"));
    connect(m_rename, &QAction::triggered, this, [this] {
        if (QTreeWidgetItem* item = rowOf(selectedPaintLayer()); item && selectedPaintLayer() != 0)
            m_list->editItem(item, NameColumn);
    });
}

QList<QAction*> PaintLayersPanel::operationActions() const {
    return {m_newLayer,  m_newFill, m_duplicate, m_delete,  nullptr,
            m_mergeDown, m_flatten, nullptr,     m_addMask, m_deleteMask};
}

const core::PaintLayerTarget* PaintLayersPanel::target() const {
    if (m_document.meshSerial() == 0 || !m_document.hasPaintTarget())
        return nullptr;
    return m_document.currentPaintTarget()->paintLayers();
}

QString PaintLayersPanel::disabledReason() const {
    if (m_document.meshSerial() == 0)
        return tr("Open a model to paint in paint layers.");
    if (m_document.paintTargetKind() != core::PaintTargetKind::Texture)
        return tr("Vertex colours have no paint layers: choose a texture as the paint target "
                  "(in the brush bar) to paint in paint layers.");
    return {};
}

std::uint64_t PaintLayersPanel::selectedPaintLayer() const {
    const core::PaintLayerTarget* painted = target();
    return painted ? painted->selection().layer : 0;
}

QTreeWidgetItem* PaintLayersPanel::rowOf(std::uint64_t id) const {
    for (int i = 0; i < m_list->topLevelItemCount(); ++i) {
        QTreeWidgetItem* item = m_list->topLevelItem(i);
        if (item->data(0, kIdRole).toULongLong() == id)
            return item;
    }
    return nullptr;
}

void PaintLayersPanel::refresh() {
    const QScopedValueRollback guard(m_updating, true);
    const QString reason = disabledReason();
    m_reason->setText(reason);
    m_reason->setVisible(!reason.isEmpty());
    m_list->setEnabled(reason.isEmpty());
    m_list->clear();
    updateTextureSets();
    const std::uint32_t page = shownPage();

    const core::PaintLayerTarget* painted = target();
    const core::PaintSelection selection = painted ? painted->selection() : core::PaintSelection{};
    if (reason.isEmpty()) {
        if (painted) {
            const core::PaintLayerStack& stack = painted->paintLayerStack();
            for (std::size_t i = stack.size(); i-- > 0;) {
                const core::PaintLayer& layer = stack.layer(i);
                auto* item = new QTreeWidgetItem(m_list);
                item->setData(0, kIdRole, QVariant::fromValue<qulonglong>(layer.id));
                item->setFlags(Qt::ItemIsEnabled | Qt::ItemIsSelectable | Qt::ItemIsEditable |
                               Qt::ItemIsDragEnabled);
                item->setIcon(EyeColumn,
                              QIcon(QPixmap::fromImage(eyeIcon(layer.settings.visible, kEye))));
                item->setToolTip(EyeColumn, layer.settings.visible ? tr("Shown: click to hide")
                                                                   : tr("Hidden: click to show"));
                item->setIcon(ThumbnailColumn,
                              thumbnailIcon(layerThumbnail(
                                  layer, kThumbnail,
                                  selection == core::PaintSelection{layer.id, false}, page)));
                QString name = QString::fromStdString(layer.settings.name);
                item->setText(NameColumn, name);
                QStringList notes;
                if (layer.settings.kind == core::PaintLayerKind::Fill)
                    notes << tr("fill layer");
                if (layer.settings.blend != core::BlendMode::Normal)
                    notes << blendModeText(layer.settings.blend);
                if (layer.settings.opacity < 1.0f)
                    notes << tr("%1 %").arg(std::lround(layer.settings.opacity * 100.0f));
                item->setToolTip(NameColumn, notes.isEmpty()
                                                 ? name
                                                 : tr("%1 (%2)").arg(name, notes.join(tr(", "))));
                if (layer.mask) {
                    const bool maskSelected = selection == core::PaintSelection{layer.id, true};
                    item->setIcon(MaskColumn, thumbnailIcon(maskThumbnail(*layer.mask, kThumbnail,
                                                                          maskSelected, page)));
                    item->setToolTip(MaskColumn,
                                     layer.id == m_maskView
                                         ? tr("Shown alone in the view: Alt+click to see the "
                                              "paint layers again")
                                     : maskSelected ? tr("Painting the mask (black hides, white "
                                                         "shows); Alt+click shows it alone")
                                                    : tr("Mask: click to paint it, Alt+click to "
                                                         "see it alone"));
                }
            }
        }
        auto* base = new QTreeWidgetItem(m_list);
        base->setData(0, kIdRole, QVariant::fromValue<qulonglong>(0));
        base->setFlags(Qt::ItemIsEnabled | Qt::ItemIsSelectable);
        base->setText(NameColumn, tr("Base"));
        base->setToolTip(NameColumn, tr("The model's own surface (painting here changes it "
                                        "directly)"));
        if (painted)
            base->setIcon(ThumbnailColumn, thumbnailIcon(baseThumbnail(painted->paintLayerStack(),
                                                                       kThumbnail, page)));
        if (QTreeWidgetItem* current = rowOf(selection.layer))
            m_list->setCurrentItem(current);
    }
    updateControls();
    emit refreshed();
}

void PaintLayersPanel::updateControls() {
    const QScopedValueRollback guard(m_updating, true);
    const core::PaintLayerTarget* painted = target();
    const bool enabled = disabledReason().isEmpty();
    const core::PaintLayer* layer = nullptr;
    std::size_t index = 0, count = 0;
    if (painted) {
        const core::PaintLayerStack& stack = painted->paintLayerStack();
        count = stack.size();
        if (const auto at = stack.indexOf(painted->selection().layer)) {
            index = *at;
            layer = &stack.layer(*at);
        }
    }
    m_controls->setEnabled(layer != nullptr);
    const core::PaintLayerSettings settings = layer ? layer->settings : core::PaintLayerSettings{};
    m_opacity->setValue(int(std::lround(settings.opacity * 100.0f)));
    m_opacityText->setText(tr("%1 %").arg(m_opacity->value()));
    m_blend->setCurrentIndex(m_blend->findData(int(settings.blend)));
    m_lock->setChecked(settings.lockTransparency);
    // A fill layer's values, shown only for one.
    const bool fill = layer != nullptr && settings.kind == core::PaintLayerKind::Fill;
    const bool material = fill && painted->paintLayerStack().hasMaterialChannels();
    m_form->setRowVisible(m_fillColorRow, fill);
    m_form->setRowVisible(m_fillRoughness, material);
    m_form->setRowVisible(m_fillMetallic, material);
    m_fillColorOn->setChecked(settings.fill.baseColor.has_value());
    m_fillColor->setEnabled(settings.fill.baseColor.has_value());
    if (settings.fill.baseColor)
        m_fillColorValue = QColor::fromRgbF(std::clamp(settings.fill.baseColor->x, 0.0f, 1.0f),
                                            std::clamp(settings.fill.baseColor->y, 0.0f, 1.0f),
                                            std::clamp(settings.fill.baseColor->z, 0.0f, 1.0f));
    QPixmap swatch(m_fillColor->iconSize());
    swatch.fill(m_fillColorValue);
    m_fillColor->setIcon(QIcon(swatch));
    const auto unit = [](const std::optional<float>& v) {
        return v ? double(std::clamp(*v, 0.0f, 1.0f)) : -1.0;
    };
    m_fillRoughness->setValue(unit(settings.fill.roughness));
    m_fillMetallic->setValue(unit(settings.fill.metallic));

    m_newLayer->setEnabled(enabled);
    m_newFill->setEnabled(enabled);
    m_duplicate->setEnabled(layer != nullptr);
    m_delete->setEnabled(layer != nullptr);
    m_mergeDown->setEnabled(layer != nullptr && index > 0);
    m_flatten->setEnabled(enabled && count > 0);
    m_addMask->setEnabled(layer != nullptr && !layer->mask);
    m_deleteMask->setEnabled(layer != nullptr && layer->mask != nullptr);
    m_rename->setEnabled(layer != nullptr);
}

void PaintLayersPanel::finish(const core::Status& status, const core::PaintChanges& changes) {
    if (!status)
        emit message(tr("Paint layers: %1").arg(QString::fromStdString(status.error())));
    refresh();
    if (status)
        emit changed(changes);
}

void PaintLayersPanel::addLayer(bool fill) {
    core::PaintLayerSettings settings;
    if (fill) {
        settings.kind = core::PaintLayerKind::Fill;
        settings.name = tr("Fill %1").arg(m_nextNumber++).toStdString();
        // The brush's channels: what it would paint, everywhere.
        const core::Brush& brush = m_document.brush();
        const glm::vec3 srgb{core::linearToSrgb(brush.color.r) / 255.0f,
                             core::linearToSrgb(brush.color.g) / 255.0f,
                             core::linearToSrgb(brush.color.b) / 255.0f};
        if (brush.paintBaseColor)
            settings.fill.baseColor = srgb;
        if (brush.paintRoughness)
            settings.fill.roughness = brush.roughness;
        if (brush.paintMetallic)
            settings.fill.metallic = brush.metallic;
        if (settings.fill == core::ChannelValues{})
            settings.fill.baseColor = srgb;
    } else {
        settings.name = tr("Paint Layer %1").arg(m_nextNumber++).toStdString();
    }
    core::PaintChanges changes;
    const auto id = m_document.addPaintLayer(std::move(settings), changes);
    finish(id ? core::Status{} : core::Status{core::Error{id.error()}}, changes);
}

void PaintLayersPanel::select(std::uint64_t id, bool mask) {
    if (m_maskView != 0 && !(mask && id == m_maskView))
        emit maskViewRequested(0); // the mask view follows the mask being painted
    const core::Status status = m_document.selectPaint({id, mask});
    if (!status)
        emit message(tr("Paint layers: %1").arg(QString::fromStdString(status.error())));
    refresh();
    emit selectionChanged();
}

void PaintLayersPanel::onItemClicked(QTreeWidgetItem* item, int column) {
    if (m_updating || !item)
        return;
    const std::uint64_t id = item->data(0, kIdRole).toULongLong();
    const core::PaintLayerTarget* painted = target();
    const core::PaintLayer* layer = nullptr;
    if (painted && id != 0)
        if (const auto index = painted->paintLayerStack().indexOf(id))
            layer = &painted->paintLayerStack().layer(*index);
    if (layer && column == EyeColumn) {
        const bool visible = !layer->settings.visible;
        editSettings(id,
                     [visible](core::PaintLayerSettings& settings) { settings.visible = visible; });
        return;
    }
    const bool onMask = layer && layer->mask && column == MaskColumn;
    const bool alt = (static_cast<PaintLayerList*>(m_list)->clickModifiers & Qt::AltModifier) != 0;
    select(id, onMask);
    if (onMask && alt) // Alt+click: the mask alone in the view, or back
        emit maskViewRequested(m_maskView == id ? 0 : id);
}

void PaintLayersPanel::setMaskView(std::uint64_t id) {
    if (m_maskView == id)
        return;
    m_maskView = id;
    refresh();
}

void PaintLayersPanel::onItemChanged(QTreeWidgetItem* item, int column) {
    if (m_updating || column != NameColumn)
        return;
    const QString name = item->text(NameColumn).trimmed();
    const std::uint64_t id = item->data(0, kIdRole).toULongLong();
    if (name.isEmpty()) {
        // Deferred: the editor is still closing.
        QTimer::singleShot(0, this, &PaintLayersPanel::refresh);
        return;
    }
    QTimer::singleShot(0, this, [this, id, name] {
        editSettings(id, [&name](core::PaintLayerSettings& settings) {
            settings.name = name.toStdString();
        });
    });
}

template <typename Edit> void PaintLayersPanel::editSettings(std::uint64_t id, Edit edit) {
    const core::PaintLayerTarget* painted = target();
    if (!painted || id == 0)
        return;
    const auto index = painted->paintLayerStack().indexOf(id);
    if (!index)
        return;
    core::PaintLayerSettings settings = painted->paintLayerStack().layer(*index).settings;
    edit(settings);
    core::PaintChanges changes;
    finish(m_document.setPaintLayerSettings(id, std::move(settings), changes), changes);
}

void PaintLayersPanel::moveToRow(std::uint64_t id, int row) {
    const core::PaintLayerTarget* painted = target();
    if (!painted)
        return;
    const int count = int(painted->paintLayerStack().size());
    if (count == 0)
        return;
    row = std::clamp(row, 0, count - 1);
    core::PaintChanges changes;
    finish(m_document.movePaintLayer(id, std::size_t(count - 1 - row), changes), changes);
}

void PaintLayersPanel::showContextMenu(const QPoint& position) {
    if (!disabledReason().isEmpty())
        return;
    if (QTreeWidgetItem* item = m_list->itemAt(position)) {
        const std::uint64_t id = item->data(0, kIdRole).toULongLong();
        if (id != selectedPaintLayer())
            select(id, false);
    }
    QMenu menu(this);
    for (QAction* action : operationActions()) {
        if (action)
            menu.addAction(action);
        else
            menu.addSeparator();
    }
    menu.addSeparator();
    menu.addAction(m_rename);
    menu.exec(m_list->viewport()->mapToGlobal(position));
}

} // namespace ui
