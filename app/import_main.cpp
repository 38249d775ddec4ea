// SPDX-License-Identifier: GPL-3.0-or-later
// layerpaint-import: the importer process. Parses one model file (or, with --image, one image
// file) in a sandbox (import_sandbox.h) and writes the result to standard output as frames
// (core/import_protocol.h): progress, warnings, then the mesh, the image or an error. Started by
// core::loadMesh() and core::loadImageFile(); its output is binary, not for reading by hand.
//
//   layerpaint-import [--max-file-bytes N] [--max-vertices N] [--max-triangles N]
//                     [--max-image-pixels N] [--max-seconds S] [--require-textures]
//                     [--image] -- FILE
//   layerpaint-import --probe OTHER_FILE -- FILE   (tests: what the sandbox allows, as text)
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <optional>
#include <string>
#include <system_error>
#include <vector>

#include <fcntl.h>
#include <sys/socket.h>
#include <unistd.h>

#include "app/import_sandbox.h"
#include "core/import_protocol.h"
#include "core/mesh_io_in_process.h"

namespace {

namespace fs = std::filesystem;

struct Options {
    core::LoadLimits limits;
    bool image = false;
    std::optional<std::string> probe;
    std::string file;
};

int usage(const char* problem) {
    std::fprintf(stderr,
                 "layerpaint-import: %s\nusage: layerpaint-import [--max-file-bytes N] "
                 "[--max-vertices N] [--max-triangles N] [--max-image-pixels N] [--max-seconds S] "
                 "[--require-textures] [--image] -- FILE\n(run by LayerPaint to read files; it "
                 "writes binary frames to its standard output)\n",
                 problem);
    return 2;
}

bool number(const char* text, std::uint64_t& out) {
    char* end = nullptr;
    errno = 0;
    const unsigned long long value = std::strtoull(text, &end, 10);
    if (errno != 0 || end == text || *end != '\0' || text[0] == '-')
        return false;
    out = value;
    return true;
}

std::optional<Options> parse(int argc, char** argv) {
    Options o;
    int i = 1;
    for (; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--") {
            ++i;
            break;
        }
        if (arg == "--image") {
            o.image = true;
        } else if (arg == "--require-textures") {
            o.limits.requireTextures = true;
        } else if (i + 1 < argc) {
            const char* value = argv[++i];
            std::uint64_t n = 0;
            if (arg == "--probe") {
                o.probe = value;
            } else if (arg == "--max-seconds") {
                char* end = nullptr;
                o.limits.maxSeconds = std::strtod(value, &end);
                if (end == value || *end != '\0' || !(o.limits.maxSeconds > 0.0))
                    return std::nullopt;
            } else if (!number(value, n)) {
                return std::nullopt;
            } else if (arg == "--max-file-bytes") {
                o.limits.maxFileBytes = n;
            } else if (arg == "--max-vertices") {
                o.limits.maxVertices = n;
            } else if (arg == "--max-triangles") {
                o.limits.maxTriangles = n;
            } else if (arg == "--max-image-pixels") {
                o.limits.maxImagePixels = n;
            } else {
                return std::nullopt;
            }
        } else {
            return std::nullopt;
        }
    }
    if (i + 1 != argc)
        return std::nullopt;
    o.file = argv[i];
    return o;
}

/** What the loader may read: an image file itself, or everything in a model's folder. */
std::vector<std::string> readablePaths(const Options& o) {
    std::error_code ec;
    const fs::path file = fs::canonical(o.file, ec);
    if (ec)
        return {};
    return {o.image ? file.string() : file.parent_path().string()};
}

/** Test mode: tries what a hostile file might make the loader do, prints what happened. */
int probe(const Options& o, const importer::SandboxReport& report) {
    auto attempt = [](bool ok) { return ok ? "allowed" : "denied"; };
    auto canOpen = [](const std::string& path, int flags) {
        const int fd = ::open(path.c_str(), flags | O_CLOEXEC, 0600);
        if (fd >= 0)
            ::close(fd);
        return fd >= 0;
    };
    const fs::path folder = fs::path(o.file).parent_path();
    const int sock = ::socket(AF_INET, SOCK_STREAM, 0);
    if (sock >= 0)
        ::close(sock);
    std::printf("landlock-abi=%d landlock=%d seccomp=%d no-new-privs=%d address-space-limit=%d "
                "read-file=%s read-other=%s create-file=%s socket=%s\n",
                report.landlockAbi, report.landlock, report.seccomp, report.noNewPrivs,
                report.addressSpaceLimit, attempt(canOpen(o.file, O_RDONLY)),
                attempt(canOpen(*o.probe, O_RDONLY)),
                attempt(canOpen((folder / "probe-created").string(), O_WRONLY | O_CREAT)),
                attempt(sock >= 0));
    return 0;
}

} // namespace

int main(int argc, char** argv) {
    const std::optional<Options> options = parse(argc, argv);
    if (!options)
        return usage("invalid arguments");
    const Options& o = *options;

    importer::SandboxOptions sandbox;
    sandbox.readable = readablePaths(o);
    sandbox.maxSeconds = o.limits.maxSeconds;
    const importer::SandboxReport report = importer::applySandbox(sandbox);
    if (o.probe)
        return probe(o, report);

    core::importer::FrameWriter out(STDOUT_FILENO);
    bool sent = false;
    if (o.image) {
        const core::Result<core::Image> image = core::loadImageFileInProcess(o.file, o.limits);
        sent = image ? out.image(*image) : out.text(core::importer::Tag::Error, image.error());
    } else {
        // Reports often enough for a smooth progress bar, not once per primitive.
        double reported = -1.0;
        const core::ProgressFn progress = [&](double fraction) {
            if (fraction >= 1.0 || fraction - reported >= 0.01) {
                reported = fraction;
                out.progress(fraction);
            }
            return true; // the application ends this process to cancel
        };
        const core::Result<core::Mesh> mesh = core::loadMeshInProcess(o.file, progress, o.limits);
        sent = mesh ? out.mesh(*mesh) : out.text(core::importer::Tag::Error, mesh.error());
    }
    // No destructors: freeing a large scene only costs time, and a heap that a parser damaged
    // cannot crash the process after its answer.
    ::_exit(sent ? 0 : 1);
}
