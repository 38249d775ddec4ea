// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/panels/brush_tip_box.h"

#include <QComboBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QImage>
#include <QLabel>
#include <QListWidget>
#include <QMessageBox>
#include <QPixmap>
#include <QPushButton>
#include <QScopedValueRollback>
#include <QSettings>
#include <QSpinBox>
#include <QVBoxLayout>

#include <cmath>
#include <memory>
#include <utility>

#include "core/io/project/project_file_tip.h"
#include "ui/panels/value_spin_box.h"
#include "ui/shell/background_task.h"

namespace ui {

namespace {

constexpr int kPreviewSide = 40;
const QString kUserItem = QStringLiteral("user");

/** A preview of tip: dark where it paints, on white; round tips from the falloff. */
QIcon tipIcon(const core::Brush& brush) {
    QImage image(kPreviewSide, kPreviewSide, QImage::Format_RGB32);
    core::TipSampler sampler;
    const float r = 0.5f * float(kPreviewSide) - 1.0f;
    sampler.setup(brush.tipImage(), brush.tipHardness(), r, 0.0f);
    for (int y = 0; y < kPreviewSide; ++y)
        for (int x = 0; x < kPreviewSide; ++x) {
            const glm::vec2 o(float(x) + 0.5f - 0.5f * kPreviewSide,
                              float(y) + 0.5f - 0.5f * kPreviewSide);
            const int v = 255 - int(std::lround(255.0f * sampler.weight(o, std::hypot(o.x, o.y))));
            image.setPixel(x, y, qRgb(v, v, v));
        }
    return QIcon(QPixmap::fromImage(image));
}

QString tipLabel(std::string_view name) {
    if (name == "round")
        return BrushTipBox::tr("Round");
    if (name == "round-soft")
        return BrushTipBox::tr("Round soft");
    if (name == "round-hard")
        return BrushTipBox::tr("Round hard");
    if (name == "square")
        return BrushTipBox::tr("Square");
    if (name == "spatter")
        return BrushTipBox::tr("Spatter");
    if (name == "chalk")
        return BrushTipBox::tr("Chalk");
    if (name == "bristle")
        return BrushTipBox::tr("Bristle");
    if (name == "star")
        return BrushTipBox::tr("Star");
    if (name == "noise")
        return BrushTipBox::tr("Noise");
    return QString::fromStdString(std::string(name));
}

QString settingsKey(const char* name) {
    return QStringLiteral("brushTip/") + QLatin1String(name);
}

} // namespace

BrushTipBox::BrushTipBox(QWidget* parent) : QGroupBox(tr("Brush tip"), parent) {
    setObjectName(QStringLiteral("brushTipBox"));
    auto* layout = new QVBoxLayout(this);

    m_tips = new QListWidget(this);
    m_tips->setObjectName(QStringLiteral("brushTipList"));
    m_tips->setViewMode(QListView::IconMode);
    m_tips->setIconSize(QSize(kPreviewSide, kPreviewSide));
    m_tips->setGridSize(QSize(kPreviewSide + 24, kPreviewSide + 22));
    m_tips->setMovement(QListView::Static);
    m_tips->setResizeMode(QListView::Adjust);
    m_tips->setWrapping(true);
    m_tips->setMinimumHeight(2 * (kPreviewSide + 22) + 8);
    m_tips->setToolTip(tr("The tip's shape: every channel painted is weighted by it"));
    for (const std::string_view name : core::builtinTipNames()) {
        core::Brush b;
        b.tip = std::string(name);
        auto* item = new QListWidgetItem(tipIcon(b), tipLabel(name), m_tips);
        item->setData(Qt::UserRole, QString::fromStdString(b.tip));
        item->setToolTip(tipLabel(name));
    }
    layout->addWidget(m_tips);
    connect(m_tips, &QListWidget::currentItemChanged, this, [this] { readControls(); });

    m_load = new QPushButton(tr("Load T&ip…"), this);
    m_load->setObjectName(QStringLiteral("brushTipLoad"));
    m_load->setToolTip(tr("Use a PNG or TIFF image as the tip (dark paints); it is kept in the "
                          "project"));
    connect(m_load, &QPushButton::clicked, this, &BrushTipBox::chooseFile);
    auto* loadRow = new QHBoxLayout;
    loadRow->addWidget(m_load);
    loadRow->addStretch(1);
    layout->addLayout(loadRow);

    auto* form = new QFormLayout;
    layout->addLayout(form);
    m_angleMode = new QComboBox(this);
    m_angleMode->setObjectName(QStringLiteral("brushTipAngleMode"));
    m_angleMode->addItem(tr("Fixed"), int(core::TipAngleMode::Fixed));
    m_angleMode->addItem(tr("Follow the stroke"), int(core::TipAngleMode::Stroke));
    m_angleMode->addItem(tr("Random"), int(core::TipAngleMode::Random));
    m_angleMode->setToolTip(tr("How the tip is turned: by the angle, along the stroke's "
                               "direction plus the angle, or at random per dab"));
    form->addRow(tr("Tip tur&n"), m_angleMode);
    connect(m_angleMode, &QComboBox::currentIndexChanged, this, [this] { readControls(); });

    const auto spinRow = [&](const QString& label, const QString& name, int lo, int hi,
                             const QString& suffix, const QString& tip) {
        QSpinBox* spin = makeValueSpinBox(this, name, lo, hi, suffix, tip);
        QHBoxLayout* row = sliderRow(spin);
        form->addRow(label, row);
        if (auto* text = qobject_cast<QLabel*>(form->labelForField(row)))
            text->setBuddy(spin);
        connect(spin, &QSpinBox::valueChanged, this, [this] { readControls(); });
        return spin;
    };
    m_angle = spinRow(tr("&Angle"), QStringLiteral("brushTipAngle"), -180, 180, tr("°"),
                      tr("The tip's turn, clockwise"));
    m_jitterSize = spinRow(tr("Size &jitter"), QStringLiteral("brushTipJitterSize"), 0, 100,
                           tr(" %"), tr("Each dab is up to this much smaller, at random"));
    m_jitterOpacity =
        spinRow(tr("Opacit&y jitter"), QStringLiteral("brushTipJitterOpacity"), 0, 100, tr(" %"),
                tr("Each dab is up to this much more transparent, at random"));
    m_jitterAngle = spinRow(tr("An&gle jitter"), QStringLiteral("brushTipJitterAngle"), 0, 180,
                            tr("°"), tr("Each dab turns up to this far either way, at random"));
    m_jitterScatter =
        spinRow(tr("Scatt&er"), QStringLiteral("brushTipJitterScatter"), 0, 400, tr(" %"),
                tr("Each dab moves up to this far from the stroke, in per cent of the radius"));
    m_seed = makeValueSpinBox(this, QStringLiteral("brushTipSeed"), 0, 999999, QString(),
                              tr("The random jitter's seed: the same seed paints the same "
                                 "stroke again"));
    form->addRow(tr("See&d"), m_seed);
    connect(m_seed, &QSpinBox::valueChanged, this, [this] { readControls(); });

    show(m_tip);
}

BrushTipBox::~BrushTipBox() {
    m_pool.waitForDone();
}

void BrushTipBox::show(const core::Brush& brush) {
    const QScopedValueRollback guard(m_updating, true);
    const bool newUser = brush.userTip != m_tip.userTip;
    m_tip = brush;
    if (newUser)
        addUserItem();
    const QString tip = brush.tip == core::kUserTip && !brush.userTip
                            ? QStringLiteral("round")
                            : QString::fromStdString(brush.tip);
    for (int i = 0; i < m_tips->count(); ++i)
        if (m_tips->item(i)->data(Qt::UserRole).toString() == tip)
            m_tips->setCurrentRow(i);
    m_angleMode->setCurrentIndex(m_angleMode->findData(int(brush.angleMode)));
    m_angle->setValue(int(std::lround(brush.angle)));
    m_jitterSize->setValue(int(std::lround(brush.jitter.size * 100.0f)));
    m_jitterOpacity->setValue(int(std::lround(brush.jitter.opacity * 100.0f)));
    m_jitterAngle->setValue(int(std::lround(brush.jitter.angle)));
    m_jitterScatter->setValue(int(std::lround(brush.jitter.scatter * 100.0f)));
    m_seed->setValue(int(std::min<std::uint32_t>(brush.seed, 999999u)));
}

void BrushTipBox::addUserItem() {
    for (int i = 0; i < m_tips->count(); ++i)
        if (m_tips->item(i)->data(Qt::UserRole).toString() == kUserItem)
            delete m_tips->takeItem(i);
    if (!m_tip.userTip)
        return;
    core::Brush b = m_tip;
    b.tip = std::string(core::kUserTip);
    const QString name = QFileInfo(QString::fromStdString(m_tip.userTipName)).fileName();
    auto* item = new QListWidgetItem(tipIcon(b), name.isEmpty() ? tr("Loaded") : name, m_tips);
    item->setData(Qt::UserRole, kUserItem);
    item->setToolTip(QString::fromStdString(m_tip.userTipName));
}

void BrushTipBox::apply(core::Brush& brush) {
    if (m_chosenSpacing)
        brush.spacing = *std::exchange(m_chosenSpacing, std::nullopt);
    brush.tip = m_tip.tip;
    brush.angleMode = m_tip.angleMode;
    brush.angle = m_tip.angle;
    brush.jitter = m_tip.jitter;
    brush.seed = m_tip.seed;
    brush.userTip = m_tip.userTip;
    brush.userTipName = m_tip.userTipName;
}

void BrushTipBox::readControls() {
    if (m_updating)
        return;
    if (const QListWidgetItem* item = m_tips->currentItem()) {
        const std::string tip = item->data(Qt::UserRole).toString().toStdString();
        if (tip != m_tip.tip && core::isBuiltinTip(tip)) {
            // A tip chosen comes with the spacing, turn and jitter that make it look like itself.
            m_tip.chooseTip(tip);
            m_chosenSpacing = m_tip.spacing;
            show(m_tip);
            remember();
            emit changed();
            return;
        }
        m_tip.tip = tip;
    }
    m_tip.angleMode = core::TipAngleMode(m_angleMode->currentData().toInt());
    m_tip.angle = float(m_angle->value());
    m_tip.jitter.size = float(m_jitterSize->value()) / 100.0f;
    m_tip.jitter.opacity = float(m_jitterOpacity->value()) / 100.0f;
    m_tip.jitter.angle = float(m_jitterAngle->value());
    m_tip.jitter.scatter = float(m_jitterScatter->value()) / 100.0f;
    m_tip.seed = std::uint32_t(m_seed->value());
    remember();
    emit changed();
}

void BrushTipBox::remember() const {
    QSettings settings;
    // A loaded tip lives in the project; the settings keep built-in ones only.
    if (m_tip.tip != core::kUserTip)
        settings.setValue(settingsKey("tip"), QString::fromStdString(m_tip.tip));
    settings.setValue(settingsKey("angleMode"), QString(core::tipAngleModeName(m_tip.angleMode)));
    settings.setValue(settingsKey("angle"), double(m_tip.angle));
    settings.setValue(settingsKey("jitterSize"), double(m_tip.jitter.size));
    settings.setValue(settingsKey("jitterOpacity"), double(m_tip.jitter.opacity));
    settings.setValue(settingsKey("jitterAngle"), double(m_tip.jitter.angle));
    settings.setValue(settingsKey("jitterScatter"), double(m_tip.jitter.scatter));
    settings.setValue(settingsKey("seed"), m_tip.seed);
}

void BrushTipBox::restore(core::Brush& brush) const {
    const QSettings settings;
    const auto number = [&](const char* key, float fallback, float lo, float hi) {
        bool ok = false;
        const double v = settings.value(settingsKey(key), double(fallback)).toDouble(&ok);
        return ok && std::isfinite(v) ? std::clamp(float(v), lo, hi) : fallback;
    };
    const std::string tip = settings.value(settingsKey("tip")).toString().toStdString();
    if (core::isBuiltinTip(tip))
        brush.tip = tip;
    core::tipAngleModeFromName(settings.value(settingsKey("angleMode")).toString().toStdString(),
                               brush.angleMode);
    brush.angle = number("angle", brush.angle, -180.0f, 180.0f);
    brush.jitter.size = number("jitterSize", brush.jitter.size, 0.0f, 1.0f);
    brush.jitter.opacity = number("jitterOpacity", brush.jitter.opacity, 0.0f, 1.0f);
    brush.jitter.angle = number("jitterAngle", brush.jitter.angle, 0.0f, 180.0f);
    brush.jitter.scatter = number("jitterScatter", brush.jitter.scatter, 0.0f, 4.0f);
    brush.seed =
        std::uint32_t(std::clamp(settings.value(settingsKey("seed"), 0u).toUInt(), 0u, 999999u));
}

void BrushTipBox::chooseFile() {
    const QString path = QFileDialog::getOpenFileName(
        this, tr("Load Brush Tip"), QString(), tr("Images (*.png *.tif *.tiff);;All files (*)"));
    if (path.isEmpty())
        return;
    connect(
        this, &BrushTipBox::loadFailed, this,
        [this](const QString& message) {
            QMessageBox::warning(this, tr("Load Brush Tip"), message);
        },
        Qt::SingleShotConnection);
    loadTip(path);
}

void BrushTipBox::loadTip(const QString& path) {
    m_load->setEnabled(false);
    struct Outcome {
        core::Result<std::shared_ptr<const core::TipImage>> tip = core::Error{"not loaded"};
    };
    auto outcome = std::make_shared<Outcome>();
    const std::string file = path.toStdString();
    runInBackground(
        m_pool, this,
        [outcome, file](const core::ProgressFn&) {
            try {
                outcome->tip = core::loadTipImageFile(file);
            } catch (const std::exception& e) {
                outcome->tip = core::Error{file + ": " + e.what()};
            }
        },
        [this, outcome, file] {
            m_load->setEnabled(true);
            if (!outcome->tip) {
                emit loadFailed(QString::fromStdString(outcome->tip.error()));
                return;
            }
            core::Brush b = m_tip;
            b.userTip = std::move(outcome->tip).value();
            b.userTipName = file;
            b.tip = std::string(core::kUserTip);
            show(b);
            readControls();
        });
}

} // namespace ui
