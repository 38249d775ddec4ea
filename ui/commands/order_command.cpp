// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/commands/order_command.h"

#include <utility>

#include "core/document/document.h"

namespace ui {

OrderCommand::OrderCommand(core::Document& document, const bool& suspended,
                           core::RegionOrder before, core::RegionOrder after,
                           std::uint64_t layersSerial, const QString& text,
                           std::function<void()> applied)
    : QUndoCommand(text), m_document(document), m_suspended(suspended), m_before(std::move(before)),
      m_after(std::move(after)), m_layersSerial(layersSerial), m_applied(std::move(applied)) {}

void OrderCommand::undo() {
    apply(m_before);
}

void OrderCommand::redo() {
    if (!m_pushed) {
        m_pushed = true; // push(): the change is made already
        return;
    }
    apply(m_after);
}

void OrderCommand::apply(const core::RegionOrder& order) {
    if (m_suspended || m_document.layersSerial() != m_layersSerial)
        return;
    m_document.setRegionOrder(order);
    if (m_applied)
        m_applied();
}

OrderCommand* OrderCommand::clone() const {
    auto* copy = new OrderCommand(m_document, m_suspended, m_before, m_after, m_layersSerial,
                                  text(), m_applied);
    copy->m_pushed = true;
    return copy;
}

} // namespace ui
