// SPDX-License-Identifier: GPL-3.0-or-later
// layerpaint-import: the importer process. Parses one model file (or, with --image, one image
// file; with --glb-images, the images in buffer views of a project's binary glTF) in a sandbox
// (import_sandbox.h) and writes the result to standard output as frames (core/import_protocol.h):
// progress, warnings, then the mesh, the image(s) or an error. Started by core::loadMesh(),
// core::loadImageFile() and core::loadGlbImages(); its output is binary, not for reading by hand.
//
//   layerpaint-import [--max-file-bytes N] [--max-vertices N] [--max-triangles N]
//                     [--max-image-pixels N] [--max-seconds S] [--require-textures]
//                     [--image | --glb-images V[:WxH],V,...] -- FILE
//   layerpaint-import --stdin    (the same arguments from standard input, each ended by a NUL,
//                                 then an empty one: a process started before it is needed)
//   layerpaint-import --probe OTHER_FILE -- FILE   (tests: what the sandbox allows, as text)
#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <optional>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include <fcntl.h>
#include <malloc.h>
#include <poll.h>
#include <sys/mman.h>
#include <sys/socket.h>
#include <unistd.h>

#include "app/import_sandbox.h"
#include "core/io/image/image_codecs.h"
#include "core/io/importer/import_protocol.h"
#include "core/io/importer/mesh_io_in_process.h"

