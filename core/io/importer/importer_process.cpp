// SPDX-License-Identifier: GPL-3.0-or-later
// loadMesh() and loadImageFile(): the file is parsed by layerpaint-import in a child process
// (app/import_main.cpp). Its output (import_protocol.h) is read here under a wall-clock deadline,
// checked against the limits, then checked and repaired as a load in process is (the importer
// leaves that to this side, so it is done once); a crash, hang, abort or malformed output
// becomes one error message, and the child is always killed and reaped before returning. Every
// file gets a fresh process; keepImporterReady() only starts the next one ahead of time.
#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <future>
#include <iterator>
#include <mutex>
#include <new>
#include <sstream>
#include <string>
#include <string_view>
#include <system_error>
#include <thread>
#include <utility>
#include <vector>

#include <fcntl.h>
#include <poll.h>
#include <spawn.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "core/io/importer/import_budget.h"
#include "core/io/importer/import_protocol.h"
#include "core/io/importer/mesh_io_in_process.h"
#include "core/io/importer/program_files.h"
#include "core/io/mesh_io.h"
#include "core/model/builtin_models.h"

extern char** environ;

namespace core {

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

constexpr const char* kImporterName = "layerpaint-import";
constexpr const char* kImporterVariable = "LAYERPAINT_IMPORTER";
constexpr const char* kImporterStderrVariable = "LAYERPAINT_IMPORTER_STDERR";
/** How often cancel and the deadline are checked while waiting for the importer. */
constexpr auto kCheckInterval = std::chrono::milliseconds(100);
/**
 * Past the deadline, how long an importer is watched for processor time used: one still at work
 * is left to its processor-time limit (a busy machine slows it, not its parse), up to
 * kMaxDeadlines deadlines in all.
 */
constexpr auto kWorkWindow = std::chrono::seconds(1);
constexpr int kMaxDeadlines = 10;

/** The processor time process pid has used (user and system), in clock ticks; -1 if unknown. */
long long processorTicks(pid_t pid) {
    std::ifstream in("/proc/" + std::to_string(pid) + "/stat");
    const std::string stat((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    // The name (field 2) is in parentheses and may hold anything; utime and stime are fields
    // 14 and 15, the 12th and 13th after the name.
    const std::size_t name = stat.rfind(')');
    if (name == std::string::npos)
        return -1;
    std::istringstream fields(stat.substr(name + 1));
    std::string field;
    for (int i = 0; i < 11 && fields >> field; ++i) {
    }
    long long user = -1, system = -1;
    fields >> user >> system;
    return fields && user >= 0 && system >= 0 ? user + system : -1;
}

/** The importer program, or the problem (where it was looked for). */
Result<std::string> findImporter() {
    return findProgramFile(kImporterName, kImporterVariable, "the importer program", true);
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
    if (WIFEXITED(status) && WEXITSTATUS(status) == 1)
        return "it could not send its answer";
    if (WIFEXITED(status) && WEXITSTATUS(status) == 2)
        return "it did not understand the request (a bug: please report it)";
    if (WIFEXITED(status) && WEXITSTATUS(status) != 0)
        return "it exited with status " + std::to_string(WEXITSTATUS(status));
    return "its output ended before the answer was complete";
}

/** A started importer waiting for its request on its standard input. */
struct Process {
    pid_t pid = -1;
    int output = -1;  // its standard output (the read end, non-blocking)
    int request = -1; // its standard input (a socket: a write never raises SIGPIPE here)
    std::string program;
};

/** Kills p unless it has exited, reaps it and closes its descriptors. */
void discard(Process& p) {
    if (p.pid > 0) {
        ::kill(p.pid, SIGKILL);
        while (::waitpid(p.pid, nullptr, 0) < 0 && errno == EINTR) {
        }
    }
    for (int fd : {p.output, p.request})
        if (fd >= 0)
            ::close(fd);
    p = Process{};
}

/** Starts `program --stdin` without a shell: only standard input, output and error open. */
Result<Process> spawnImporter(const std::string& program) {
    Process p;
    p.program = program;
    int out[2], in[2];
    if (::pipe2(out, O_CLOEXEC) != 0)
        return Error{std::string("cannot start the importer (") + std::strerror(errno) + ")"};
    if (::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, in) != 0) {
        const int error = errno;
        ::close(out[0]);
        ::close(out[1]);
        return Error{std::string("cannot start the importer (") + std::strerror(error) + ")"};
    }
    p.output = out[0];
    p.request = in[0];
    ::fcntl(p.output, F_SETFL, ::fcntl(p.output, F_GETFL) | O_NONBLOCK);
    // Fewer wake-ups for big meshes; the system may refuse, which only costs speed.
    ::fcntl(p.output, F_SETPIPE_SZ, 1 << 20);

    posix_spawn_file_actions_t actions;
    posix_spawnattr_t attributes;
    ::posix_spawn_file_actions_init(&actions);
    ::posix_spawnattr_init(&attributes);
    ::posix_spawn_file_actions_adddup2(&actions, in[1], 0);
    ::posix_spawn_file_actions_adddup2(&actions, out[1], 1);
    // What a parser prints (a decoder's warning, the C library's "free(): invalid pointer" as a
    // damaged heap aborts it) is not for the user: the error message says what happened. With
    // LAYERPAINT_IMPORTER_STDERR=1 its messages (a sanitizer's report) go where ours go, unless
    // that is a regular file: the importer may not write files (RLIMIT_FSIZE 0 would kill it).
    struct stat errStat {};
    const char* passStderr = std::getenv(kImporterStderrVariable);
    if (passStderr == nullptr || std::string_view(passStderr) != "1" ||
        ::fstat(STDERR_FILENO, &errStat) != 0 || S_ISREG(errStat.st_mode))
        ::posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
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

    std::string name = program, mode = "--stdin";
    char* argv[] = {name.data(), mode.data(), nullptr};
    const int error = ::posix_spawn(&p.pid, program.c_str(), &actions, &attributes, argv, environ);
    ::posix_spawn_file_actions_destroy(&actions);
    ::posix_spawnattr_destroy(&attributes);
    ::close(out[1]);
    ::close(in[1]);
    if (error != 0) {
        p.pid = -1;
        discard(p);
        return Error{"the importer " + program + " cannot be started (" + std::strerror(error) +
                     ")"};
    }
    return p;
}

// One importer started ahead (keepImporterReady()), so that a load need not wait for the program
// and its libraries to load. It serves one request like any other.
std::mutex g_spareMutex;
Process g_spare;
bool g_keepSpare = false;

/** The spare if it runs program and is still alive; else a Process without pid. */
Process takeSpare(const std::string& program) {
    std::lock_guard lock(g_spareMutex);
    Process p = std::exchange(g_spare, Process{});
    if (p.pid > 0 && p.program == program && ::waitpid(p.pid, nullptr, WNOHANG) == 0)
        return p;
    discard(p);
    return {};
}

/** Starts a new spare if spares are wanted and none is waiting. */
void refillSpare(const std::string& program) {
    {
        std::lock_guard lock(g_spareMutex);
        if (!g_keepSpare || g_spare.pid > 0)
            return;
    }
    Result<Process> p = spawnImporter(program);
    if (!p)
        return;
    std::lock_guard lock(g_spareMutex);
    if (!g_keepSpare || g_spare.pid > 0)
        discard(*p);
    else
        g_spare = std::move(*p);
}

/**
 * refillSpare() on another thread, so that a load does not wait for the next importer to start
 * (posix_spawn returns only once the program runs). At most one at a time; the last is waited
 * for when the program ends.
 */
void refillSpareLater(const std::string& program) {
    static std::mutex refillMutex;
    static std::future<void> refill;
    std::lock_guard lock(refillMutex);
    if (refill.valid() && refill.wait_for(std::chrono::seconds(0)) != std::future_status::ready)
        return;
    refill = std::async(std::launch::async, [program] { refillSpare(program); });
}

/**
 * One run of the importer: the spare or a new process gets the request, its standard output is
 * read under a deadline, and it is killed and reaped on destruction at the latest.
 */
class ImporterRun final : public importer::FrameSource {
public:
    enum class Stop { None, Ended, TimedOut, Cancelled, Failed };

    ImporterRun(const ProgressFn& progress, double maxSeconds)
        : m_progress(progress), m_maxSeconds(std::clamp(maxSeconds, 0.1, 1e7)) {}
    ~ImporterRun() override { finish(true); }
    ImporterRun(const ImporterRun&) = delete;
    ImporterRun& operator=(const ImporterRun&) = delete;

    /** Gives program the request args; an empty string, or why it could not start. */
    std::string start(const std::string& program, const std::vector<std::string>& args) {
        m_process = takeSpare(program);
        if (m_process.pid <= 0) {
            Result<Process> started = spawnImporter(program);
            if (!started)
                return started.error();
            m_process = std::move(*started);
        }
        const Clock::time_point now = Clock::now();
        const auto limit = std::chrono::duration_cast<Clock::duration>(
            std::chrono::duration<double>(m_maxSeconds));
        m_deadline = now + limit;
        m_lastDeadline = now + limit * kMaxDeadlines;
        m_nextCheck = now + kCheckInterval;
        // The arguments, each ended by a NUL, then an empty one. An importer that has ended
        // already cannot take them; its exit status says why once its output is read.
        std::string request;
        for (const std::string& arg : args)
            request.append(arg).push_back('\0');
        request.push_back('\0');
        for (std::size_t sent = 0; sent < request.size();) {
            const ssize_t n = ::send(m_process.request, request.data() + sent,
                                     request.size() - sent, MSG_NOSIGNAL);
            if (n < 0 && errno == EINTR)
                continue;
            if (n <= 0)
                break;
            sent += static_cast<std::size_t>(n);
        }
        ::close(m_process.request);
        m_process.request = -1;
        return {};
    }

    bool read(void* data, std::size_t size) override {
        auto* p = static_cast<std::uint8_t*>(data);
        while (size > 0) {
            if (!check())
                return false;
            const ssize_t n = ::read(m_process.output, p, size);
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
            pollfd pfd{m_process.output, POLLIN, 0};
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
     * Ends the run: kills the importer and reaps it. With `kill` false (it has answered) its
     * output must end right after the answer, and the status is 0. Returns the wait status (0
     * if it never ran).
     */
    int finish(bool kill) {
        if (m_process.pid > 0 && !kill) {
            // It has answered: its output must end there (it closes it before exiting).
            std::uint8_t extra = 0;
            if (read(&extra, 1)) {
                m_extraOutput = true;
            } else if (m_stop == Stop::Ended) {
                // Nothing more can come from it. Unmapping a large load's memory takes it a
                // while: it is reaped on the side instead of waited for.
                ::kill(m_process.pid, SIGKILL);
                if (::waitpid(m_process.pid, nullptr, WNOHANG) != m_process.pid)
                    std::thread([pid = m_process.pid] {
                        while (::waitpid(pid, nullptr, 0) < 0 && errno == EINTR) {
                        }
                    }).detach();
                m_process.pid = -1;
                m_status = 0;
            }
        }
        if (m_process.pid > 0) {
            ::kill(m_process.pid, SIGKILL);
            while (::waitpid(m_process.pid, &m_status, 0) < 0 && errno == EINTR) {
            }
            m_process.pid = -1;
        }
        discard(m_process);
        return m_status;
    }

    Stop stop() const { return m_stop; }
    /** Whether it wrote more after its answer (finish(false) then kills it). */
    bool extraOutput() const { return m_extraOutput; }

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
            if (stillAtWork(now))
                return report(m_fraction);
            m_stop = Stop::TimedOut;
            return false;
        }
        return report(m_fraction);
    }

    /**
     * At the deadline: whether the importer has used processor time in the last kWorkWindow
     * (then the deadline moves a window on, up to m_lastDeadline).
     */
    bool stillAtWork(Clock::time_point now) {
        const long long ticks = processorTicks(m_process.pid);
        const bool working = ticks >= 0 && m_ticks >= 0 && ticks > m_ticks;
        const bool first = m_ticks < 0;
        m_ticks = ticks;
        if ((!first && !working) || ticks < 0 || now >= m_lastDeadline)
            return false;
        m_deadline = now + kWorkWindow;
        return true;
    }

    const ProgressFn& m_progress;
    double m_maxSeconds;
    Clock::time_point m_deadline;
    Clock::time_point m_lastDeadline;
    long long m_ticks = -1; // the importer's processor time at the last look past the deadline
    Clock::time_point m_nextCheck;
    double m_fraction = 0.0;
    Process m_process;
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

/** Runs the importer on path; mode is empty (a model), {"--image"} or {"--glb-images", LIST}. */
Result<importer::Received> runImporter(const std::string& path,
                                       const std::vector<std::string>& mode,
                                       const ProgressFn& progress, const LoadLimits& limits) {
    Result<std::string> program = findImporter();
    if (!program)
        return detail::fileError(path, program.error(), ErrorKind::Failed);
    // The importer gets the processor time; the deadline here is later unless it was given, so
    // that a parser that spins is told apart from one that waits.
    LoadLimits resolved = limits;
    const bool image = std::find(mode.begin(), mode.end(), "--image") != mode.end();
    resolved.maxSeconds = detail::importSeconds(
        path, limits, image ? detail::ImportKind::Image : detail::ImportKind::Model);
    const double deadline = limits.maxSeconds > 0.0
                                ? limits.maxSeconds
                                : detail::importWallSeconds(resolved.maxSeconds);
    std::vector<std::string> args = limitArgs(resolved);
    args.insert(args.end(), mode.begin(), mode.end());
    args.emplace_back("--");
    args.push_back(path);

    ImporterRun run(progress, deadline);
    if (std::string problem = run.start(*program, args); !problem.empty())
        return detail::fileError(path, problem, ErrorKind::Failed);
    importer::Received received =
        importer::readFrames(run, limits, [&run](double f) { return run.report(f); });
    const bool answered = received.mesh || received.image || received.error;
    const int status = run.finish(!answered || !received.malformed.empty());
    refillSpareLater(*program); // now: while loading, it would compete for the processor

    const std::string stopped = "the importer stopped: ";
    if (received.cancelled || run.stop() == ImporterRun::Stop::Cancelled)
        return detail::fileError(path, "cancelled", ErrorKind::Cancelled);
    if (run.stop() == ImporterRun::Stop::TimedOut)
        return detail::fileError(path,
                                 stopped + "it did not finish within " + secondsText(deadline));
    if (!received.malformed.empty())
        return detail::fileError(path, stopped + received.malformed);
    if (run.extraOutput())
        return detail::fileError(path, stopped + "it sent more after its answer");
    if (!answered || status != 0)
        return detail::fileError(path, stopped + describeExit(status, resolved.maxSeconds));
    return received;
}

} // namespace

namespace detail {

double importSeconds(const std::string& path, const LoadLimits& limits, ImportKind kind) {
    if (limits.maxSeconds > 0.0)
        return limits.maxSeconds;
    // A parser that hangs on a few hundred bytes is stopped in seconds; a large file, or one
    // with large companions, gets time to load.
    return importProcessorSeconds(estimateImportInput(path, kind));
}

} // namespace detail

Result<Mesh> loadMesh(const std::string& path, const ProgressFn& progress,
                      const LoadLimits& limits) {
    // Built-in models parse nothing; an empty path is refused with the usual message.
    if (path.empty() || path.rfind(kBuiltinPrefix, 0) == 0)
        return loadMeshInProcess(path, progress, limits);
    try {
        if (Result<fs::path> checked = detail::checkModelFile(path, limits); !checked)
            return checked.takeError();
        if (!reportProgress(progress, 0.0))
            return detail::fileError(path, "cancelled", ErrorKind::Cancelled);
        Result<importer::Received> received = runImporter(path, {}, progress, limits);
        if (!received)
            return received.takeError();
        if (received->error)
            return fromImporter(path, *received->error);
        if (!received->mesh)
            return detail::fileError(path, "the importer stopped: it sent no mesh");
        Mesh mesh = std::move(*received->mesh);
        // The importer sends the format loader's mesh unchecked: the checks and repairs of a
        // load in process are made here, once, on what it sent, as if it were the file itself.
        if (Status finished = detail::finishMesh(mesh, limits, path); !finished)
            return detail::fileError(path, finished.takeError());
        if (!reportProgress(progress, 1.0))
            return detail::fileError(path, "cancelled", ErrorKind::Cancelled);
        return mesh;
    } catch (const std::bad_alloc&) {
        return detail::fileError(
            path, "too large for this machine's memory (an allocation failed while loading it)",
            ErrorKind::Failed);
    } catch (const std::exception& e) {
        return detail::fileError(path, e.what(), ErrorKind::Failed);
    }
}

void keepImporterReady(bool keep) {
    {
        std::lock_guard lock(g_spareMutex);
        g_keepSpare = keep;
        if (!keep)
            discard(g_spare);
    }
    if (Result<std::string> program = findImporter(); program && keep)
        refillSpare(*program);
}

Result<Image> loadImageFile(const std::string& path, const LoadLimits& limits) {
    if (path.empty())
        return Error{"(no file name): no file was given"};
    try {
        Result<importer::Received> received = runImporter(path, {"--image"}, {}, limits);
        if (!received)
            return received.takeError();
        if (received->error)
            return fromImporter(path, *received->error);
        if (!received->image)
            return detail::fileError(path, "the importer stopped: it sent no image");
        return std::move(*received->image);
    } catch (const std::bad_alloc&) {
        return detail::fileError(
            path, "too large for this machine's memory (an allocation failed while loading it)",
            ErrorKind::Failed);
    } catch (const std::exception& e) {
        return detail::fileError(path, e.what(), ErrorKind::Failed);
    }
}

Result<std::vector<Image>> loadGlbImages(const std::string& path,
                                         const std::vector<GlbImageRequest>& requests,
                                         const LoadLimits& limits) {
    if (requests.empty())
        return std::vector<Image>{};
    try {
        // "VIEW" or "VIEW:WIDTHxHEIGHT", comma-separated.
        std::string list;
        for (const GlbImageRequest& request : requests) {
            list += (list.empty() ? "" : ",") + std::to_string(request.view);
            if (request.width > 0 && request.height > 0)
                list += ":" + std::to_string(request.width) + "x" + std::to_string(request.height);
        }
        Result<importer::Received> received = runImporter(path, {"--glb-images", list}, {}, limits);
        if (!received)
            return received.takeError();
        if (received->error)
            return fromImporter(path, *received->error);
        // The images come as the textures of a mesh without triangles.
        if (!received->mesh || received->mesh->textures.size() != requests.size() ||
            !received->mesh->positions.empty() || !received->mesh->indices.empty())
            return detail::fileError(path, "the importer stopped: it sent no images");
        return std::move(received->mesh->textures);
    } catch (const std::bad_alloc&) {
        return detail::fileError(
            path, "too large for this machine's memory (an allocation failed while loading it)",
            ErrorKind::Failed);
    } catch (const std::exception& e) {
        return detail::fileError(path, e.what(), ErrorKind::Failed);
    }
}

} // namespace core
