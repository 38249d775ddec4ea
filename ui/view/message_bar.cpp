// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/view/message_bar.h"

#include <QEvent>

#include <QHBoxLayout>
#include <QLabel>
#include <QStyle>
#include <QToolButton>
#include <algorithm>

namespace ui {

namespace {
constexpr int kMargin = 8;
constexpr int kMaxLines = 12; // more go to the tooltip
} // namespace

MessageBar::MessageBar(QWidget& parent) : QFrame(&parent), m_host(parent) {
    setObjectName(QStringLiteral("messageBar"));
    setFrameShape(QFrame::StyledPanel);
    setAutoFillBackground(true);
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(8, 6, 4, 6);
    m_icon = new QLabel(this);
    m_icon->setAlignment(Qt::AlignTop);
    layout->addWidget(m_icon);
    m_text = new QLabel(this);
    m_text->setObjectName(QStringLiteral("messageBarText"));
    m_text->setWordWrap(true);
    m_text->setTextFormat(Qt::PlainText);
    m_text->setTextInteractionFlags(Qt::TextSelectableByMouse); // can be copied into a report
    layout->addWidget(m_text, 1);
    m_close = new QToolButton(this);
    m_close->setObjectName(QStringLiteral("messageBarClose"));
    m_close->setAutoRaise(true);
    m_close->setIcon(style()->standardIcon(QStyle::SP_TitleBarCloseButton));
    m_close->setToolTip(tr("Dismiss"));
    m_close->setFocusPolicy(Qt::NoFocus); // the keys stay with the view
    layout->addWidget(m_close, 0, Qt::AlignTop);
    connect(m_close, &QToolButton::clicked, this, &MessageBar::dismiss);
    parent.installEventFilter(this);
    hide();
}

void MessageBar::showMessage(Level level, const QString& title, const QStringList& lines) {
    m_level = level;
    QPalette colors = palette();
    // Pale amber for warnings, pale blue for notes; dark text on both.
    colors.setColor(QPalette::Window,
                    level == Level::Warning ? QColor(255, 243, 205) : QColor(222, 236, 252));
    colors.setColor(QPalette::WindowText, QColor(32, 32, 32));
    setPalette(colors);
    const int size = style()->pixelMetric(QStyle::PM_SmallIconSize, nullptr, this);
    m_icon->setPixmap(style()
                          ->standardIcon(level == Level::Warning ? QStyle::SP_MessageBoxWarning
                                                                 : QStyle::SP_MessageBoxInformation)
                          .pixmap(size, size));
    QStringList shown;
    shown.append(title);
    for (int i = 0; i < lines.size(); ++i) {
        if (i == kMaxLines && lines.size() > kMaxLines + 1) {
            shown.append(
                tr("… and %n more (see the tooltip)", nullptr, int(lines.size() - kMaxLines)));
            break;
        }
        shown.append(QStringLiteral("• ") + lines.at(i));
    }
    // Later: this may run inside one of the buttons' own click.
    for (QToolButton* button : m_buttons) {
        button->hide();
        button->deleteLater();
    }
    m_buttons.clear();
    m_text->setText(shown.join(QLatin1Char('\n')));
    setToolTip(lines.size() > kMaxLines + 1 ? lines.join(QLatin1Char('\n')) : QString());
    show();
    raise();
    place();
}

QToolButton* MessageBar::addButton(const QString& text, std::function<void()> onClick) {
    auto* button = new QToolButton(this);
    button->setObjectName(QStringLiteral("messageBarButton"));
    button->setText(text);
    button->setToolButtonStyle(Qt::ToolButtonTextOnly);
    button->setFocusPolicy(Qt::NoFocus); // the keys stay with the view
    auto* row = static_cast<QHBoxLayout*>(layout());
    row->insertWidget(row->indexOf(m_close), button, 0, Qt::AlignTop);
    m_buttons.append(button);
    button->show(); // the bar may be shown already
    connect(button, &QToolButton::clicked, this, [this, onClick = std::move(onClick)] {
        const std::function<void()> call = onClick; // the button may go while it runs
        dismiss();
        call();
    });
    if (isVisible())
        place();
    return button;
}

void MessageBar::dismiss() {
    hide();
}

QString MessageBar::text() const {
    return m_text->text();
}

void MessageBar::place() {
    const int width = std::max(0, m_host.width() - 2 * kMargin);
    const int height =
        std::min(heightForWidth(width) > 0 ? heightForWidth(width) : sizeHint().height(),
                 std::max(0, m_host.height() - 2 * kMargin));
    setGeometry(kMargin, kMargin, width, height);
}

bool MessageBar::eventFilter(QObject* watched, QEvent* event) {
    if (watched == &m_host && event->type() == QEvent::Resize && isVisible())
        place();
    return QFrame::eventFilter(watched, event);
}

} // namespace ui
