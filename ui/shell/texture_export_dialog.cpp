// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/shell/texture_export_dialog.h"

#include <algorithm>

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QLocale>
#include <QPushButton>
#include <QSettings>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QVBoxLayout>

namespace ui {

namespace {

const QString kPresetKey = QStringLiteral("textureExport/preset");
const QString kPresetFilesKey = QStringLiteral("textureExport/presetFiles");
const QString kFormatKey = QStringLiteral("textureExport/format");
const QString kBitDepthKey = QStringLiteral("textureExport/bitDepth");
const QString kPaddingKey = QStringLiteral("textureExport/padding");
const QString kSizeKey = QStringLiteral("textureExport/size");

constexpr int kSizes[] = {0, 512, 1024, 2048, 4096, 8192};

std::string encodePath(const QString& path) {
    return QFile::encodeName(path).toStdString();
}

} // namespace

TextureExportDialog::TextureExportDialog(std::shared_ptr<const core::Mesh> mesh,
                                         const QString& meshName, const QString& folder,
                                         QWidget* parent)
    : QDialog(parent), m_mesh(std::move(mesh)), m_meshName(meshName) {
    setObjectName(QStringLiteral("textureExportDialog"));
    setWindowTitle(tr("Export Textures"));
    auto* layout = new QVBoxLayout(this);
    auto* form = new QFormLayout;
    layout->addLayout(form);
    buildPresetRow();
    form->addRow(tr("&Preset:"), m_preset);
    auto* folderRow = new QHBoxLayout;
    m_folder = new QLineEdit(QDir::toNativeSeparators(folder), this);
    m_folder->setObjectName(QStringLiteral("textureExportFolder"));
    auto* browse = new QPushButton(tr("&Browse…"), this);
    connect(browse, &QPushButton::clicked, this, &TextureExportDialog::browseFolder);
    folderRow->addWidget(m_folder, 1);
    folderRow->addWidget(browse);
    auto* folderLabel = new QLabel(tr("&Folder:"), this);
    folderLabel->setBuddy(m_folder);
    form->addRow(folderLabel, folderRow);
    buildFormatRows();
    form->addRow(tr("F&ormat:"), m_format);
    form->addRow(tr("&Bit depth:"), m_bitDepth);
    form->addRow(tr("&Normal map:"), m_normal);
    auto* paddingRow = new QHBoxLayout;
    paddingRow->addWidget(m_padding);
    paddingRow->addWidget(m_fill, 1);
    auto* paddingLabel = new QLabel(tr("Pa&dding:"), this);
    paddingLabel->setBuddy(m_padding);
    form->addRow(paddingLabel, paddingRow);
    form->addRow(tr("&Size:"), m_size);
    layout->addWidget(new QLabel(tr("Files to write:"), this));
    m_files = new QListWidget(this);
    m_files->setObjectName(QStringLiteral("textureExportFiles"));
    layout->addWidget(m_files, 1);
    m_problem = new QLabel(this);
    m_problem->setObjectName(QStringLiteral("textureExportProblem"));
    m_problem->setWordWrap(true);
    m_problem->setStyleSheet(QStringLiteral("color: #c62828"));
    m_problem->hide();
    layout->addWidget(m_problem);
    m_buttons = new QDialogButtonBox(QDialogButtonBox::Cancel, this);
    m_buttons->addButton(tr("&Export"), QDialogButtonBox::AcceptRole)
        ->setObjectName(QStringLiteral("textureExportButton"));
    connect(m_buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(m_buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    layout->addWidget(m_buttons);

    restoreSettings();
    connect(m_folder, &QLineEdit::textChanged, this, &TextureExportDialog::updateFiles);
    resize(560, 520);
}

void TextureExportDialog::buildPresetRow() {
    m_preset = new QComboBox(this);
    m_preset->setObjectName(QStringLiteral("textureExportPreset"));
    const QHash<QString, QString> names = {
        {QStringLiteral("gltf"), tr("glTF metallic-roughness")},
        {QStringLiteral("unreal"), tr("Unreal Engine")},
        {QStringLiteral("unity"), tr("Unity (URP, HDRP)")},
        {QStringLiteral("orm"), tr("ORM (Godot, Blender)")},
    };
    for (const core::ExportPreset& preset : core::builtinPresets()) {
        const QString id = QString::fromStdString(preset.id);
        m_presets.push_back(preset);
        m_presetFiles.append(QString());
        m_preset->addItem(names.value(id, QString::fromStdString(preset.name)), id);
    }
    m_preset->addItem(tr("From a Preset File…"));
    connect(m_preset, &QComboBox::activated, this, [this](int index) {
        if (index >= int(m_presets.size()))
            loadPresetFile();
    });
    connect(m_preset, &QComboBox::currentIndexChanged, this, &TextureExportDialog::choosePreset);
}

void TextureExportDialog::buildFormatRows() {
    m_format = new QComboBox(this);
    m_format->setObjectName(QStringLiteral("textureExportFormat"));
    m_format->addItem(tr("PNG"), int(core::MapFileFormat::Png));
    m_format->addItem(tr("TIFF"), int(core::MapFileFormat::Tiff));
    m_format->addItem(tr("OpenEXR"), int(core::MapFileFormat::Exr));
    m_format->addItem(tr("TGA"), int(core::MapFileFormat::Tga));
    m_bitDepth = new QComboBox(this);
    m_bitDepth->setObjectName(QStringLiteral("textureExportBitDepth"));
    m_normal = new QComboBox(this);
    m_normal->setObjectName(QStringLiteral("textureExportNormal"));
    m_normal->addItem(tr("OpenGL (Y up: glTF, Unity, Godot, Blender)"),
                      int(core::NormalConvention::OpenGl));
    m_normal->addItem(tr("DirectX (Y down: Unreal Engine)"), int(core::NormalConvention::DirectX));
    m_padding = new QSpinBox(this);
    m_padding->setObjectName(QStringLiteral("textureExportPadding"));
    m_padding->setRange(0, core::kMaxPadding);
    m_padding->setValue(16); // when Fill is turned off
    m_padding->setSuffix(tr(" texels"));
    m_padding->setToolTip(tr("How far the colours at the edges of the UV charts are grown into "
                             "the empty space, so that mipmaps show no seams"));
    m_fill = new QCheckBox(tr("Fill all empty space"), this);
    m_fill->setObjectName(QStringLiteral("textureExportFill"));
    connect(m_fill, &QCheckBox::toggled, m_padding, &QWidget::setDisabled);
    m_size = new QComboBox(this);
    m_size->setObjectName(QStringLiteral("textureExportSize"));
    for (const int size : kSizes)
        m_size->addItem(size == 0 ? tr("Each texture set's own")
                                  : tr("%1 × %1").arg(QLocale().toString(size)),
                        size);
    connect(m_format, &QComboBox::currentIndexChanged, this, &TextureExportDialog::updateBitDepths);
    for (QComboBox* box : {m_bitDepth, m_normal, m_size})
        connect(box, &QComboBox::currentIndexChanged, this, &TextureExportDialog::updateFiles);
    connect(m_padding, &QSpinBox::valueChanged, this, &TextureExportDialog::updateFiles);
    connect(m_fill, &QCheckBox::toggled, this, &TextureExportDialog::updateFiles);
}

void TextureExportDialog::choosePreset(int index) {
    if (index < 0 || index >= int(m_presets.size()))
        return;
    const core::ExportPreset& preset = m_presets[std::size_t(index)];
    // The preset's own format and conventions; the dialog's rows can change them.
    m_format->setCurrentIndex(m_format->findData(int(preset.format)));
    updateBitDepths();
    m_bitDepth->setCurrentIndex(std::max(0, m_bitDepth->findData(preset.bitDepth)));
    m_normal->setCurrentIndex(m_normal->findData(int(preset.normal)));
    m_fill->setChecked(preset.padding == core::kPadToFill);
    if (preset.padding != core::kPadToFill)
        m_padding->setValue(preset.padding);
    updateFiles();
}

void TextureExportDialog::updateBitDepths() {
    const auto format = core::MapFileFormat(m_format->currentData().toInt());
    const int previous = m_bitDepth->currentData().toInt();
    const QSignalBlocker blocker(m_bitDepth);
    m_bitDepth->clear();
    if (format == core::MapFileFormat::Exr) {
        m_bitDepth->addItem(tr("16-bit float (half)"), 16);
        m_bitDepth->addItem(tr("32-bit float"), 32);
    } else {
        m_bitDepth->addItem(tr("8-bit"), 8);
        if (format != core::MapFileFormat::Tga)
            m_bitDepth->addItem(tr("16-bit"), 16);
    }
    m_bitDepth->setCurrentIndex(std::max(0, m_bitDepth->findData(previous)));
    updateFiles();
}

core::TextureExportOptions TextureExportDialog::options() const {
    core::TextureExportOptions out;
    const int index = std::clamp(m_preset->currentIndex(), 0, int(m_presets.size()) - 1);
    out.preset = m_presets[std::size_t(index)];
    out.preset.format = core::MapFileFormat(m_format->currentData().toInt());
    out.preset.bitDepth = m_bitDepth->currentData().toInt();
    out.preset.normal = core::NormalConvention(m_normal->currentData().toInt());
    out.preset.padding = m_fill->isChecked() ? core::kPadToFill : m_padding->value();
    out.meshName = m_meshName.toStdString();
    out.size = m_size->currentData().toInt();
    return out;
}

QString TextureExportDialog::folder() const {
    return QDir::fromNativeSeparators(m_folder->text().trimmed());
}

QStringList TextureExportDialog::fileNames() const {
    QStringList out;
    for (int i = 0; i < m_files->count(); ++i)
        out.append(m_files->item(i)->text());
    return out;
}

void TextureExportDialog::updateFiles() {
    if (!m_files || !m_buttons)
        return;
    m_files->clear();
    QString problem;
    const core::Result<std::vector<std::string>> names =
        core::textureExportFileNames(*m_mesh, options());
    if (!names)
        problem = QString::fromStdString(names.error());
    else if (names->empty())
        problem = tr("The model has no texture set to export: it is painted with vertex colours.");
    else if (folder().isEmpty())
        problem = tr("Choose the folder to write the files into.");
    if (names)
        for (const std::string& name : *names)
            m_files->addItem(QString::fromStdString(name));
    m_problem->setText(problem);
    m_problem->setVisible(!problem.isEmpty());
    if (QPushButton* ok = m_buttons->findChild<QPushButton*>(QStringLiteral("textureExportButton")))
        ok->setEnabled(problem.isEmpty());
}

void TextureExportDialog::browseFolder() {
    const QString chosen =
        QFileDialog::getExistingDirectory(this, tr("Export Textures To"), folder());
    if (!chosen.isEmpty())
        m_folder->setText(QDir::toNativeSeparators(chosen));
}

void TextureExportDialog::loadPresetFile() {
    const QString path = QFileDialog::getOpenFileName(this, tr("Texture Export Preset"), folder(),
                                                      tr("Export presets (*.json)"));
    QString error;
    if (path.isEmpty() || !addPresetFile(path, &error)) {
        // Back to the first preset, saying why the file was refused.
        const QSignalBlocker blocker(m_preset);
        m_preset->setCurrentIndex(0);
        choosePreset(0);
        if (!error.isEmpty()) {
            m_problem->setText(error);
            m_problem->show();
        }
    }
}

bool TextureExportDialog::addPresetFile(const QString& path, QString* error) {
    core::Result<core::ExportPreset> preset = core::findPreset(encodePath(path));
    if (!preset) {
        if (error)
            *error = QString::fromStdString(preset.error());
        return false;
    }
    const int existing = int(m_presetFiles.indexOf(path));
    int index = existing;
    if (existing >= 0) {
        m_presets[std::size_t(existing)] = *preset;
    } else {
        index = int(m_presets.size());
        m_presets.push_back(*preset);
        m_presetFiles.append(path);
        m_preset->insertItem(index, QString::fromStdString(preset->name), path);
    }
    m_preset->setCurrentIndex(index);
    choosePreset(index);
    return true;
}

void TextureExportDialog::restoreSettings() {
    QSettings settings;
    for (const QString& file : settings.value(kPresetFilesKey).toStringList())
        if (QFileInfo::exists(file) && core::findPreset(encodePath(file)))
            addPresetFile(file);
    const int chosen = m_preset->findData(settings.value(kPresetKey, QStringLiteral("gltf")));
    m_preset->setCurrentIndex(std::max(0, chosen));
    choosePreset(m_preset->currentIndex());
    // The last export's format and padding, where it chose them.
    if (const int f = m_format->findData(settings.value(kFormatKey, -1)); f >= 0) {
        m_format->setCurrentIndex(f);
        m_bitDepth->setCurrentIndex(
            std::max(0, m_bitDepth->findData(settings.value(kBitDepthKey, 8))));
    }
    const QVariant padding = settings.value(kPaddingKey);
    if (padding.isValid()) {
        m_fill->setChecked(padding.toInt() == core::kPadToFill);
        if (padding.toInt() >= 0)
            m_padding->setValue(padding.toInt());
    }
    m_size->setCurrentIndex(std::max(0, m_size->findData(settings.value(kSizeKey, 0))));
    updateFiles();
}

void TextureExportDialog::saveSettings() const {
    QSettings settings;
    settings.setValue(kPresetKey, m_preset->currentData());
    QStringList files;
    for (const QString& file : m_presetFiles)
        if (!file.isEmpty())
            files.append(file);
    settings.setValue(kPresetFilesKey, files);
    const core::TextureExportOptions chosen = options();
    settings.setValue(kFormatKey, int(chosen.preset.format));
    settings.setValue(kBitDepthKey, chosen.preset.bitDepth);
    settings.setValue(kPaddingKey, chosen.preset.padding);
    settings.setValue(kSizeKey, chosen.size);
}

} // namespace ui
