// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/panels/segmentation_controls.h"

#include <QCheckBox>
#include <QComboBox>
#include <QEvent>
#include <QFontMetrics>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QKeyEvent>
#include <QLabel>
#include <QLocale>
#include <QSignalBlocker>
#include <QSlider>
#include <QToolButton>

#include <algorithm>
#include <cmath>

namespace ui {

namespace {
const int kDecades = int(std::lround(
    std::log10(SegmentationControls::kMaxThreshold / SegmentationControls::kMinThreshold)));
} // namespace

SegmentationControls::SegmentationControls(QWidget* parent) : QWidget(parent) {
    m_threshold = new QSlider(Qt::Horizontal, this);
    m_threshold->setObjectName(QStringLiteral("thresholdSlider"));
    m_threshold->setRange(0, kDecades * kStepsPerDecade);
    m_threshold->setSingleStep(1);
    m_threshold->setPageStep(kStepsPerDecade / 5);
    m_threshold->setTickPosition(QSlider::TicksBelow);
    m_threshold->setTickInterval(kStepsPerDecade);
    m_threshold->installEventFilter(this);
    m_threshold->setAccessibleName(tr("Depth threshold"));
    m_threshold->setToolTip(
        tr("How far apart in depth two neighbouring pixels may be and still count as one "
           "surface, as a fraction of the model's longest side.\n"
           "Smaller splits the view into more regions."));

    m_thresholdValue = new QLabel(this);
    m_thresholdValue->setObjectName(QStringLiteral("thresholdValue"));
    m_thresholdValue->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
    // Wide enough for the longest value, so the slider does not jump while it moves.
    m_thresholdValue->setMinimumWidth(
        QFontMetrics(m_thresholdValue->font()).horizontalAdvance(formatThreshold(1.5e-5f)) + 4);

    auto* reset = new QToolButton(this);
    reset->setObjectName(QStringLiteral("thresholdReset"));
    reset->setText(tr("Reset"));
    reset->setToolTip(tr("Back to the default threshold (%1)")
                          .arg(formatThreshold(core::DepthLayerOptions{}.threshold)));
    reset->setAutoRaise(true);

    auto* thresholdRow = new QHBoxLayout;
    thresholdRow->setContentsMargins(0, 0, 0, 0);
    thresholdRow->addWidget(m_threshold, 1);
    thresholdRow->addWidget(m_thresholdValue);
    thresholdRow->addWidget(reset);

    m_test = new QComboBox(this);
    m_test->setObjectName(QStringLiteral("connectionTest"));
    m_test->addItem(tr("Surface"), int(core::ConnectionTest::Surface));
    m_test->addItem(tr("Plain depth"), int(core::ConnectionTest::Plain));
    m_test->setItemData(0,
                        tr("Follows each triangle's plane: sloped surfaces stay one region at "
                           "any threshold"),
                        Qt::ToolTipRole);
    m_test->setItemData(1,
                        tr("The paper's test: depth difference below the threshold; steep "
                           "surfaces break apart"),
                        Qt::ToolTipRole);
    m_test->setToolTip(tr("How neighbouring pixels are judged to lie on one surface"));

    m_twoSided = new QCheckBox(tr("Capture back faces (two-sided)"), this);
    m_twoSided->setObjectName(QStringLiteral("twoSidedCapture"));
    m_twoSided->setToolTip(tr("Show, paint and split into depth layers the back faces of every "
                              "surface. Without it, back faces are hidden but for the open "
                              "surfaces of double-sided materials (a leaf, a cloth). Changing it "
                              "captures the view again."));

    auto* form = new QFormLayout(this);
    form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    form->setLabelAlignment(Qt::AlignLeft | Qt::AlignVCenter);
    form->addRow(tr("Threshold:"), thresholdRow);
    form->addRow(tr("Test:"), m_test);
    form->addRow(m_twoSided);
    // docs/architecture.md §2: the C++ path and the GL compute pass give the same links; Auto takes
    // the faster for this renderer (C++ on software OpenGL).
    m_connectivity = new QComboBox(this);
    m_connectivity->setObjectName(QStringLiteral("connectivityBackend"));
    m_connectivity->addItem(tr("Automatic"), 0);
    m_connectivity->addItem(tr("C++ (processor)"), 1);
    m_connectivity->addItem(tr("Compute shader (graphics card)"), 2);
    m_connectivity->setToolTip(tr("Where pixel connectivity is computed; both give the same "
                                  "result, Automatic picks the faster for this computer"));
    form->addRow(tr("Connectivity:"), m_connectivity);
    connect(m_connectivity, &QComboBox::currentIndexChanged, this, [this](int index) {
        emit connectivityBackendChanged(m_connectivity->itemData(index).toInt());
    });

    connect(m_threshold, &QSlider::valueChanged, this, [this](int position) {
        if (m_updating)
            return;
        m_options.threshold = thresholdAt(position);
        updateLabels();
        emit optionsChanged(m_options);
    });
    connect(reset, &QToolButton::clicked, this, [this] {
        m_threshold->setValue(sliderPositionFor(core::DepthLayerOptions{}.threshold));
    });
    connect(m_test, &QComboBox::currentIndexChanged, this, [this](int index) {
        if (m_updating || index < 0)
            return;
        m_options.test = core::ConnectionTest(m_test->itemData(index).toInt());
        emit optionsChanged(m_options);
    });
    connect(m_twoSided, &QCheckBox::toggled, this, [this](bool twoSided) {
        if (m_updating)
            return;
        m_options.cullBackFaces = !twoSided;
        emit optionsChanged(m_options);
    });

    setOptions(m_options);
}

void SegmentationControls::setOptions(const core::DepthLayerOptions& options) {
    m_updating = true;
    m_options = options;
    m_threshold->setValue(sliderPositionFor(options.threshold));
    m_test->setCurrentIndex(m_test->findData(int(options.test)));
    m_twoSided->setChecked(!options.cullBackFaces);
    m_updating = false;
    updateLabels();
}

bool SegmentationControls::eventFilter(QObject* watched, QEvent* event) {
    // The slider's own keys win over window shortcuts while it has focus (Home frames the
    // model elsewhere).
    if (watched == m_threshold && event->type() == QEvent::ShortcutOverride) {
        const auto* key = static_cast<QKeyEvent*>(event);
        if (key->modifiers() == Qt::NoModifier) {
            switch (key->key()) {
            case Qt::Key_Home:
            case Qt::Key_End:
            case Qt::Key_PageUp:
            case Qt::Key_PageDown:
            case Qt::Key_Left:
            case Qt::Key_Right:
            case Qt::Key_Up:
            case Qt::Key_Down:
                event->accept();
                return true;
            default:
                break;
            }
        }
    }
    return QWidget::eventFilter(watched, event);
}

float SegmentationControls::thresholdAt(int sliderPosition) {
    const double exponent =
        std::log10(double(kMinThreshold)) +
        double(std::clamp(sliderPosition, 0, kDecades * kStepsPerDecade)) / kStepsPerDecade;
    return float(std::pow(10.0, exponent));
}

int SegmentationControls::sliderPositionFor(float threshold) {
    const double clamped =
        std::clamp(double(threshold), double(kMinThreshold), double(kMaxThreshold));
    return int(
        std::lround((std::log10(clamped) - std::log10(double(kMinThreshold))) * kStepsPerDecade));
}

QString SegmentationControls::formatThreshold(float threshold) {
    // Two significant digits in plain decimals (0.0010, 0.000015), which read better than 1e-05.
    // The nudge keeps a float just below a power of ten (0.00099999) from gaining a digit.
    const double magnitude = std::floor(std::log10(double(threshold) * (1.0 + 1e-6)));
    const int decimals = std::max(1, 1 - int(magnitude));
    return QLocale().toString(double(threshold), 'f', decimals);
}

void SegmentationControls::updateLabels() {
    m_thresholdValue->setText(formatThreshold(m_options.threshold));
}

void SegmentationControls::setConnectivityBackend(int backend) {
    const QSignalBlocker block(m_connectivity);
    m_connectivity->setCurrentIndex(std::max(0, m_connectivity->findData(backend)));
}

void SegmentationControls::setConnectivityInUse(const QString& name) {
    m_connectivity->setItemText(0,
                                name.isEmpty() ? tr("Automatic") : tr("Automatic (%1)").arg(name));
}

} // namespace ui
