// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/panels/brush_presets_panel.h"

#include <cmath>

#include <QAction>
#include <QColor>
#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QGridLayout>
#include <QIcon>
#include <QInputDialog>
#include <QLineEdit>
#include <QLinearGradient>
#include <QListWidget>
#include <QMenu>
#include <QPainter>
#include <QPixmap>
#include <QPushButton>
#include <QRegularExpression>
#include <QSaveFile>
#include <QSettings>
#include <QVBoxLayout>

#include "core/base/color.h"
#include "core/io/project/project_file_tip.h"
#include "core/paint/brush/brush_preview.h"

namespace ui {

namespace {

const QString kListKey = QStringLiteral("brushPresets/list");
const QString kSeededKey = QStringLiteral("brushPresets/seeded");
const QString kDirKey = QStringLiteral("brushPresets/lastFolder");
constexpr QSize kPreviewSize(96, 40);
constexpr qint64 kMaxPresetFileBytes = 1 << 20;

/** The starter presets' names as shown (core names them in English). */
QString starterName(const std::string& name) {
    static const char* const names[] = {
        QT_TRANSLATE_NOOP("BrushPresetsPanel", "Soft Round"),
        QT_TRANSLATE_NOOP("BrushPresetsPanel", "Hard Ink"),
        QT_TRANSLATE_NOOP("BrushPresetsPanel", "Chalk"),
        QT_TRANSLATE_NOOP("BrushPresetsPanel", "Spatter"),
        QT_TRANSLATE_NOOP("BrushPresetsPanel", "Metal Paint"),
        QT_TRANSLATE_NOOP("BrushPresetsPanel", "Rough Matte"),
        QT_TRANSLATE_NOOP("BrushPresetsPanel", "Eraser Soft"),
        QT_TRANSLATE_NOOP("BrushPresetsPanel", "Stabilized Liner"),
    };
    for (const char* known : names)
        if (name == known)
            return QCoreApplication::translate("BrushPresetsPanel", known);
    return QString::fromStdString(name);
}

core::Result<std::shared_ptr<const core::TipImage>> loadTip(const std::string& path) {
    return core::loadTipImageFile(path);
}

} // namespace

BrushPresetsPanel::BrushPresetsPanel(std::function<core::Brush()> current, QWidget* parent)
    : QWidget(parent), m_current(std::move(current)) {
    m_list = new QListWidget(this);
    m_list->setObjectName(QStringLiteral("brushPresetList"));
    m_list->setViewMode(QListView::IconMode);
    m_list->setIconSize(kPreviewSize);
    m_list->setGridSize(kPreviewSize + QSize(16, 28));
    m_list->setResizeMode(QListView::Adjust);
    m_list->setMovement(QListView::Static);
    m_list->setWordWrap(true);
    m_list->setUniformItemSizes(true);
    m_list->setSelectionMode(QAbstractItemView::SingleSelection);
    m_list->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed);
    m_list->setContextMenuPolicy(Qt::CustomContextMenu);
    m_list->setMinimumHeight(2 * m_list->gridSize().height() + 8);

    const auto button = [this](const QString& text, const QString& tip, const QString& name) {
        auto* b = new QPushButton(text, this);
        b->setToolTip(tip);
        b->setObjectName(name);
        return b;
    };
    m_newButton = button(tr("New from Current"), tr("Save the current brush as a preset"),
                         QStringLiteral("presetNewButton"));
    m_renameButton =
        button(tr("Rename"), tr("Rename the chosen preset"), QStringLiteral("presetRenameButton"));
    m_deleteButton =
        button(tr("Delete"), tr("Delete the chosen preset"), QStringLiteral("presetDeleteButton"));
    m_importButton = button(tr("Import…"), tr("Add a preset from a .lpbrush file"),
                            QStringLiteral("presetImportButton"));
    m_exportButton = button(tr("Export…"), tr("Write the chosen preset to a .lpbrush file"),
                            QStringLiteral("presetExportButton"));

