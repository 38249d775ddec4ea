// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/panels/brush_toolbar.h"

#include "core/base/color.h"
#include "core/paint/targets/layout_target.h"
#include "ui/panels/value_spin_box.h"

#include <QColorDialog>
#include <QComboBox>
#include <QLabel>
#include <QPainter>
#include <QPixmap>
#include <QScopedValueRollback>
#include <QSpinBox>
#include <QStringList>
#include <QToolButton>

#include <algorithm>
#include <cmath>
#include <iterator>

namespace ui {

namespace {
constexpr int kResolutions[] = {512, 1024, 2048, 4096, 8192};
constexpr int kVertexColorsItem = -1;            // the combo's data for vertex colours
constexpr int kAutomaticRole = Qt::UserRole + 1; // true: a texture over an automatic layout
constexpr int kMaxTipMaterials = 12;

/** sizes with the materials no triangle uses left out (their size 0 × 0). */
std::vector<core::PageSize> usedOnly(std::vector<core::PageSize> sizes, const core::Mesh& mesh) {
    std::vector<char> used(sizes.size(), 0);
    for (std::uint32_t m : mesh.triangleMaterial)
        if (m < used.size())
            used[m] = 1;
    for (std::size_t m = 0; m < sizes.size(); ++m)
        if (!used[m])
            sizes[m] = core::PageSize{};
    return sizes;
}

} // namespace

/** One texture entry of the target box. */
struct BrushToolBar::TargetItem {
    QString text;
    QString tip;
    int resolution = 0;
    bool automatic = false;
};

BrushToolBar::BrushToolBar(QWidget* parent) : QToolBar(parent) {
    // Named apart from the Brush panel (View ▸ Panels lists both).
    setWindowTitle(tr("Brush Bar"));
    setObjectName(QStringLiteral("brushToolBar"));

    m_color = new QToolButton(this);
    m_color->setObjectName(QStringLiteral("brushColor"));
    m_color->setToolTip(tr("Brush colour"));
    connect(m_color, &QToolButton::clicked, this, &BrushToolBar::chooseColor);
    addWidget(m_color);

    const auto addSpin = [this](const QString& label, const QString& name, int minimum, int maximum,
                                const QString& suffix, const QString& tip) {
        auto* text = new QLabel(label, this);
        text->setContentsMargins(6, 0, 2, 0);
        addWidget(text);
        QSpinBox* spin = makeValueSpinBox(this, name, minimum, maximum, suffix, tip);
        text->setBuddy(spin);
        addWidget(spin);
        return spin;
    };
    m_radius = addSpin(tr("&Radius"), QStringLiteral("brushRadius"), 1, 500, tr(" px"),
                       tr("Brush radius on screen ([ smaller, ] larger)"));
    m_hardness =
        addSpin(tr("&Hardness"), QStringLiteral("brushHardness"), 0, 100, tr(" %"),
                tr("0: soft falloff from the centre, 100: a hard edge (Shift+[ softer, Shift+] "
                   "harder)"));
    m_opacity = addSpin(tr("O&pacity"), QStringLiteral("brushOpacity"), 1, 100, tr(" %"),
                        tr("The most one stroke covers"));
    const auto changed = [this] {
        if (m_updating)
            return;
        m_brush.radius = float(m_radius->value());
        m_brush.hardness = float(m_hardness->value()) / 100.0f;
        m_brush.opacity = float(m_opacity->value()) / 100.0f;
        emit brushChanged(m_brush);
    };
    for (QSpinBox* spin : {m_radius, m_hardness, m_opacity})
        connect(spin, &QSpinBox::valueChanged, this, changed);

    addSeparator();
    auto* targetLabel = new QLabel(tr("Paint &into"), this);
    targetLabel->setContentsMargins(2, 0, 2, 0);
    addWidget(targetLabel);
    m_target = new QComboBox(this);
    m_target->setObjectName(QStringLiteral("paintTarget"));
    m_targetTip = tr("Where paint goes: a texture (meshes with UVs) or vertex colours. "
                     "Changing it starts the painting afresh.");
    m_target->setToolTip(m_targetTip);
    targetLabel->setBuddy(m_target);
    addWidget(m_target);
    connect(m_target, &QComboBox::activated, this, [this](int index) {
        if (m_updating)
            return;
        core::PaintTargetOptions options;
        const int choice = m_target->itemData(index).toInt();
        if (choice == kVertexColorsItem) {
            options.kind = core::PaintTargetKind::VertexColors;
        } else {
            options.kind = core::PaintTargetKind::Texture;
            options.resolution = choice;
            options.automaticUvs = m_target->itemData(index, kAutomaticRole).toBool();
        }
        emit targetRequested(options);
    });

    setBrush(m_brush);
    setTarget(core::PaintTargetOptions{}, nullptr);
}

void BrushToolBar::setBrush(const core::Brush& brush) {
    const QScopedValueRollback guard(m_updating, true);
    m_brush = brush;
    m_radius->setValue(int(std::lround(brush.radius)));
    m_hardness->setValue(int(std::lround(brush.hardness * 100.0f)));
    m_opacity->setValue(int(std::lround(brush.opacity * 100.0f)));
    updateColorIcon();
}

void BrushToolBar::setTarget(const core::PaintTargetOptions& options, const core::Mesh* mesh,
                             const std::vector<core::PageSize>& current) {
    const QScopedValueRollback guard(m_updating, true);
    const bool hasUvs = mesh == nullptr || mesh->hasUvs();
    const bool texture = options.kind ? *options.kind == core::PaintTargetKind::Texture : hasUvs;
    const bool automatic = !hasUvs || options.automaticUvs;
    std::vector<TargetItem> items = targetItems(options, mesh);
    if (texture && mesh != nullptr && current.size() == mesh->materials.size())
        showCurrentSizes(items, options, *mesh, usedOnly(current, *mesh));
    m_target->clear();
    int shown = -1;
    for (const TargetItem& item : items) {
        m_target->addItem(item.text, item.resolution);
        const int i = m_target->count() - 1;
        m_target->setItemData(i, item.automatic, kAutomaticRole);
        m_target->setItemData(i, item.tip, Qt::ToolTipRole);
        if (texture && item.automatic == automatic &&
            (shown < 0 || item.resolution == options.resolution))
            shown = i;
    }
    m_target->addItem(tr("Vertex colours"), kVertexColorsItem);
    m_target->setCurrentIndex(shown < 0 ? m_target->count() - 1 : shown);

    const QString why = tr("This model has no texture coordinates (UVs): a texture gets an "
                           "automatic UV layout; vertex colours follow its vertices.");
    QString tip = hasUvs ? m_targetTip : m_targetTip + QStringLiteral("\n\n") + why;
    if (shown >= 0 && !items[std::size_t(shown)].tip.isEmpty())
        tip += QStringLiteral("\n\n") + items[std::size_t(shown)].tip;
    m_target->setToolTip(tip);
}

void BrushToolBar::showCurrentSizes(std::vector<TargetItem>& items,
                                    const core::PaintTargetOptions& options, const core::Mesh& mesh,
                                    const std::vector<core::PageSize>& current) const {
    // The entry of the target in use names its sizes as they are now (a raised texture).
    const bool automatic = !mesh.hasUvs() || options.automaticUvs;
    for (TargetItem& item : items)
        if (item.automatic == automatic && item.resolution == options.resolution) {
            item.text = automatic ? tr("Texture %1, automatic UVs").arg(sizesText(current))
                                  : tr("Texture %1").arg(sizesText(current));
            if (!automatic)
                item.tip = sizesTip(current, mesh, false);
            return;
        }
}

std::vector<BrushToolBar::TargetItem>
BrushToolBar::targetItems(const core::PaintTargetOptions& options, const core::Mesh* mesh) const {
    const bool hasUvs = mesh == nullptr || mesh->hasUvs();
    std::vector<TargetItem> items;
    // The mesh's own UVs: one entry per distinct set of sizes (the resolution only sizes the
    // materials without a base colour texture; with none such, one entry says it all).
    for (int resolution : kResolutions) {
        if (!hasUvs)
            break;
        core::PaintTargetOptions texture = options;
        texture.resolution = resolution;
        texture.automaticUvs = false;
        const std::vector<core::PageSize> sizes =
            mesh ? usedOnly(core::texturePageSizes(*mesh, texture), *mesh)
                 : std::vector<core::PageSize>{{resolution, resolution}};
        TargetItem item{tr("Texture %1").arg(sizesText(sizes)),
                        mesh ? sizesTip(sizes, *mesh, false) : QString(), resolution, false};
        if (!items.empty() && items.back().text == item.text) {
            if (resolution == options.resolution)
                items.back().resolution = resolution;
            continue;
        }
        items.push_back(std::move(item));
    }
    // An automatic layout: one new page for all materials, offered for any mesh.
    for (int resolution : kResolutions)
        items.push_back({tr("Texture %1 × %1, automatic UVs").arg(resolution),
                         tr("A new texture of %1 × %1 texels over an automatic UV layout: "
                            "places that share UVs are painted apart.")
                             .arg(resolution),
                         resolution, true});
    return items;
}

QString BrushToolBar::sizesText(const std::vector<core::PageSize>& all) const {
    std::vector<core::PageSize> sizes;
    std::copy_if(all.begin(), all.end(), std::back_inserter(sizes),
                 [](const core::PageSize& s) { return s.width > 0; });
    if (sizes.empty())
        return QString();
    const auto area = [](const core::PageSize& s) { return qint64(s.width) * s.height; };
    const auto [smallest, largest] =
        std::minmax_element(sizes.begin(), sizes.end(), [&area](const auto& a, const auto& b) {
            return area(a) < area(b) || (area(a) == area(b) && a.width < b.width);
        });
    const QString low = tr("%1 × %2").arg(smallest->width).arg(smallest->height);
    if (*smallest == *largest)
        return low;
    return tr("%1 – %2").arg(low, tr("%1 × %2").arg(largest->width).arg(largest->height));
}

QString BrushToolBar::sizesTip(const std::vector<core::PageSize>& sizes, const core::Mesh& mesh,
                               bool automatic) const {
    QStringList lines;
    const auto used = std::count_if(sizes.begin(), sizes.end(),
                                    [](const core::PageSize& s) { return s.width > 0; });
    for (std::size_t m = 0; m < sizes.size() && m < mesh.materials.size(); ++m) {
        if (sizes[m].width <= 0)
            continue;
        if (lines.size() == kMaxTipMaterials) {
            lines.append(tr("… and %n more material(s)", nullptr, int(used) - kMaxTipMaterials));
            break;
        }
        const core::Material& material = mesh.materials[m];
        const QString name = material.name.empty() ? tr("material %1").arg(m + 1)
                                                   : QString::fromStdString(material.name);
        const QString size = tr("%1 × %2").arg(sizes[m].width).arg(sizes[m].height);
        const bool own = !automatic && material.baseColorTexture >= 0 &&
                         std::size_t(material.baseColorTexture) < mesh.textures.size();
        lines.append(own ? tr("%1: %2 (its base colour texture)").arg(name, size)
                         : tr("%1: %2 (a new texture)").arg(name, size));
    }
    return lines.isEmpty()
               ? QString()
               : tr("Painted into:") + QLatin1Char('\n') + lines.join(QLatin1Char('\n'));
}

QColor BrushToolBar::toQColor(const glm::vec4& linear) {
    return QColor::fromRgb(core::linearToSrgb(linear.r), core::linearToSrgb(linear.g),
                           core::linearToSrgb(linear.b));
}

glm::vec4 BrushToolBar::toLinear(const QColor& color) {
    const QColor rgb = color.toRgb();
    return {core::srgbToLinear(std::uint8_t(rgb.red())),
            core::srgbToLinear(std::uint8_t(rgb.green())),
            core::srgbToLinear(std::uint8_t(rgb.blue())), 1.0f};
}

void BrushToolBar::chooseColor() {
    const QColor color = QColorDialog::getColor(toQColor(m_brush.color), this, tr("Brush Colour"));
    if (!color.isValid())
        return;
    m_brush.color = toLinear(color);
    updateColorIcon();
    emit brushChanged(m_brush);
}

void BrushToolBar::updateColorIcon() {
    QPixmap swatch(20, 20);
    swatch.fill(Qt::transparent);
    QPainter painter(&swatch);
    painter.setRenderHint(QPainter::Antialiasing);
    painter.setPen(QPen(palette().color(QPalette::WindowText), 1.0));
    painter.setBrush(toQColor(m_brush.color));
    painter.drawRoundedRect(QRectF(1.5, 1.5, 17, 17), 3, 3);
    painter.end();
    m_color->setIcon(QIcon(swatch));
}

} // namespace ui
