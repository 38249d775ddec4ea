// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/document/history.h"

#include <algorithm>
#include <limits>

namespace core {

namespace {

constexpr std::uint64_t kNoState = std::numeric_limits<std::uint64_t>::max();

std::size_t partBytes(const StepPart& part) {
    return std::visit([](const auto& p) { return p.bytes(); }, part);
}

} // namespace

const char* stepKindName(StepKind kind) {
    switch (kind) {
    case StepKind::Stroke:
        return "stroke";
    case StepKind::Fill:
        return "fill";
    case StepKind::PopUp:
        return "pop-up";
    case StepKind::Hide:
        return "hide";
    case StepKind::Unhide:
        return "unhide";
    case StepKind::ResetOrder:
        return "reset-order";
    case StepKind::PaintTarget:
        return "paint-target";
    case StepKind::Script:
        return "script";
    case StepKind::PaintLayers:
        return "paint-layers";
    }
    return "step";
}

std::size_t OrderChange::bytes() const {
    return sizeof(OrderChange) + before.bytes() + after.bytes();
}

std::size_t TargetSwap::bytes() const {
    return sizeof(TargetSwap) + (other ? other->bytes() : 0);
}

std::size_t PaintLayerChange::bytes() const {
    std::size_t total = sizeof(PaintLayerChange) + settings.name.capacity();
    for (const auto& layer : held)
        total += sizeof(PaintLayer) + layer->bytes();
    return total + (mask ? mask->allocatedBytes() : 0);
}

std::size_t HistoryStep::bytes() const {
    std::size_t total = sizeof(HistoryStep);
    for (const StepPart& part : parts)
        total += partBytes(part);
    return total;
}

bool History::push(HistoryStep step) {
    if (step.empty())
        return false;
    ++m_revision;
    // A new step makes the undone ones unreachable (the saved state too, if it was one of them).
    while (m_steps.size() > m_next) {
        if (m_steps.back().id == m_savedId)
            m_savedId = kNoState;
        m_bytes -= m_steps.back().bytes;
        m_steps.pop_back();
    }
    const std::size_t size = step.bytes();
    if (size > m_budget) {
        // Too big to keep. The older steps must go too: undoing them over this step's changes
        // would restore a mix of states.
        m_dropped += m_steps.size() + 1;
        reset();
        m_savedId = kNoState; // the state changed: it is not the saved one any more
        notify();
        return false;
    }
    m_steps.push_back({std::move(step), size, m_nextId++});
    m_bytes += size;
    m_next = m_steps.size();
    enforceBudget();
    notify();
    return true;
}

HistoryStep* History::nextUndo() {
    return canUndo() ? &m_steps[m_next - 1].step : nullptr;
}

HistoryStep* History::nextRedo() {
    return canRedo() ? &m_steps[m_next].step : nullptr;
}

void History::undone() {
    if (canUndo()) {
        --m_next;
        ++m_revision;
        notify();
    }
}

void History::redone() {
    if (canRedo()) {
        ++m_next;
        ++m_revision;
        notify();
    }
}

std::optional<StepKind> History::undoKind() const {
    if (!canUndo())
        return std::nullopt;
    return m_steps[m_next - 1].step.kind;
}

std::optional<StepKind> History::redoKind() const {
    if (!canRedo())
        return std::nullopt;
    return m_steps[m_next].step.kind;
}

void History::setBudget(std::size_t budgetBytes) {
    m_budget = budgetBytes;
    enforceBudget();
    notify();
}

void History::clear() {
    reset();
    notify();
}

void History::reset() {
    m_steps.clear();
    m_next = 0;
    m_bytes = 0;
    m_baseId = m_nextId++;
    m_savedId = m_baseId; // as loaded: call markSaved() elsewhere if that is not the saved state
    ++m_revision;
}

void History::dropStaleOrders(std::uint64_t depthLayersSerial) {
    bool changed = false;
    for (std::size_t i = m_steps.size(); i-- > 0;) {
        Entry& entry = m_steps[i];
        auto& parts = entry.step.parts;
        const auto stale = [depthLayersSerial](const StepPart& part) {
            const auto* order = std::get_if<OrderChange>(&part);
            return order && order->depthLayersSerial != depthLayersSerial;
        };
        if (std::none_of(parts.begin(), parts.end(), stale))
            continue;
        changed = true;
        parts.erase(std::remove_if(parts.begin(), parts.end(), stale), parts.end());
        m_bytes -= entry.bytes;
        entry.bytes = entry.step.bytes();
        m_bytes += entry.bytes;
        if (!parts.empty())
            continue;
        // Nothing left: without its order change the step leaves the state as the one before.
        const std::uint64_t previous = i > 0 ? m_steps[i - 1].id : m_baseId;
        if (m_savedId == entry.id)
            m_savedId = previous;
        m_bytes -= entry.bytes;
        m_steps.erase(m_steps.begin() + std::ptrdiff_t(i));
        if (i < m_next)
            --m_next;
    }
    if (changed) {
        ++m_revision;
        notify();
    }
}

bool History::squash(std::uint64_t mark, StepKind kind) {
    std::size_t first = 0; // the first step done after mark
    if (mark != m_baseId) {
        first = m_steps.size() + 1;
        for (std::size_t i = 0; i < m_steps.size(); ++i)
            if (m_steps[i].id == mark)
                first = i + 1;
    }
    if (first >= m_next || first > m_steps.size())
        return false;
    HistoryStep merged{kind, {}};
    std::uint64_t lastId = m_steps[m_next - 1].id;
    for (std::size_t i = first; i < m_next; ++i)
        for (StepPart& part : m_steps[i].step.parts)
            merged.parts.push_back(std::move(part));
    const bool savedInside = [&] {
        for (std::size_t i = first; i < m_steps.size(); ++i)
            if (m_steps[i].id == m_savedId && m_steps[i].id != lastId)
                return true;
        return false;
    }();
    for (std::size_t i = first; i < m_steps.size(); ++i)
        m_bytes -= m_steps[i].bytes;
    m_steps.erase(m_steps.begin() + std::ptrdiff_t(first), m_steps.end());
    if (savedInside)
        m_savedId = kNoState; // a state inside the merged step cannot be reached any more
    const std::size_t size = merged.bytes();
    m_steps.push_back({std::move(merged), size, lastId});
    m_bytes += size;
    m_next = m_steps.size();
    ++m_revision;
    enforceBudget();
    notify();
    return true;
}

void History::markSaved() {
    m_savedId = stateId();
    notify();
}

std::uint64_t History::subscribe(std::function<void()> listener) {
    m_listeners.emplace_back(m_nextListener, std::move(listener));
    return m_nextListener++;
}

void History::unsubscribe(std::uint64_t id) {
    std::erase_if(m_listeners, [id](const auto& entry) { return entry.first == id; });
}

void History::notify() const {
    for (const auto& [id, listener] : m_listeners)
        listener();
}

bool History::atSavedState() const {
    return m_savedId == stateId();
}

std::optional<std::size_t> History::savedIndex() const {
    if (m_savedId == m_baseId)
        return 0;
    for (std::size_t i = 0; i < m_steps.size(); ++i)
        if (m_steps[i].id == m_savedId)
            return i + 1;
    return std::nullopt;
}

std::uint64_t History::stateId() const {
    return m_next > 0 ? m_steps[m_next - 1].id : m_baseId;
}

void History::dropFront() {
    m_bytes -= m_steps.front().bytes;
    m_baseId = m_steps.front().id;
    m_steps.pop_front();
    ++m_dropped;
}

void History::enforceBudget() {
    // The oldest step goes first: it is the least likely to be wanted back.
    while (m_bytes > m_budget && m_next > 0) {
        dropFront();
        --m_next;
    }
    // Only a lowered budget gets here with steps left: drop the furthest redo steps.
    while (m_bytes > m_budget && !m_steps.empty()) {
        if (m_steps.back().id == m_savedId)
            m_savedId = kNoState;
        m_bytes -= m_steps.back().bytes;
        m_steps.pop_back();
        ++m_dropped;
    }
    ++m_revision;
}

} // namespace core