    auto* buttons = new QGridLayout;
    buttons->addWidget(m_newButton, 0, 0, 1, 2);
    buttons->addWidget(m_renameButton, 1, 0);
    buttons->addWidget(m_deleteButton, 1, 1);
    buttons->addWidget(m_importButton, 2, 0);
    buttons->addWidget(m_exportButton, 2, 1);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_list, 1);
    layout->addLayout(buttons);

    connect(m_list, &QListWidget::itemClicked, this,
            [this](QListWidgetItem* item) { choose(m_list->row(item)); });
    connect(m_list, &QListWidget::itemChanged, this, [this](QListWidgetItem* item) {
        if (m_rebuilding)
            return;
        const int row = m_list->row(item);
        if (row >= 0 && std::size_t(row) < m_presets.size() &&
            item->text().toStdString() != m_presets[std::size_t(row)].name &&
            !renamePreset(row, item->text()))
            rebuild(row); // an empty name: back to the old one
    });
    connect(m_list, &QListWidget::currentRowChanged, this, [this] { updateButtons(); });
    connect(m_newButton, &QPushButton::clicked, this, [this] { askNewFromCurrent(); });
    connect(m_renameButton, &QPushButton::clicked, this, [this] {
        if (QListWidgetItem* item = m_list->currentItem())
            m_list->editItem(item);
    });
    connect(m_deleteButton, &QPushButton::clicked, this, [this] { deletePreset(currentRow()); });
    connect(m_importButton, &QPushButton::clicked, this, [this] { askImport(); });
    connect(m_exportButton, &QPushButton::clicked, this, [this] { askExport(); });
    connect(m_list, &QListWidget::customContextMenuRequested, this, [this](const QPoint& at) {
        if (QListWidgetItem* item = m_list->itemAt(at))
            m_list->setCurrentItem(item);
        QMenu menu(this);
        menu.addAction(m_newButton->text(), this, [this] { askNewFromCurrent(); });
        const bool chosen = currentRow() >= 0;
        menu.addAction(m_renameButton->text(), this,
                       [this] {
                           if (QListWidgetItem* item = m_list->currentItem())
                               m_list->editItem(item);
                       })
            ->setEnabled(chosen);
        menu.addAction(m_deleteButton->text(), this, [this] { deletePreset(currentRow()); })
            ->setEnabled(chosen);
        menu.addSeparator();
        menu.addAction(m_importButton->text(), this, [this] { askImport(); });
        menu.addAction(m_exportButton->text(), this, [this] { askExport(); })->setEnabled(chosen);
        menu.exec(m_list->viewport()->mapToGlobal(at));
    });

    load();
    rebuild(-1);
}

QImage BrushPresetsPanel::preview(const core::Brush& brush, QSize size) {
    const std::vector<std::uint8_t> cover =
        core::renderBrushPreview(brush, size.width(), size.height());
    QImage image(size, QImage::Format_ARGB32_Premultiplied);
    // What the stroke shows: the colour it paints; roughness alone as its grey; an eraser as
    // light paint taken off a grey ground.
    QColor ink =
        QColor::fromRgb(core::linearToSrgb(brush.color.r), core::linearToSrgb(brush.color.g),
                        core::linearToSrgb(brush.color.b));
    if (!brush.paintBaseColor)
        ink = QColor::fromRgbF(brush.roughness, brush.roughness, brush.roughness);
    if (brush.eraser) {
        image.fill(QColor(128, 128, 128));
        ink = QColor(240, 240, 240);
    } else {
        image.fill(QColor(250, 250, 250));
    }
    for (int y = 0; y < size.height(); ++y) {
        auto* row = reinterpret_cast<QRgb*>(image.scanLine(y));
        for (int x = 0; x < size.width(); ++x) {
            const float a = float(cover[std::size_t(y) * std::size_t(size.width()) + x]) / 255.0f;
            const QColor under = QColor::fromRgb(row[x]);
            row[x] = qRgb(int(std::lround(under.red() + (ink.red() - under.red()) * a)),
                          int(std::lround(under.green() + (ink.green() - under.green()) * a)),
                          int(std::lround(under.blue() + (ink.blue() - under.blue()) * a)));
        }
    }
    if (brush.paintMetallic && brush.metallic > 0.0f) {
        // A metallic brush: a sheen line along the preview's top.
        QPainter painter(&image);
        QLinearGradient sheen(0, 0, size.width(), 0);
        sheen.setColorAt(0.0, QColor(255, 255, 255, 0));
        sheen.setColorAt(0.5, QColor(255, 255, 255, 200));
        sheen.setColorAt(1.0, QColor(255, 255, 255, 0));
        painter.fillRect(QRect(0, 0, size.width(), 3), sheen);
    }
    return image;
}

