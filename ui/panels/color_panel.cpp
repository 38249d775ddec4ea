// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/panels/color_panel.h"

#include <QColorDialog>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QMouseEvent>
#include <QPainter>
#include <QRegularExpressionValidator>
#include <QSettings>
#include <QToolButton>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace ui {

namespace {
const QString kRecentKey = QStringLiteral("colors/recent");
constexpr double kHueBarWidth = 18.0;
constexpr double kGap = 6.0;
constexpr int kRecentColumns = 6;

QIcon swatchIcon(const QColor& color, int size, const QColor& frame) {
    QPixmap pixmap(size, size);
    pixmap.fill(Qt::transparent);
    QPainter painter(&pixmap);
    painter.setRenderHint(QPainter::Antialiasing);
    painter.setPen(QPen(frame, 1.0));
    painter.setBrush(color);
    painter.drawRoundedRect(QRectF(0.5, 0.5, size - 1.0, size - 1.0), 3, 3);
    return QIcon(pixmap);
}
} // namespace

// ---------------------------------------------------------------------------------------------
// HsvPicker

HsvPicker::HsvPicker(QWidget* parent) : QWidget(parent) {
    setObjectName(QStringLiteral("hsvPicker"));
    // Wider with the panel, higher only up to a point: a taller Colour panel's room is left
    // below (the window's extra height goes to the panels with lists).
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Preferred);
    setMaximumHeight(kMaximumHeight);
    setCursor(Qt::CrossCursor);
    setToolTip(tr("Saturation and value (square) and hue (bar)"));
}

QSize HsvPicker::sizeHint() const {
    return {200, 160};
}

QSize HsvPicker::minimumSizeHint() const {
    return {100, 80};
}

QRectF HsvPicker::squareRect() const {
    return QRectF(1.0, 1.0, std::max(1.0, width() - kHueBarWidth - kGap - 2.0),
                  std::max(1.0, height() - 2.0));
}

QRectF HsvPicker::hueRect() const {
    return QRectF(width() - kHueBarWidth - 1.0, 1.0, kHueBarWidth, std::max(1.0, height() - 2.0));
}

QPointF HsvPicker::squarePoint(double s, double v) const {
    const QRectF r = squareRect();
    return {r.left() + s * r.width(), r.top() + (1.0 - v) * r.height()};
}

QPointF HsvPicker::huePoint(double h) const {
    const QRectF r = hueRect();
    return {r.center().x(), r.top() + h * r.height()};
}

void HsvPicker::setColor(const QColor& color) {
    const QColor hsv = color.toHsv();
    // Greys have no hue: keep the one shown, so the square does not jump to red.
    if (hsv.hsvHueF() >= 0.0f)
        m_hue = hsv.hsvHueF();
    m_saturation = hsv.hsvSaturationF();
    m_value = hsv.valueF();
    update();
}

QColor HsvPicker::color() const {
    return QColor::fromHsvF(float(m_hue), float(m_saturation), float(m_value));
}

void HsvPicker::resizeEvent(QResizeEvent* event) {
    m_squareHue = -1.0; // made again at the new size
    QWidget::resizeEvent(event);
}

void HsvPicker::paintEvent(QPaintEvent*) {
    QPainter painter(this);
    const QRectF square = squareRect();
    const QSize size(int(square.width()), int(square.height()));
    if (m_squareHue != m_hue || m_square.size() != size) {
        m_square = QImage(size, QImage::Format_RGB32);
        for (int y = 0; y < size.height(); ++y) {
            auto* line = reinterpret_cast<QRgb*>(m_square.scanLine(y));
            const float v = 1.0f - float(y) / float(std::max(1, size.height() - 1));
            for (int x = 0; x < size.width(); ++x) {
                const float s = float(x) / float(std::max(1, size.width() - 1));
                line[x] = QColor::fromHsvF(float(m_hue), s, v).rgb();
            }
        }
        m_squareHue = m_hue;
    }
    painter.drawImage(square.topLeft(), m_square);

    const QRectF bar = hueRect();
    QLinearGradient hues(bar.topLeft(), bar.bottomLeft());
    for (int i = 0; i <= 6; ++i)
        hues.setColorAt(i / 6.0, QColor::fromHsvF(float(i % 6) / 6.0f, 1.0f, 1.0f));
    painter.fillRect(bar, hues);

    painter.setRenderHint(QPainter::Antialiasing);
    // Markers in black and white, visible on any colour.
    const QPointF at = squarePoint(m_saturation, m_value);
    painter.setBrush(Qt::NoBrush);
    painter.setPen(QPen(Qt::black, 1.0));
    painter.drawEllipse(at, 5.0, 5.0);
    painter.setPen(QPen(Qt::white, 1.0));
    painter.drawEllipse(at, 4.0, 4.0);
    const double y = huePoint(m_hue).y();
    painter.setPen(QPen(Qt::black, 3.0));
    painter.drawLine(QPointF(bar.left(), y), QPointF(bar.right(), y));
    painter.setPen(QPen(Qt::white, 1.0));
    painter.drawLine(QPointF(bar.left(), y), QPointF(bar.right(), y));
}

