// SPDX-License-Identifier: GPL-3.0-or-later
// Loads the image codecs module (image_codecs.h) on first use.
#include "core/io/image/image_codecs.h"

#include <mutex>
#include <string>

#include <dlfcn.h>

#include "core/io/importer/program_files.h"

namespace core {

namespace {

constexpr const char* kModuleName = "layerpaint-image-codecs.so";
constexpr const char* kModuleVariable = "LAYERPAINT_IMAGE_CODECS";

Result<const ImageCodecs*> load() {
    Result<std::string> path = findImageCodecs();
    if (!path)
        return path.takeError();
    // Never closed: the codecs serve until the process ends.
    void* module = ::dlopen(path->c_str(), RTLD_NOW | RTLD_LOCAL);
    if (module == nullptr) {
        const char* why = ::dlerror();
        return Error{"the image codecs module " + *path + " cannot be loaded (" +
                     (why ? why : "unknown error") + ")"};
    }
    using Entry = const ImageCodecs* (*)();
    auto entry = reinterpret_cast<Entry>(::dlsym(module, "layerpaint_image_codecs"));
    const ImageCodecs* codecs = entry ? entry() : nullptr;
    if (codecs == nullptr)
        return Error{"the image codecs module " + *path + " is not LayerPaint's"};
    return codecs;
}

} // namespace

Result<std::string> findImageCodecs() {
    return findProgramFile(kModuleName, kModuleVariable, "the image codecs module", false);
}

Result<const ImageCodecs*> imageCodecs() {
    static std::once_flag once;
    static Result<const ImageCodecs*> loaded = Error{""};
    std::call_once(once, [] { loaded = load(); });
    return loaded;
}

Status writeImage(const std::string& path, int width, int height, int channels, PixelType type,
                  const void* pixels) {
    Result<const ImageCodecs*> codecs = imageCodecs();
    if (!codecs)
        return Error{path + ": " + codecs.error()};
    return (*codecs)->write(path, width, height, channels, type, pixels);
}

} // namespace core
