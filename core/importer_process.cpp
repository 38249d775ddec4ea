// SPDX-License-Identifier: GPL-3.0-or-later
// loadMesh() and loadImageFile(): the file is parsed by layerpaint-import in a child process
// (app/import_main.cpp). Its output (import_protocol.h) is read here under a wall-clock deadline,
// checked against the limits and validated again; a crash, hang, abort or malformed output
// becomes one error message, and the child is always killed and reaped before returning.
#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <new>
#include <string>
#include <system_error>
#include <vector>

#include <fcntl.h>
#include <poll.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include "core/builtin_models.h"
#include "core/import_protocol.h"
#include "core/mesh_io.h"
#include "core/mesh_io_in_process.h"

extern char** environ;

// Where the importer is installed, relative to the folder of the programs (set by CMake from
// the install directories).
#ifndef LAYERPAINT_LIBEXEC_FROM_BIN
#define LAYERPAINT_LIBEXEC_FROM_BIN "../libexec"
#endif

namespace core {

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

constexpr const char* kImporterName = "layerpaint-import";
constexpr const char* kImporterVariable = "LAYERPAINT_IMPORTER";
/** How often cancel and the deadline are checked while waiting for the importer. */
constexpr auto kCheckInterval = std::chrono::milliseconds(100);

bool executable(const fs::path& path) {
    std::error_code ec;
    return fs::is_regular_file(path, ec) && ::access(path.c_str(), X_OK) == 0;
}

/** The importer program, or the problem (where it was looked for). */
Result<std::string> findImporter() {
    if (const char* configured = std::getenv(kImporterVariable);
        configured != nullptr && *configured != '\0') {
        if (executable(configured))
            return std::string(configured);
        return Error{std::string("the importer program ") + configured + " (set in " +
                     kImporterVariable + ") does not exist or cannot be run"};
    }
    std::error_code ec;
    const fs::path self = fs::read_symlink("/proc/self/exe", ec);
    if (ec)
        return Error{std::string("the importer program ") + kImporterName +
                     " cannot be found (the running program's folder is unknown; set " +
                     kImporterVariable + " to its path)"};
    const fs::path beside = self.parent_path() / kImporterName;
    const fs::path installed =
        (self.parent_path() / LAYERPAINT_LIBEXEC_FROM_BIN / "layerpaint" / kImporterName)
            .lexically_normal();
    for (const fs::path& candidate : {beside, installed})
        if (executable(candidate))
            return candidate.string();
    return Error{std::string("the importer program ") + kImporterName + " is missing (looked for " +
                 beside.string() + " and " + installed.string() + "; set " + kImporterVariable +
                 " to its path)"};
}

std::string signalName(int sig) {
#if defined(__GLIBC__) && (__GLIBC__ > 2 || (__GLIBC__ == 2 && __GLIBC_MINOR__ >= 32))
    if (const char* abbrev = ::sigabbrev_np(sig))
        return std::string("SIG") + abbrev;
#endif
    return "signal " + std::to_string(sig);
}

std::string secondsText(double seconds) {
    const long long whole = std::llround(seconds);
    return std::to_string(whole) + (whole == 1 ? " second" : " seconds");
}

/** What ended the importer, in plain words ("it crashed (segmentation fault)"). */
std::string describeExit(int status, double maxSeconds) {
    if (WIFSIGNALED(status)) {
        switch (const int sig = WTERMSIG(status)) {
        case SIGSEGV:
            return "it crashed (segmentation fault)";
        case SIGBUS:
            return "it crashed (bus error)";
        case SIGILL:
            return "it crashed (illegal instruction)";
        case SIGFPE:
            return "it crashed (arithmetic error)";
        case SIGABRT:
            return "it aborted";
        case SIGXCPU:
            return "it used more than " + secondsText(maxSeconds) + " of processor time";
        case SIGXFSZ:
            return "it tried to write a file";
        case SIGSYS:
            return "it made a forbidden system call";
        case SIGKILL:
            return "it was killed (perhaps it ran out of memory)";
        default:
            return "it was ended by " + signalName(sig);
        }
    }
    if (WIFEXITED(status) && WEXITSTATUS(status) != 0)
        return "it exited with status " + std::to_string(WEXITSTATUS(status));
    return "its output ended before the answer was complete";
}

/**
 * One run of the importer: spawned without a shell, its standard output read through a pipe
 * under a deadline, killed and reaped on destruction at the latest.
 */
class ImporterRun final : public importer::FrameSource {
public:
    enum class Stop { None, Ended, TimedOut, Cancelled, Failed };

    ImporterRun(const ProgressFn& progress, double maxSeconds)
        : m_progress(progress), m_maxSeconds(maxSeconds),
          m_deadline(Clock::now() +
                     std::chrono::duration_cast<Clock::duration>(
                         std::chrono::duration<double>(std::clamp(maxSeconds, 0.1, 1e7)))),
          m_nextCheck(Clock::now() + kCheckInterval) {}

    ~ImporterRun() override { finish(true); }
    ImporterRun(const ImporterRun&) = delete;
    ImporterRun& operator=(const ImporterRun&) = delete;