void HsvPicker::mousePressEvent(QMouseEvent* event) {
    if (event->button() != Qt::LeftButton) {
        QWidget::mousePressEvent(event);
        return;
    }
    m_dragging = event->position().x() >= hueRect().left() - kGap / 2 ? Part::Hue : Part::Square;
    pick(event->position());
}

void HsvPicker::mouseMoveEvent(QMouseEvent* event) {
    if (m_dragging != Part::None)
        pick(event->position());
}

void HsvPicker::mouseReleaseEvent(QMouseEvent* event) {
    if (event->button() == Qt::LeftButton && m_dragging != Part::None) {
        pick(event->position());
        m_dragging = Part::None;
    }
}

void HsvPicker::pick(QPointF position) {
    if (m_dragging == Part::Hue) {
        const QRectF r = hueRect();
        // Hue 1 is hue 0 again: stop just short so the bar's bottom stays magenta-red.
        m_hue = std::clamp((position.y() - r.top()) / r.height(), 0.0, 0.9999);
    } else {
        const QRectF r = squareRect();
        m_saturation = std::clamp((position.x() - r.left()) / r.width(), 0.0, 1.0);
        m_value = std::clamp(1.0 - (position.y() - r.top()) / r.height(), 0.0, 1.0);
    }
    update();
    emit colorChanged(color());
}

// ---------------------------------------------------------------------------------------------
// ColorPanel

ColorPanel::ColorPanel(QWidget* parent) : QWidget(parent) {
    auto* layout = new QVBoxLayout(this);

    m_picker = new HsvPicker(this);
    layout->addWidget(m_picker);
    connect(m_picker, &HsvPicker::colorChanged, this, &ColorPanel::chooseForeground);

    auto* row = new QHBoxLayout;
    m_foregroundButton = new QToolButton(this);
    m_foregroundButton->setObjectName(QStringLiteral("foregroundColor"));
    m_foregroundButton->setIconSize({28, 28});
    m_foregroundButton->setToolTip(tr("Foreground colour: the brush paints with it"));
    m_foregroundButton->setAutoRaise(true);
    connect(m_foregroundButton, &QToolButton::clicked, this, [this] {
        const QColor color = QColorDialog::getColor(m_foreground, this, tr("Foreground Colour"));
        if (color.isValid())
            chooseForeground(color);
    });
    m_backgroundButton = new QToolButton(this);
    m_backgroundButton->setObjectName(QStringLiteral("backgroundColor"));
    m_backgroundButton->setIconSize({20, 20});
    m_backgroundButton->setToolTip(tr("Background colour (X swaps it with the foreground)"));
    m_backgroundButton->setAutoRaise(true);
    connect(m_backgroundButton, &QToolButton::clicked, this, &ColorPanel::chooseBackground);
    auto* swap = new QToolButton(this);
    swap->setObjectName(QStringLiteral("swapColors"));
    swap->setText(QStringLiteral("⇄"));
    swap->setToolTip(tr("Swap foreground and background colours (X)"));
    swap->setAutoRaise(true);
    connect(swap, &QToolButton::clicked, this, &ColorPanel::swapColors);
    row->addWidget(m_foregroundButton);
    row->addWidget(swap);
    row->addWidget(m_backgroundButton);
    row->addStretch(1);
    auto* hexLabel = new QLabel(tr("&Hex"), this);
    m_hex = new QLineEdit(this);
    m_hex->setObjectName(QStringLiteral("colorHex"));
    m_hex->setToolTip(tr("The foreground colour as #rrggbb (sRGB)"));
    m_hex->setValidator(new QRegularExpressionValidator(
        QRegularExpression(QStringLiteral("#?[0-9A-Fa-f]{0,6}")), m_hex));
    m_hex->setMaximumWidth(fontMetrics().horizontalAdvance(QStringLiteral("#DDDDDD")) + 16);
    hexLabel->setBuddy(m_hex);
    row->addWidget(hexLabel);
    row->addWidget(m_hex);
    layout->addLayout(row);
    connect(m_hex, &QLineEdit::editingFinished, this, [this] {
        QString text = m_hex->text().trimmed();
        if (!text.startsWith(QLatin1Char('#')))
            text.prepend(QLatin1Char('#'));
        const QColor color = QColor::fromString(text);
        if (text.size() == 7 && color.isValid() && color != m_foreground)
            chooseForeground(color);
        else
            m_hex->setText(hexName(m_foreground)); // back to what is in use
    });

    auto* recentLabel = new QLabel(tr("Recent colours"), this);
    layout->addWidget(recentLabel);
    m_recentGrid = new QGridLayout;
    m_recentGrid->setSpacing(2);
    layout->addLayout(m_recentGrid);
    layout->addStretch(1);
    for (int i = 0; i < kMaxRecent; ++i) {
        auto* button = new QToolButton(this);
        button->setObjectName(QStringLiteral("recentColor%1").arg(i));
        button->setIconSize({18, 18});
        button->setAutoRaise(true);
        connect(button, &QToolButton::clicked, this, [this, i] {
            if (i < m_recent.size())
                chooseForeground(m_recent.at(i));
        });
        m_recentGrid->addWidget(button, i / kRecentColumns, i % kRecentColumns);
        m_recentButtons.append(button);
    }

    const QStringList stored = QSettings().value(kRecentKey).toStringList();
    for (const QString& name : stored) {
        const QColor color = QColor::fromString(name);
        if (color.isValid() && !m_recent.contains(color) && m_recent.size() < kMaxRecent)
            m_recent.append(color);
    }
    showColors();
    showRecent();
}

