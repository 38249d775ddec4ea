// SPDX-License-Identifier: GPL-3.0-or-later
// MainWindow: the Brush Presets panel, the tool hint in the status bar and the quick guide.
#include "ui/shell/main_window.h"

#include <QAction>
#include <QDockWidget>
#include <QKeySequence>
#include <QStatusBar>

#include "ui/panels/brush_presets_panel.h"
#include "ui/shell/elided_label.h"
#include "ui/shell/quick_guide.h"
#include "ui/tools/tool_hints.h"

namespace ui {

void MainWindow::createHelpAndPresets() {
    m_presetsPanel = new BrushPresetsPanel([this] { return m_document->brush(); }, this);
    m_presetsDock = makeDock(tr("Brush Presets"), QStringLiteral("brushPresetsDock"),
                             m_presetsPanel, Qt::LeftDockWidgetArea);
    // Beside the Colour panel (a tab), so the Brush panel keeps its height.
    tabifyDockWidget(m_colorDock, m_presetsDock);
    m_colorDock->raise();
    connect(m_presetsPanel, &BrushPresetsPanel::presetChosen, this,
            [this](const core::Brush& preset, const QString& name) {
                // A preset is the brush's kind; the colour and the symmetry stay the artist's.
                core::Brush brush = preset;
                brush.color = m_document->brush().color;
                brush.symmetry = m_document->brush().symmetry;
                setBrush(brush);
                statusBar()->showMessage(tr("Brush preset: %1").arg(name), kPaintMessageMs);
            });
    connect(m_presetsPanel, &BrushPresetsPanel::errorOccurred, this, [this](const QString& text) {
        statusBar()->showMessage(text, kStatusMessageMs);
        showError(tr("Brush Presets"), text, {});
    });

    // The hint for the tool in use, left in the status bar (messages cover it for a while).
    auto* hint = new ElidedLabel(this);
    hint->setObjectName(QStringLiteral("toolHint"));
    m_toolHint = hint;
    statusBar()->addWidget(m_toolHint, 1);
    const auto showHint = [this](Tool tool) {
        m_toolHint->setText(toolHint(tool));
        m_toolHint->setToolTip(toolHint(tool));
    };
    showHint(m_tool);
    connect(this, &MainWindow::toolChanged, this, showHint);

    m_quickGuideAction = new QAction(tr("Quick &Guide"), this);
    m_quickGuideAction->setObjectName(QStringLiteral("actionQuickGuide"));
    m_quickGuideAction->setShortcut(QKeySequence(Qt::Key_F1));
    m_quickGuideAction->setStatusTip(
        tr("One page on layer-aware painting, pop-up, paint to hide, orbiting and the keys"));
    connect(m_quickGuideAction, &QAction::triggered, this, &MainWindow::showQuickGuide);
}

void MainWindow::showQuickGuide() {
    if (!m_guide) {
        m_guide = new QuickGuideDialog(this);
        m_guide->setAttribute(Qt::WA_DeleteOnClose);
    }
    m_guide->show();
    m_guide->raise();
    m_guide->activateWindow();
}

QuickGuideDialog* MainWindow::quickGuide() const {
    return m_guide.data();
}

void MainWindow::showQuickGuideAtStart() {
    if (QuickGuideDialog::takeShowAtStart())
        showQuickGuide();
}

} // namespace ui
