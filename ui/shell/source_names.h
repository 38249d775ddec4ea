// SPDX-License-Identifier: GPL-3.0-or-later
// How the window and its controllers name what is open: a file by its name, a built-in model
// ("builtin:NAME") by its translated label.
#pragma once

#include <QString>

namespace ui {

/** A "builtin:NAME" source rather than a file. */
bool isBuiltinSource(const QString& source);
/** The translated name of a built-in model ("trefoil" → "Trefoil knot"). */
QString builtinLabel(const QString& name);
/** The name shown for a source: a built-in's label or the file name. */
QString sourceDisplayName(const QString& source);

} // namespace ui