void BrushPresetsPanel::load() {
    QSettings settings;
    m_presets.clear();
    if (!settings.value(kSeededKey, false).toBool()) {
        for (core::BrushPreset preset : core::starterBrushPresets()) {
            preset.name = starterName(preset.name).toStdString();
            m_presets.push_back(std::move(preset));
        }
        save();
        return;
    }
    for (const QString& text : settings.value(kListKey).toStringList()) {
        // An entry that no longer reads (say a tip file that went) is left out.
        const nlohmann::json value = nlohmann::json::parse(text.toStdString(), nullptr, false);
        if (core::Result<core::BrushPreset> preset = core::brushPresetFromJson(value, loadTip))
            m_presets.push_back(std::move(preset).value());
    }
}

void BrushPresetsPanel::save() const {
    QStringList list;
    for (const core::BrushPreset& preset : m_presets)
        list.push_back(QString::fromStdString(core::brushPresetToJson(preset).dump()));
    QSettings settings;
    settings.setValue(kListKey, list);
    settings.setValue(kSeededKey, true);
}

void BrushPresetsPanel::rebuild(int selectRow) {
    m_rebuilding = true;
    m_list->clear();
    for (const core::BrushPreset& preset : m_presets) {
        auto* item =
            new QListWidgetItem(QIcon(QPixmap::fromImage(preview(preset.brush, kPreviewSize))),
                                QString::fromStdString(preset.name), m_list);
        item->setFlags(item->flags() | Qt::ItemIsEditable);
        item->setToolTip(QString::fromStdString(preset.name));
    }
    if (selectRow >= 0 && selectRow < m_list->count())
        m_list->setCurrentRow(selectRow);
    m_rebuilding = false;
    updateButtons();
}

int BrushPresetsPanel::currentRow() const {
    QListWidgetItem* item = m_list->currentItem();
    return item && item->isSelected() ? m_list->row(item) : -1;
}

void BrushPresetsPanel::updateButtons() {
    const bool chosen = m_list->currentRow() >= 0;
    m_renameButton->setEnabled(chosen);
    m_deleteButton->setEnabled(chosen);
    m_exportButton->setEnabled(chosen);
}

bool BrushPresetsPanel::addFromCurrent(const QString& name) {
    const QString trimmed = name.trimmed();
    if (trimmed.isEmpty() || !m_current)
        return false;
    m_presets.push_back({trimmed.toStdString().substr(0, core::kMaxPresetNameBytes), m_current()});
    save();
    rebuild(int(m_presets.size()) - 1);
    return true;
}

bool BrushPresetsPanel::renamePreset(int row, const QString& name) {
    const QString trimmed = name.trimmed();
    if (row < 0 || std::size_t(row) >= m_presets.size() || trimmed.isEmpty())
        return false;
    m_presets[std::size_t(row)].name = trimmed.toStdString().substr(0, core::kMaxPresetNameBytes);
    save();
    rebuild(row);
    return true;
}

