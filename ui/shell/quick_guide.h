// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <vector>

#include <QDialog>
#include <QFuture>
#include <QImage>
#include <QThreadPool>

class QCheckBox;
class QLabel;

namespace ui {

/**
 * Help ▸ Quick Guide: one scrollable page on the layer-aware stroke, pop-up, paint-to-hide,
 * orbiting about a surface point and the keys, with pictures the app draws itself
 * (makeQuickGuidePictures(), in the background when the guide first opens). Not modal. Its
 * "Show at start" box is the setting showAtStartKey().
 */
class QuickGuideDialog : public QDialog {
    Q_OBJECT

public:
    explicit QuickGuideDialog(QWidget* parent = nullptr);
    /** Cancels and waits for the pictures still being drawn. */
    ~QuickGuideDialog() override;

    /** The setting that opens the guide at start (absent on a first start: it opens once). */
    static QString showAtStartKey();
    /** Whether the guide should open at this start; a first start marks itself done. */
    static bool takeShowAtStart();

    /** The pictures, once drawn (picturesReady()); empty before. */
    const std::vector<QImage>& pictures() const { return m_pictures; }
    QCheckBox* showAtStartBox() const { return m_showAtStart; }

signals:
    void picturesReady();

private:
    void drawPictures();

    QCheckBox* m_showAtStart = nullptr;
    std::vector<QLabel*> m_pictureLabels;
    std::vector<QImage> m_pictures;
    QThreadPool m_pool;
    QFuture<void> m_job;
};

} // namespace ui