    /** Starts program with args; an empty string, or why it could not start. */
    std::string start(const std::string& program, const std::vector<std::string>& args) {
        int fds[2];
        if (::pipe2(fds, O_CLOEXEC) != 0)
            return std::string("cannot start the importer (") + std::strerror(errno) + ")";
        m_fd = fds[0];
        ::fcntl(m_fd, F_SETFL, ::fcntl(m_fd, F_GETFL) | O_NONBLOCK);
        // Fewer wake-ups for big meshes; the system may refuse, which only costs speed.
        ::fcntl(m_fd, F_SETPIPE_SZ, 1 << 20);

        posix_spawn_file_actions_t actions;
        posix_spawnattr_t attributes;
        ::posix_spawn_file_actions_init(&actions);
        ::posix_spawnattr_init(&attributes);
        ::posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
        ::posix_spawn_file_actions_adddup2(&actions, fds[1], 1);
#if defined(__GLIBC__) && (__GLIBC__ > 2 || (__GLIBC__ == 2 && __GLIBC_MINOR__ >= 34))
        ::posix_spawn_file_actions_addclosefrom_np(&actions, 3);
#endif
        // Default dispositions and no blocked signals, whatever this process set up.
        sigset_t none, defaults;
        sigemptyset(&none);
        sigfillset(&defaults);
        sigdelset(&defaults, SIGKILL);
        sigdelset(&defaults, SIGSTOP);
        ::posix_spawnattr_setsigmask(&attributes, &none);
        ::posix_spawnattr_setsigdefault(&attributes, &defaults);
        ::posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETSIGDEF);

        std::vector<char*> argv;
        std::string name = program;
        argv.push_back(name.data());
        std::vector<std::string> owned = args;
        for (std::string& a : owned)
            argv.push_back(a.data());
        argv.push_back(nullptr);
        const int error =
            ::posix_spawn(&m_pid, program.c_str(), &actions, &attributes, argv.data(), environ);
        ::posix_spawn_file_actions_destroy(&actions);
        ::posix_spawnattr_destroy(&attributes);
        ::close(fds[1]);
        if (error != 0) {
            m_pid = -1;
            return "the importer " + program + " cannot be started (" + std::strerror(error) + ")";
        }
        return {};
    }

    bool read(void* data, std::size_t size) override {
        auto* p = static_cast<std::uint8_t*>(data);
        while (size > 0) {
            if (!check())
                return false;
            const ssize_t n = ::read(m_fd, p, size);
            if (n > 0) {
                p += n;
                size -= static_cast<std::size_t>(n);
                continue;
            }
            if (n == 0) {
                m_stop = Stop::Ended;
                return false;
            }
            if (errno == EINTR)
                continue;
            if (errno != EAGAIN && errno != EWOULDBLOCK) {
                m_stop = Stop::Failed;
                return false;
            }
            pollfd pfd{m_fd, POLLIN, 0};
            const auto wait = std::chrono::duration_cast<std::chrono::milliseconds>(
                std::min(m_nextCheck, m_deadline) - Clock::now());
            ::poll(&pfd, 1, static_cast<int>(std::max<long long>(1, wait.count())));
        }
        return true;
    }

    /** Forwards a progress report; false when it asks to cancel. */
    bool report(double fraction) {
        m_fraction = fraction;
        if (!reportProgress(m_progress, fraction)) {
            m_stop = Stop::Cancelled;
            return false;
        }
        return true;
    }

    /**
     * Ends the run: kills the importer unless `kill` is false and it exits by itself before the
     * deadline, and reaps it. Returns its wait status (0 if it never ran).
     */
    int finish(bool kill) {
        if (m_pid > 0) {
            if (!kill) {
                // It has answered: its output must end there, then it must exit.
                std::uint8_t extra = 0;
                if (read(&extra, 1))
                    m_extraOutput = true;
                while (!m_extraOutput && m_stop == Stop::Ended) {
                    const pid_t r = ::waitpid(m_pid, &m_status, WNOHANG);
                    if (r == m_pid) {
                        m_pid = -1;
                        break;
                    }
                    if (r < 0 && errno != EINTR)
                        break;
                    if (!check())
                        break;
                    ::usleep(200);
                }
            }
            if (m_pid > 0) {
                ::kill(m_pid, SIGKILL);
                while (::waitpid(m_pid, &m_status, 0) < 0 && errno == EINTR) {
                }
                m_pid = -1;
            }
        }
        if (m_fd >= 0) {
            ::close(m_fd);
            m_fd = -1;
        }
        return m_status;
    }

    Stop stop() const {
        return m_stop;
    }
    /** Whether it wrote more after its answer (finish(false) then kills it). */
    bool extraOutput() const {
        return m_extraOutput;
    }

private:
    /** Every kCheckInterval: the deadline and cancel. False once either stops the run. */
    bool check() {
        if (m_stop == Stop::TimedOut || m_stop == Stop::Cancelled || m_stop == Stop::Failed)
            return false;
        const Clock::time_point now = Clock::now();
        if (now < m_nextCheck && now < m_deadline)
            return true;
        m_nextCheck = now + kCheckInterval;
        if (now >= m_deadline) {
            m_stop = Stop::TimedOut;
            return false;
        }
        return report(m_fraction);
    }

