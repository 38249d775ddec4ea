// SPDX-License-Identifier: GPL-3.0-or-later
// Saving a file so that a crash, a full disk or a failed write never leaves half a file under its
// name: a temporary file in the same folder, written, flushed and synced, then renamed over the
// old one, which is first kept as a backup when asked.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>

#include "core/base/result.h"

namespace core {

/**
 * Writes size bytes to path atomically (docs/architecture.md §6): a temporary file in the same
 * folder is written, flushed and fsync'ed, then renamed over path. With keepBackup, an existing
 * file is first kept as path + ".bak" (replacing an older backup). A symbolic link at path is
 * followed, so the file it points to is replaced. The new file gets the old one's permissions (else
 * the default ones). On failure (missing or unwritable folder, disk full, ...) nothing at path
 * changes, the temporary file is removed, and the Error names path and the problem.
 */
Status writeFileAtomically(const std::string& path, const void* data, std::size_t size,
                           bool keepBackup = true);

/** writeFileAtomically() of parts written one after another (no copy of them is made). */
Status writePartsAtomically(const std::string& path,
                            std::span<const std::span<const std::uint8_t>> parts,
                            bool keepBackup = true);

} // namespace core
