// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/shell/preferences.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>
#include <QSettings>
#include <QSpinBox>
#include <QVBoxLayout>

#include <algorithm>
#include <iterator>

#include "core/paint/brush/dab.h"

namespace ui {

const QString Preferences::kUndoBudgetKey = QStringLiteral("paint/undoBudgetMiB");
const QString Preferences::kTextureSizeKey = QStringLiteral("paint/textureSize");
const QString Preferences::kPressureGammaKey = QStringLiteral("paint/pressureGamma");
const QString Preferences::kCameraMappingKey = QStringLiteral("view/cameraMapping");
const QString Preferences::kLanguageKey = QStringLiteral("ui/language");
const QString Preferences::kAutosaveMinutesKey = QStringLiteral("autosave/intervalMinutes");

namespace {
constexpr int kTextureSizes[] = {512, 1024, 2048, 4096, 8192};

const char* mappingName(CameraMapping mapping) {
    switch (mapping) {
    case CameraMapping::Blender:
        return "blender";
    case CameraMapping::AltBased:
        return "alt";
    case CameraMapping::Both:
        break;
    }
    return "both";
}

bool isLanguage(const QString& code) {
    return code.isEmpty() || code == QLatin1String("en") || code == QLatin1String("de") ||
           code == QLatin1String("zh_CN");
}
} // namespace

Preferences Preferences::load() {
    const QSettings settings;
    Preferences p;
    bool ok = false;
    const int budget = settings.value(kUndoBudgetKey, p.undoBudgetMiB).toInt(&ok);
    if (ok && budget >= kMinUndoBudgetMiB && budget <= kMaxUndoBudgetMiB)
        p.undoBudgetMiB = budget;
    const int size = settings.value(kTextureSizeKey, p.textureSize).toInt(&ok);
    if (ok && std::find(std::begin(kTextureSizes), std::end(kTextureSizes), size) !=
                  std::end(kTextureSizes))
        p.textureSize = size;
    const double gamma = settings.value(kPressureGammaKey, double(p.pressureGamma)).toDouble(&ok);
    if (ok && gamma >= core::PressureCurve::kMinGamma && gamma <= core::PressureCurve::kMaxGamma)
        p.pressureGamma = float(gamma);
    const QString mapping = settings.value(kCameraMappingKey).toString();
    for (const CameraMapping m :
         {CameraMapping::Both, CameraMapping::Blender, CameraMapping::AltBased})
        if (mapping == QLatin1String(mappingName(m)))
            p.cameraMapping = m;
    const QString language = settings.value(kLanguageKey).toString();
    if (isLanguage(language))
        p.language = language;
    const int minutes = settings.value(kAutosaveMinutesKey, p.autosaveMinutes).toInt(&ok);
    if (ok && minutes >= 0 && minutes <= kMaxAutosaveMinutes)
        p.autosaveMinutes = minutes;
    return p;
}

void Preferences::save() const {
    QSettings settings;
    settings.setValue(kUndoBudgetKey, undoBudgetMiB);
    settings.setValue(kTextureSizeKey, textureSize);
    settings.setValue(kPressureGammaKey, double(pressureGamma));
    settings.setValue(kCameraMappingKey, QString::fromLatin1(mappingName(cameraMapping)));
    settings.setValue(kLanguageKey, language);
    settings.setValue(kAutosaveMinutesKey, autosaveMinutes);
}

PreferencesDialog::PreferencesDialog(const Preferences& preferences, QWidget* parent)
    : QDialog(parent) {
    setObjectName(QStringLiteral("preferencesDialog"));
    setWindowTitle(tr("Preferences"));
    auto* form = new QFormLayout;

    m_undoBudget = new QSpinBox(this);
    m_undoBudget->setObjectName(QStringLiteral("undoBudget"));
    m_undoBudget->setRange(Preferences::kMinUndoBudgetMiB, Preferences::kMaxUndoBudgetMiB);
    m_undoBudget->setSuffix(tr(" MiB"));
    m_undoBudget->setValue(preferences.undoBudgetMiB);
    m_undoBudget->setToolTip(tr("The most memory undo keeps; the oldest strokes are forgotten "
                                "beyond it"));
    form->addRow(tr("&Undo memory:"), m_undoBudget);

    m_textureSize = new QComboBox(this);
    m_textureSize->setObjectName(QStringLiteral("textureSize"));
    for (const int size : kTextureSizes) {
        m_textureSize->addItem(tr("%1 × %1").arg(size), size);
        if (size == preferences.textureSize)
            m_textureSize->setCurrentIndex(m_textureSize->count() - 1);
    }
    m_textureSize->setToolTip(tr("The size of a new texture for models without one to paint "
                                 "(used from the next model on)"));
    form->addRow(tr("New &texture size:"), m_textureSize);

    m_pressureGamma = new QDoubleSpinBox(this);
    m_pressureGamma->setObjectName(QStringLiteral("pressureGamma"));
    m_pressureGamma->setRange(core::PressureCurve::kMinGamma, core::PressureCurve::kMaxGamma);
    m_pressureGamma->setSingleStep(0.1);
    m_pressureGamma->setDecimals(2);
    m_pressureGamma->setValue(preferences.pressureGamma);
    m_pressureGamma->setToolTip(tr("Pen pressure curve (pressure to the power of this): below 1 "
                                   "a light touch gives more, above 1 it takes a firm press"));
    form->addRow(tr("&Pressure curve:"), m_pressureGamma);

    m_cameraMapping = new QComboBox(this);
    m_cameraMapping->setObjectName(QStringLiteral("cameraMapping"));
    m_cameraMapping->addItem(tr("Both: the middle button and Alt with any button"),
                             int(CameraMapping::Both));
    m_cameraMapping->addItem(tr("Blender-like: middle drag orbits, Shift+middle pans"),
                             int(CameraMapping::Blender));
    m_cameraMapping->addItem(tr("Alt-based: Alt+left orbits, Alt+middle pans, Alt+right zooms"),
                             int(CameraMapping::AltBased));
    m_cameraMapping->setCurrentIndex(m_cameraMapping->findData(int(preferences.cameraMapping)));
    m_cameraMapping->setToolTip(tr("Which buttons move the camera; the wheel always zooms"));
    form->addRow(tr("&Camera buttons:"), m_cameraMapping);

    m_language = new QComboBox(this);
    m_language->setObjectName(QStringLiteral("language"));
    m_language->addItem(tr("System"), QString());
    // Each language in its own words, so it can be found whatever the current one.
    m_language->addItem(QStringLiteral("English"), QStringLiteral("en"));
    m_language->addItem(QStringLiteral("Deutsch"), QStringLiteral("de"));
    m_language->addItem(QStringLiteral("简体中文"), QStringLiteral("zh_CN"));
    m_language->setCurrentIndex(std::max(0, m_language->findData(preferences.language)));
    form->addRow(tr("&Language:"), m_language);
    auto* languageNote = new QLabel(tr("A new language applies after a restart."), this);
    languageNote->setEnabled(false); // shown as a quiet hint
    form->addRow(QString(), languageNote);

    m_autosave = new QSpinBox(this);
    m_autosave->setObjectName(QStringLiteral("autosaveMinutes"));
    m_autosave->setRange(0, Preferences::kMaxAutosaveMinutes);
    m_autosave->setSuffix(tr(" min"));
    m_autosave->setSpecialValueText(tr("Off"));
    m_autosave->setValue(preferences.autosaveMinutes);
    m_autosave->setToolTip(tr("How often a recovery copy of the work is saved; 0 turns it off"));
    form->addRow(tr("&Autosave every:"), m_autosave);

    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(buttons);
}

Preferences PreferencesDialog::preferences() const {
    Preferences p;
    p.undoBudgetMiB = m_undoBudget->value();
    p.textureSize = m_textureSize->currentData().toInt();
    p.pressureGamma = float(m_pressureGamma->value());
    p.cameraMapping = CameraMapping(m_cameraMapping->currentData().toInt());
    p.language = m_language->currentData().toString();
    p.autosaveMinutes = m_autosave->value();
    return p;
}

} // namespace ui
