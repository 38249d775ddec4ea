// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/shell/quick_guide.h"

#include <exception>
#include <memory>

#include <QCheckBox>
#include <QDialogButtonBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPixmap>
#include <QScrollArea>
#include <QSettings>
#include <QVBoxLayout>

#include "ui/shell/background_task.h"
#include "ui/shell/quick_guide_pictures.h"

namespace ui {

namespace {
constexpr QSize kPictureSize(240, 150);
} // namespace

QString QuickGuideDialog::showAtStartKey() {
    return QStringLiteral("guide/showAtStart");
}

bool QuickGuideDialog::takeShowAtStart() {
    QSettings settings;
    if (!settings.contains(showAtStartKey())) {
        settings.setValue(showAtStartKey(), false); // once, then as the box says
        return true;
    }
    return settings.value(showAtStartKey()).toBool();
}

QuickGuideDialog::QuickGuideDialog(QWidget* parent) : QDialog(parent) {
    setObjectName(QStringLiteral("quickGuide"));
    setWindowTitle(tr("Quick Guide"));
    m_pool.setMaxThreadCount(1);

    auto* page = new QWidget;
    auto* column = new QVBoxLayout(page);
    const auto text = [column](const QString& html) {
        auto* label = new QLabel(html);
        label->setWordWrap(true);
        label->setTextFormat(Qt::RichText);
        column->addWidget(label);
        return label;
    };
    text(tr("<h2>LayerPaint in one page</h2><p>LayerPaint splits the view into <b>depth "
            "layers</b> (the first, second, … surface under each pixel) and regions, so you can "
            "paint surfaces that others hide. Turn <i>Layer-aware</i> on with <b>L</b> or the "
            "check box in the tool bar.</p>"));
    const QString sections[] = {
        tr("<h3>Layer-aware stroke</h3><p>Drag with the brush (<b>B</b>). With layer-aware "
           "painting on, the stroke stays on the surface it started on, also where it goes "
           "behind another one. Shift+click draws a straight line on from the end of the last "
           "stroke.</p>"),
        tr("<h3>Pop-up</h3><p><b>Ctrl+Shift+click</b> with any tool, or a click with the Pop Up "
           "tool (<b>P</b>), brings the region under the visible one to the front. Click the "
           "same spot again to go deeper; after the last it starts from the top. <b>R</b> "
           "resets the order.</p>"),
        tr("<h3>Paint to hide</h3><p>With the Paint to Hide tool (<b>H</b>) paint over regions "
           "on the segmentation map: they are hidden and what lies behind shows. The Paint to "
           "Hide panel unhides them, <b>Shift+H</b> all at once.</p>"),
        tr("<h3>Orbit about a surface point</h3><p>With View ▸ Orbit About Surface Point on, an "
           "orbit (middle drag, or Alt+left drag) that starts on the model turns about that "
           "point, on whatever depth layer is shown there.</p>"),
    };
    for (const QString& section : sections) {
        auto* row = new QHBoxLayout;
        auto* picture = new QLabel(tr("Drawing…"));
        picture->setFixedSize(kPictureSize);
        picture->setAlignment(Qt::AlignCenter);
        picture->setFrameShape(QFrame::StyledPanel);
        m_pictureLabels.push_back(picture);
        auto* words = new QLabel(section);
        words->setWordWrap(true);
        words->setTextFormat(Qt::RichText);
        words->setAlignment(Qt::AlignTop | Qt::AlignLeft);
        row->addWidget(picture, 0, Qt::AlignTop);
        row->addWidget(words, 1);
        column->addLayout(row);
    }
    text(tr("<h3>Keys</h3><table cellspacing=\"4\">"
            "<tr><td><b>B</b> / <b>E</b> / <b>G</b> / <b>I</b></td><td>brush, eraser, fill, "
            "eyedropper (Ctrl+click with any tool)</td></tr>"
            "<tr><td><b>H</b> / <b>P</b></td><td>paint to hide, pop up</td></tr>"
            "<tr><td><b>L</b></td><td>layer-aware painting on or off</td></tr>"
            "<tr><td><b>[</b> <b>]</b> / Shift+<b>[</b> <b>]</b></td><td>brush size / "
            "hardness</td></tr>"
            "<tr><td><b>X</b></td><td>swap foreground and background colours</td></tr>"
            "<tr><td><b>F</b> / <b>O</b></td><td>frame the model / orthographic</td></tr>"
            "<tr><td>Middle drag, Shift+, Ctrl+, wheel</td><td>orbit, pan, zoom</td></tr>"
            "<tr><td>Alt+left / right / middle drag</td><td>orbit, zoom, pan (for "
            "tablets)</td></tr>"
            "<tr><td><b>Ctrl+Z</b> / <b>Ctrl+Shift+Z</b></td><td>undo / redo</td></tr>"
            "</table>"));
    column->addStretch(1);

    auto* scroll = new QScrollArea;
    scroll->setWidget(page);
    scroll->setWidgetResizable(true);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);

    m_showAtStart = new QCheckBox(tr("&Show at start"));
    m_showAtStart->setObjectName(QStringLiteral("guideShowAtStart"));
    m_showAtStart->setChecked(QSettings().value(showAtStartKey(), false).toBool());
    connect(m_showAtStart, &QCheckBox::toggled, this,
            [](bool on) { QSettings().setValue(showAtStartKey(), on); });
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::close);
    auto* bottom = new QHBoxLayout;
    bottom->addWidget(m_showAtStart);
    bottom->addStretch(1);
    bottom->addWidget(buttons);

    auto* layout = new QVBoxLayout(this);
    layout->addWidget(scroll, 1);
    layout->addLayout(bottom);
    resize(640, 560);
    drawPictures();
}

QuickGuideDialog::~QuickGuideDialog() {
    m_job.cancel();
    m_pool.waitForDone();
}

void QuickGuideDialog::drawPictures() {
    auto result = std::make_shared<std::vector<QImage>>();
    m_job = runInBackground(
        m_pool, this,
        [result](const core::ProgressFn& progress) {
            try {
                *result = makeQuickGuidePictures(kPictureSize, progress);
            } catch (const std::exception&) {
                result->clear(); // shown as no pictures
            }
        },
        [this, result] {
            if (result->size() != m_pictureLabels.size()) {
                for (QLabel* label : m_pictureLabels)
                    label->setText(tr("(no picture)"));
                return;
            }
            m_pictures = *result;
            for (std::size_t i = 0; i < m_pictures.size(); ++i)
                m_pictureLabels[i]->setPixmap(QPixmap::fromImage(m_pictures[i]));
            emit picturesReady();
        });
}

} // namespace ui
