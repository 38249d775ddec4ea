// SPDX-License-Identifier: GPL-3.0-or-later
// Files LayerPaint's programs run or load besides themselves (the importer program, the image
// codecs module), found the same way in the build tree and when installed.
#pragma once

#include <string>

#include "core/base/result.h"

namespace core {

/**
 * The path of `name`: the value of the environment variable `variable` if it is set, else `name`
 * beside the running program, else in ../libexec/layerpaint/ from the program's folder (the
 * install layout). `what` names the file in messages ("the importer program"); with
 * `executable`, the file must be one this process may run. Otherwise an Error saying where it was
 * looked for.
 */
Result<std::string> findProgramFile(const char* name, const char* variable, const char* what,
                                    bool executable);

} // namespace core
