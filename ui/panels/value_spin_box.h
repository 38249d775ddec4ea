// SPDX-License-Identifier: GPL-3.0-or-later
// The number fields the brush panel and the brush bar share: a spin box, alone or with a slider.
#pragma once

#include <QDoubleSpinBox>
#include <QString>

class QHBoxLayout;
class QSpinBox;
class QWidget;

namespace ui {

/**
 * A 0.00–1.00 value, the unit glTF and every panel give roughness and metallic in. A typed
 * number above 1 (up to 100), or one with a %, is read as a percentage (40 → 0.40), so a value
 * meant in the other unit lands where it was meant. With off, one step below 0 reads "Off" (no
 * value; value() is negative there). Reports a typed value once, when it is complete.
 */
class UnitSpinBox : public QDoubleSpinBox {
    Q_OBJECT

public:
    UnitSpinBox(QWidget* parent, const QString& name, const QString& tip, bool off);

protected:
    QValidator::State validate(QString& text, int& pos) const override;
    double valueFromText(const QString& text) const override;

private:
    /** The number in text (a % sign and the special text aside); false if there is none. */
    bool number(QString text, double& out, bool& percent) const;
};

/**
 * A spin box for one value: object name (tests and remembered layouts find it by it), range,
 * suffix and tooltip; it reports a typed value once, when it is complete (no keyboard tracking).
 */
QSpinBox* makeValueSpinBox(QWidget* parent, const QString& name, int minimum, int maximum,
                           const QString& suffix, const QString& tip);

/** A row of a slider over spin's range, with spin's tooltip, beside spin; the two follow each
 * other. */
QHBoxLayout* sliderRow(QSpinBox* spin);

} // namespace ui