QString ColorPanel::hexName(const QColor& color) {
    return color.name(QColor::HexRgb);
}

void ColorPanel::setForeground(const QColor& color) {
    m_foreground = color.toRgb();
    showColors();
}

void ColorPanel::setBackground(const QColor& color) {
    m_background = color.toRgb();
    showColors();
}

void ColorPanel::swapColors() {
    std::swap(m_foreground, m_background);
    showColors();
    emit foregroundChanged(m_foreground);
}

void ColorPanel::chooseForeground(const QColor& color) {
    m_foreground = color.toRgb();
    showColors();
    emit foregroundChanged(m_foreground);
}

void ColorPanel::chooseBackground() {
    const QColor color = QColorDialog::getColor(m_background, this, tr("Background Colour"));
    if (color.isValid())
        setBackground(color);
}

void ColorPanel::addRecent(const QColor& color) {
    const QColor rgb = color.toRgb();
    if (!m_recent.isEmpty() && m_recent.first() == rgb)
        return;
    m_recent.removeAll(rgb);
    m_recent.prepend(rgb);
    while (m_recent.size() > kMaxRecent)
        m_recent.removeLast();
    QStringList names;
    for (const QColor& c : m_recent)
        names.append(hexName(c));
    QSettings().setValue(kRecentKey, names);
    showRecent();
}

void ColorPanel::showColors() {
    const QColor frame = palette().color(QPalette::WindowText);
    m_foregroundButton->setIcon(swatchIcon(m_foreground, 28, frame));
    m_backgroundButton->setIcon(swatchIcon(m_background, 20, frame));
    // While the picker is dragged it leads: its hue must not snap to the rounded colour's.
    if (m_picker->color().toRgb() != m_foreground)
        m_picker->setColor(m_foreground);
    if (!m_hex->hasFocus() || m_hex->text() != hexName(m_foreground))
        m_hex->setText(hexName(m_foreground));
}

void ColorPanel::showRecent() {
    const QColor frame = palette().color(QPalette::Mid);
    for (int i = 0; i < m_recentButtons.size(); ++i) {
        QToolButton* button = m_recentButtons.at(i);
        const bool used = i < m_recent.size();
        button->setEnabled(used);
        // An empty slot shows as an outline, so the palette is seen before it fills.
        button->setIcon(swatchIcon(used ? m_recent.at(i) : QColor(Qt::transparent), 18, frame));
        button->setToolTip(used ? hexName(m_recent.at(i)) : QString());
    }
}

} // namespace ui
