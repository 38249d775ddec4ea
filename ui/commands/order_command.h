// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstdint>
#include <functional>

#include <QUndoCommand>

#include "core/regions/region_order.h"

namespace core {
class Document;
}

namespace ui {

/**
 * A change of the region order (pop-up, paint-to-hide, unhide, reset) on the QUndoStack. It is
 * pushed after the change was made, so the first redo() only reports. Region ids belong to one
 * build of the layers: for others (layersSerial differs) undo() and redo() do nothing, and the
 * window drops such commands when the layers change. While suspended is true they touch nothing.
 * applied runs after every change it makes.
 */
class OrderCommand : public QUndoCommand {
public:
    OrderCommand(core::Document& document, const bool& suspended, core::RegionOrder before,
                 core::RegionOrder after, std::uint64_t layersSerial, const QString& text,
                 std::function<void()> applied);

    void undo() override;
    void redo() override;

    std::uint64_t layersSerial() const { return m_layersSerial; }
    /** The same change, for rebuilding the stack. */
    OrderCommand* clone() const;

private:
    void apply(const core::RegionOrder& order);

    core::Document& m_document;
    const bool& m_suspended;
    core::RegionOrder m_before;
    core::RegionOrder m_after;
    std::uint64_t m_layersSerial;
    std::function<void()> m_applied;
    bool m_pushed = false;
};

} // namespace ui
