// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QColor>
#include <QImage>
#include <QList>
#include <QWidget>

class QGridLayout;
class QLineEdit;
class QToolButton;

namespace ui {

/**
 * An HSV picker: a saturation (right) × value (up) square for the current hue and a hue bar
 * beside it. Dragging in either emits colorChanged(); setColor() shows a colour without emitting.
 */
class HsvPicker : public QWidget {
    Q_OBJECT

public:
    /** The most height the picker takes however high its panel is. */
    static constexpr int kMaximumHeight = 240;

    explicit HsvPicker(QWidget* parent = nullptr);
    void setColor(const QColor& color);
    QColor color() const;
    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

    /** Where the square shows saturation s and value v (0..1), in widget coordinates. */
    QPointF squarePoint(double s, double v) const;
    /** Where the hue bar shows hue h (0..1). */
    QPointF huePoint(double h) const;

signals:
    void colorChanged(const QColor& color);

protected:
    void paintEvent(QPaintEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;

private:
    enum class Part { None, Square, Hue };
    QRectF squareRect() const;
    QRectF hueRect() const;
    void pick(QPointF position);

    double m_hue = 0.0, m_saturation = 1.0, m_value = 1.0;
    Part m_dragging = Part::None;
    QImage m_square; // the square at m_squareHue and the current size
    double m_squareHue = -1.0;
};

/**
 * The Colour panel (a dock): an HSV picker with hex entry, foreground and background colours
 * with swap, and the recently used colours (kept in QSettings). The foreground is the brush
 * colour. User actions emit foregroundChanged(); setForeground() and setBackground() only show.
 */
class ColorPanel : public QWidget {
    Q_OBJECT

public:
    static constexpr int kMaxRecent = 12;

    explicit ColorPanel(QWidget* parent = nullptr);

    QColor foreground() const { return m_foreground; }
    QColor background() const { return m_background; }
    void setForeground(const QColor& color);
    void setBackground(const QColor& color);
    /** Swaps foreground and background (X); emits foregroundChanged(). */
    void swapColors();
    /** Puts color first among the recent colours (once), keeping at most kMaxRecent. */
    void addRecent(const QColor& color);
    QList<QColor> recentColors() const { return m_recent; }
    /** The colour as the hex entry shows it: "#rrggbb". */
    static QString hexName(const QColor& color);

signals:
    void foregroundChanged(const QColor& color);

private:
    void chooseForeground(const QColor& color);
    void chooseBackground();
    void showColors();
    void showRecent();

    QColor m_foreground{Qt::black};
    QColor m_background{Qt::white};
    QList<QColor> m_recent;
    HsvPicker* m_picker = nullptr;
    QLineEdit* m_hex = nullptr;
    QToolButton* m_foregroundButton = nullptr;
    QToolButton* m_backgroundButton = nullptr;
    QGridLayout* m_recentGrid = nullptr;
    QList<QToolButton*> m_recentButtons;
};

} // namespace ui