    const ProgressFn& m_progress;
    double m_maxSeconds;
    Clock::time_point m_deadline;
    Clock::time_point m_nextCheck;
    double m_fraction = 0.0;
    pid_t m_pid = -1;
    int m_fd = -1;
    int m_status = 0;
    Stop m_stop = Stop::None;
    bool m_extraOutput = false;
};

std::vector<std::string> limitArgs(const LoadLimits& limits) {
    std::vector<std::string> args = {"--max-file-bytes",   std::to_string(limits.maxFileBytes),
                                     "--max-vertices",     std::to_string(limits.maxVertices),
                                     "--max-triangles",    std::to_string(limits.maxTriangles),
                                     "--max-image-pixels", std::to_string(limits.maxImagePixels),
                                     "--max-seconds",      std::to_string(limits.maxSeconds)};
    if (limits.requireTextures)
        args.emplace_back("--require-textures");
    return args;
}

/** "path: problem", keeping a message from the importer that already names the file. */
Error fromImporter(const std::string& path, const std::string& message) {
    if (message.rfind(path + ": ", 0) == 0)
        return Error{message};
    return detail::fileError(path, message);
}

/** Runs the importer on path; mode is "--image" or empty. */
Result<importer::Received> runImporter(const std::string& path, const char* mode,
                                       const ProgressFn& progress, const LoadLimits& limits) {
    Result<std::string> program = findImporter();
    if (!program)
        return detail::fileError(path, program.error());
    std::vector<std::string> args = limitArgs(limits);
    if (mode != nullptr)
        args.emplace_back(mode);
    args.emplace_back("--");
    args.push_back(path);

    ImporterRun run(progress, limits.maxSeconds);
    if (std::string problem = run.start(*program, args); !problem.empty())
        return detail::fileError(path, problem);
    importer::Received received =
        importer::readFrames(run, limits, [&run](double f) { return run.report(f); });
    const bool answered = received.mesh || received.image || received.error;
    const int status = run.finish(!answered || !received.malformed.empty());

    const std::string stopped = "the importer stopped: ";
    if (received.cancelled || run.stop() == ImporterRun::Stop::Cancelled)
        return detail::fileError(path, "cancelled");
    if (run.stop() == ImporterRun::Stop::TimedOut)
        return detail::fileError(path, stopped + "it did not finish within " +
                                           secondsText(limits.maxSeconds));
    if (!received.malformed.empty())
        return detail::fileError(path, stopped + received.malformed);
    if (run.extraOutput())
        return detail::fileError(path, stopped + "it sent more after its answer");
    if (!answered || status != 0)
        return detail::fileError(path, stopped + describeExit(status, limits.maxSeconds));
    return received;
}

} // namespace

Result<Mesh> loadMesh(const std::string& path, const ProgressFn& progress,
                      const LoadLimits& limits) {
    // Built-in models parse nothing; an empty path is refused with the usual message.
    if (path.empty() || path.rfind(kBuiltinPrefix, 0) == 0)
        return loadMeshInProcess(path, progress, limits);
    try {
        if (Result<fs::path> checked = detail::checkModelFile(path, limits); !checked)
            return Error{checked.error()};
        if (!reportProgress(progress, 0.0))
            return detail::fileError(path, "cancelled");
        Result<importer::Received> received = runImporter(path, nullptr, progress, limits);
        if (!received)
            return Error{received.error()};
        if (received->error)
            return fromImporter(path, *received->error);
        if (!received->mesh)
            return detail::fileError(path, "the importer stopped: it sent no mesh");
        Mesh mesh = std::move(*received->mesh);
        // Its output is checked as if it came from the file itself.
        const std::size_t warnings = mesh.warnings.size();
        if (std::string problem = detail::finishMesh(mesh, limits); !problem.empty())
            return detail::fileError(path, "the importer sent an invalid mesh (" + problem + ")");
        if (mesh.warnings.size() != warnings)
            mesh.warnings.push_back("the importer sent values that had to be repaired");
        if (!reportProgress(progress, 1.0))
            return detail::fileError(path, "cancelled");
        return mesh;
    } catch (const std::bad_alloc&) {
        return detail::fileError(path, "not enough memory to load the file");
    } catch (const std::exception& e) {
        return detail::fileError(path, e.what());
    }
}

Result<Image> loadImageFile(const std::string& path, const LoadLimits& limits) {
    if (path.empty())
        return Error{"(no file name): no file was given"};
    try {
        Result<importer::Received> received = runImporter(path, "--image", {}, limits);
        if (!received)
            return Error{received.error()};
        if (received->error)
            return fromImporter(path, *received->error);
        if (!received->image)
            return detail::fileError(path, "the importer stopped: it sent no image");
        return std::move(*received->image);
    } catch (const std::bad_alloc&) {
        return detail::fileError(path, "not enough memory to load the file");
    } catch (const std::exception& e) {
        return detail::fileError(path, e.what());
    }
}

} // namespace core