namespace {

namespace fs = std::filesystem;

struct Options {
    core::LoadLimits limits;
    bool image = false;
    std::optional<std::vector<core::GlbImageRequest>> glbImages; // images in a binary glTF
    std::optional<std::string> probe;
    std::string file;
};

int usage(const char* problem) {
    std::fprintf(stderr,
                 "layerpaint-import: %s\nusage: layerpaint-import [--max-file-bytes N] "
                 "[--max-vertices N] [--max-triangles N] [--max-image-pixels N] [--max-seconds S] "
                 "[--require-textures] [--image | --glb-images V[:WxH],V,...] -- FILE\n(run by "
                 "LayerPaint to read files; it writes binary frames to its standard output)\n",
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

/**
 * A process started ahead waits for its request with its heap already grown and touched: a
 * fresh process otherwise spends a large part of a load in page faults (about 30 % on a glTF of
 * 150,000 vertices). Skipped when the request is there already (started for the load).
 */
void prepareWhileIdle() {
    pollfd pfd{STDIN_FILENO, POLLIN, 0};
    if (::poll(&pfd, 1, 0) != 0)
        return;
    core::imageCodecs(); // most models have images; its pages are touched below with the rest
    // Blocks up to 32 MiB come from the heap (not fresh mappings) and freed memory stays there.
    ::mallopt(M_MMAP_THRESHOLD, 32 << 20);
    ::mallopt(M_TRIM_THRESHOLD, 512 << 20);
    constexpr std::size_t kBlock = 8u << 20;
    std::vector<void*> blocks;
    for (int k = 0; k < 8; ++k)
        if (void* block = std::malloc(kBlock)) {
            // One write per page, through volatile: the compiler turns malloc + memset(0) into
            // calloc, which leaves fresh pages untouched (they are known to be zero).
            auto* bytes = static_cast<volatile unsigned char*>(block);
            for (std::size_t at = 0; at < kBlock; at += 4096)
                bytes[at] = 1;
            blocks.push_back(block);
        }
    for (void* block : blocks)
        std::free(block);
    // The code and read-only data of the program and its libraries in this process's page
    // tables: a load otherwise takes a page fault at the first touch of each of their pages.
    if (std::FILE* maps = std::fopen("/proc/self/maps", "re")) {
        char line[4096];
        while (std::fgets(line, sizeof line, maps) != nullptr) {
            unsigned long begin = 0, end = 0;
            char perms[5] = {};
            if (std::sscanf(line, "%lx-%lx %4s", &begin, &end, perms) == 3 && perms[0] == 'r' &&
                perms[1] == '-' && std::strchr(line, '/') != nullptr)
                ::madvise(reinterpret_cast<void*>(begin), end - begin, MADV_POPULATE_READ);
        }
        std::fclose(maps);
    }
}

/**
 * The request from standard input: arguments ended by NULs, then an empty one. Nothing (the
 * application ended without using this process) gives an empty list.
 */
std::vector<std::string> readRequest() {
    std::vector<std::string> args;
    std::string current, buffer(4096, '\0');
    std::size_t total = 0;
    while (true) {
        const ssize_t n = ::read(STDIN_FILENO, buffer.data(), buffer.size());
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0 || (total += std::size_t(n)) > (1u << 20))
            return {};
        for (ssize_t k = 0; k < n; ++k) {
            if (buffer[std::size_t(k)] != '\0') {
                current.push_back(buffer[std::size_t(k)]);
            } else if (current.empty()) {
                return args;
            } else {
                args.push_back(std::exchange(current, {}));
            }
        }
    }
}

/** A whole number of at most 0x7FFFFFFF, or nothing. */
std::optional<int> count(const std::string& text) {
    std::uint64_t n = 0;
    if (!number(text.c_str(), n) || n > 0x7FFFFFFF)
        return std::nullopt;
    return static_cast<int>(n);
}

/**
 * "3,7:256x128,12": buffer view indices, each with the size its image must have or not;
 * nothing when malformed.
 */
std::optional<std::vector<core::GlbImageRequest>> viewList(const char* text) {
    std::vector<core::GlbImageRequest> requests;
    const std::string list(text);
    std::size_t start = 0;
    while (start <= list.size()) {
        const std::size_t end = std::min(list.find(',', start), list.size());
        const std::string item = list.substr(start, end - start);
        const std::size_t colon = std::min(item.find(':'), item.size());
        const std::size_t x = item.find('x', colon);
        const auto view = count(item.substr(0, colon));
        if (!view)
            return std::nullopt;
        core::GlbImageRequest request{*view, 0, 0};
        if (colon < item.size()) {
            const auto width = x == std::string::npos
                                   ? std::nullopt
                                   : count(item.substr(colon + 1, x - colon - 1));
            const auto height = x == std::string::npos ? std::nullopt : count(item.substr(x + 1));
            if (!width || !height)
                return std::nullopt;
            request.width = *width;
            request.height = *height;
        }
        requests.push_back(request);
        start = end + 1;
    }
    return requests;
}

std::optional<Options> parse(const std::vector<std::string>& argv) {
    Options o;
    const std::size_t argc = argv.size();
    std::size_t i = 0;
    for (; i < argc; ++i) {
        const std::string& arg = argv[i];
        if (arg == "--") {
            ++i;
            break;
        }
        if (arg == "--image") {
            o.image = true;
        } else if (arg == "--require-textures") {
            o.limits.requireTextures = true;
        } else if (i + 1 < argc) {
            const char* value = argv[++i].c_str();
            std::uint64_t n = 0;
            if (arg == "--probe") {
                o.probe = value;
            } else if (arg == "--glb-images") {
                o.glbImages = viewList(value);
                if (!o.glbImages)
                    return std::nullopt;
            } else if (arg == "--max-seconds") {
                char* end = nullptr;
                o.limits.maxSeconds = std::strtod(value, &end);
                if (end == value || *end != '\0' || !(o.limits.maxSeconds >= 0.0))
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

/**
 * Ends the process once its answer is out, without destructors: freeing a large scene only costs
 * time, a heap that a parser damaged cannot crash the process after its answer, and the pages
 * the answer lent to the pipe (FrameWriter::lendUntilExit) must not change before the
 * application has read them (free() writes into freed blocks). The end of the output tells the
 * application the answer is complete.
 */
[[noreturn]] void endWith(bool sent) {
    ::close(STDOUT_FILENO);
    ::_exit(sent ? 0 : 1);
}

} // namespace

int main(int argc, char** argv) {
    std::vector<std::string> args(argv + std::min(argc, 1), argv + argc);
    if (args.size() == 1 && args[0] == "--stdin") {
        prepareWhileIdle();
        args = readRequest();
        if (args.empty())
            return 0;
        // The request channel is done with; reads from here on see an empty input.
        const int null = ::open("/dev/null", O_RDONLY | O_CLOEXEC);
        if (null >= 0) {
            ::dup2(null, STDIN_FILENO);
            ::close(null);
        }
    }
    const std::optional<Options> options = parse(args);
    if (!options)
        return usage("invalid arguments");
    const Options& o = *options;

    importer::SandboxOptions sandbox;
    sandbox.readable = readablePaths(o);
    // The image codecs module is loaded on the first image (its libraries are readable anyway).
    if (const core::Result<std::string> codecs = core::findImageCodecs())
        sandbox.readable.push_back(*codecs);
    sandbox.maxSeconds = core::detail::importSeconds(o.file, o.limits,
                                                     o.image ? core::detail::ImportKind::Image
                                                             : core::detail::ImportKind::Model);
    const importer::SandboxReport report = importer::applySandbox(sandbox);
    if (o.probe) {
        // Ends like a load does: without exit-time work (a sanitizer's leak check at exit needs
        // system calls the sandbox denies, and would end the process before stdout is flushed).
        const int status = probe(o, report);
        std::fflush(stdout);
        ::_exit(status);
    }

    core::importer::FrameWriter out(STDOUT_FILENO);
    out.lendUntilExit(); // each answer is sent from a scope that endWith() never leaves
    if (o.glbImages) {
        // A project's paint-layer images: sent as the textures of a mesh without triangles.
        core::Result<std::vector<core::Image>> images =
            core::loadGlbImagesInProcess(o.file, *o.glbImages, o.limits);
        core::Mesh carrier;
        if (images)
            carrier.textures = std::move(images).value();
        endWith(images ? out.mesh(carrier) : out.text(core::importer::Tag::Error, images.error()));
    }
    if (o.image) {
        const core::Result<core::Image> image = core::loadImageFileInProcess(o.file, o.limits);
        endWith(image ? out.image(*image) : out.text(core::importer::Tag::Error, image.error()));
    }
    // Reports often enough for a smooth progress bar, not once per primitive.
    double reported = -1.0;
    const core::ProgressFn progress = [&](double fraction) {
        if (fraction >= 1.0 || fraction - reported >= 0.01) {
            reported = fraction;
            out.progress(fraction);
        }
        return true; // the application ends this process to cancel
    };
    // Unchecked: the application checks and repairs what it receives (detail::finishMesh), so
    // the importer need not do it too.
    const core::Result<core::Mesh> mesh =
        core::loadMeshInProcess(o.file, progress, o.limits, core::MeshChecks::Later);
    endWith(mesh ? out.mesh(*mesh) : out.text(core::importer::Tag::Error, mesh.error()));
}