bool BrushPresetsPanel::deletePreset(int row) {
    if (row < 0 || std::size_t(row) >= m_presets.size())
        return false;
    m_presets.erase(m_presets.begin() + row);
    save();
    rebuild(std::min(row, int(m_presets.size()) - 1));
    return true;
}

bool BrushPresetsPanel::importFile(const QString& path) {
    const QString shown = QFileInfo(path).fileName();
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        emit errorOccurred(tr("%1: cannot be opened (%2)").arg(shown, file.errorString()));
        return false;
    }
    if (file.size() > kMaxPresetFileBytes) {
        emit errorOccurred(tr("%1: too large for a brush preset").arg(shown));
        return false;
    }
    const QByteArray bytes = file.read(kMaxPresetFileBytes + 1);
    core::Result<core::BrushPreset> preset = core::parseBrushPresetFile(
        bytes.toStdString(), shown.toStdString(), [&path](const std::string& tip) {
            // A tip named by a relative path lies beside the preset file.
            const QString tipPath =
                QFileInfo(QString::fromStdString(tip)).isAbsolute()
                    ? QString::fromStdString(tip)
                    : QFileInfo(path).dir().filePath(QString::fromStdString(tip));
            return loadTip(tipPath.toStdString());
        });
    if (!preset) {
        emit errorOccurred(QString::fromStdString(preset.error()));
        return false;
    }
    m_presets.push_back(std::move(preset).value());
    save();
    rebuild(int(m_presets.size()) - 1);
    return true;
}

bool BrushPresetsPanel::exportFile(int row, const QString& path) {
    if (row < 0 || std::size_t(row) >= m_presets.size())
        return false;
    const QString shown = QFileInfo(path).fileName();
    const QByteArray bytes =
        QByteArray::fromStdString(core::brushPresetToJson(m_presets[std::size_t(row)]).dump(2)) +
        '\n';
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly) || file.write(bytes) != bytes.size() || !file.commit()) {
        emit errorOccurred(tr("%1: cannot be written (%2)").arg(shown, file.errorString()));
        return false;
    }
    return true;
}

void BrushPresetsPanel::choose(int row) {
    if (row < 0 || std::size_t(row) >= m_presets.size())
        return;
    const core::BrushPreset& preset = m_presets[std::size_t(row)];
    emit presetChosen(preset.brush, QString::fromStdString(preset.name));
}

void BrushPresetsPanel::askNewFromCurrent() {
    bool ok = false;
    const QString name = QInputDialog::getText(this, tr("New Brush Preset"), tr("Name:"),
                                               QLineEdit::Normal, tr("My Brush"), &ok);
    if (ok)
        addFromCurrent(name);
}

void BrushPresetsPanel::askImport() {
    QSettings settings;
    const QString path = QFileDialog::getOpenFileName(
        this, tr("Import Brush Preset"), settings.value(kDirKey).toString(),
        tr("Brush presets (*.lpbrush);;All files (*)"));
    if (path.isEmpty())
        return;
    settings.setValue(kDirKey, QFileInfo(path).absolutePath());
    importFile(path);
}

void BrushPresetsPanel::askExport() {
    const int row = currentRow();
    if (row < 0)
        return;
    QSettings settings;
    QString name = QString::fromStdString(m_presets[std::size_t(row)].name);
    name.replace(QRegularExpression(QStringLiteral("[/\\\\:*?\"<>|]")), QStringLiteral("_"));
    const QString start =
        QDir(settings.value(kDirKey).toString()).filePath(name + QStringLiteral(".lpbrush"));
    const QString path = QFileDialog::getSaveFileName(this, tr("Export Brush Preset"), start,
                                                      tr("Brush presets (*.lpbrush)"));
    if (path.isEmpty())
        return;
    settings.setValue(kDirKey, QFileInfo(path).absolutePath());
    exportFile(row, path);
}

} // namespace ui
