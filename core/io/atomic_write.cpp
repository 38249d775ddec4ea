// SPDX-License-Identifier: GPL-3.0-or-later
// Atomic saves with one backup (see atomic_write.h).
#include "core/io/atomic_write.h"

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <system_error>
#include <vector>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace core {

namespace {

namespace fs = std::filesystem;
using Bytes = std::vector<std::uint8_t>;

std::string errnoText(int err) {
    return std::error_code(err, std::generic_category()).message();
}

/** Closes a file descriptor when it goes out of scope (unless released). */
class FileDescriptor {
public:
    explicit FileDescriptor(int fd = -1) : m_fd(fd) {}
    ~FileDescriptor() {
        if (m_fd >= 0)
            ::close(m_fd);
    }
    FileDescriptor(const FileDescriptor&) = delete;
    FileDescriptor& operator=(const FileDescriptor&) = delete;
    int get() const { return m_fd; }
    /** Closes now; the errno of a failed close, else 0 (NFS reports write errors here). */
    int close() {
        const int fd = m_fd;
        m_fd = -1;
        return fd >= 0 && ::close(fd) != 0 ? errno : 0;
    }

private:
    int m_fd;
};

/** Removes a file when it goes out of scope (unless released). */
class RemoveOnExit {
public:
    RemoveOnExit() = default;
    ~RemoveOnExit() {
        if (!m_path.empty())
            ::unlink(m_path.c_str());
    }
    RemoveOnExit(const RemoveOnExit&) = delete;
    RemoveOnExit& operator=(const RemoveOnExit&) = delete;
    void set(const std::string& path) { m_path = path; }
    void release() { m_path.clear(); }

private:
    std::string m_path;
};

/** Writes every byte, retrying short writes and interruptions; 0 or the errno. */
int writeAll(int fd, const std::uint8_t* data, std::size_t size) {
    while (size > 0) {
        const ssize_t n = ::write(fd, data, std::min<std::size_t>(size, 1u << 30));
        if (n < 0) {
            if (errno == EINTR)
                continue;
            return errno;
        }
        if (n == 0)
            return EIO;
        data += n;
        size -= static_cast<std::size_t>(n);
    }
    return 0;
}

/**
 * Calls make(name) with fresh hidden names next to target until it does not fail with EEXIST;
 * make returns -1 with errno set on failure. The result of the last call.
 */
template <typename Make>
int withUniqueName(const fs::path& target, const char* suffix, std::string& name, Make make) {
    static std::atomic<unsigned> counter{0};
    // Short enough that the name stays within NAME_MAX whatever the target's name.
    const std::string base = target.filename().string().substr(0, 160);
    for (int attempt = 0; attempt < 100; ++attempt) {
        name = (target.parent_path() / ("." + base + "." + std::to_string(::getpid()) + "-" +
                                        std::to_string(counter++) + suffix))
                   .string();
        const int result = make(name);
        if (result >= 0 || errno != EEXIST)
            return result;
    }
    errno = EEXIST;
    return -1;
}

/**
 * Creates a new file next to target with a unique hidden name (mode 0666 less the umask, or
 * mode when >= 0); the descriptor, or -1 with errno set.
 */
int createTemporary(const fs::path& target, const char* suffix, int mode, std::string& name) {
    return withUniqueName(target, suffix, name, [mode](const std::string& n) {
        return ::open(n.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC,
                      mode >= 0 ? static_cast<mode_t>(mode) : 0666);
    });
}

/**
 * Removes the temporary files that saves of target (or of its backup) by processes that no
 * longer run left behind: a save killed mid-write leaves its hidden ".NAME.PID-N.tmp". Files of
 * running processes, and anything that does not parse as such a name, are left alone.
 */
void removeStaleTemporaries(const fs::path& target) {
    std::error_code ec;
    for (const std::string& base : {target.filename().string().substr(0, 160),
                                    (target.filename().string() + ".bak").substr(0, 160)}) {
        const std::string prefix = "." + base + ".";
        for (fs::directory_iterator it(target.parent_path(), ec), end; !ec && it != end;
             it.increment(ec)) {
            const std::string name = it->path().filename().string();
            if (name.size() <= prefix.size() + 4 || name.rfind(prefix, 0) != 0 ||
                !name.ends_with(".tmp"))
                continue;
            const std::string middle =
                name.substr(prefix.size(), name.size() - prefix.size() - 4); // "PID-N"
            const std::size_t dash = middle.find('-');
            if (dash == std::string::npos || dash == 0 || dash + 1 == middle.size() ||
                !std::all_of(middle.begin(), middle.end(),
                             [](char c) { return c == '-' || (c >= '0' && c <= '9'); }))
                continue;
            const long pid = std::strtol(middle.substr(0, dash).c_str(), nullptr, 10);
            if (pid <= 0 || pid == ::getpid())
                continue;
            // Running (its save may be under way), or not ours to tell (EPERM): keep.
            if (::kill(static_cast<pid_t>(pid), 0) == 0 || errno != ESRCH)
                continue;
            ::unlink(it->path().c_str());
        }
    }
}

/** fsync's a folder so a rename in it survives a crash; failures are not fatal. */
void syncFolder(const fs::path& folder) {
    const int fd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd >= 0) {
        ::fsync(fd);
        ::close(fd);
    }
}

/** Writes parts into a new temporary file next to target; its name, or an Error detail. */
Result<std::string> writeTemporary(const fs::path& target,
                                   std::span<const std::span<const std::uint8_t>> parts, int mode,
                                   const char* suffix) {
    std::string name;
    FileDescriptor fd(createTemporary(target, suffix, mode, name));
    if (fd.get() < 0)
        return Error{"no file can be created in the folder " + target.parent_path().string() +
                         " (" + errnoText(errno) + ")",
                     ErrorKind::Io};
    RemoveOnExit cleanup;
    cleanup.set(name);
    if (mode >= 0)
        ::fchmod(fd.get(), static_cast<mode_t>(mode)); // the umask must not narrow the old mode
    for (const auto& part : parts)
        if (const int err = writeAll(fd.get(), part.data(), part.size()); err != 0)
            return Error{"writing failed (" + errnoText(err) + ")", ErrorKind::Io};
    if (::fsync(fd.get()) != 0)
        return Error{"writing failed (" + errnoText(errno) + ")", ErrorKind::Io};
    if (const int err = fd.close(); err != 0)
        return Error{"writing failed (" + errnoText(err) + ")", ErrorKind::Io};
    cleanup.release();
    return name;
}

/** Copies file from to a new temporary file next to target; its name, or an Error detail. */
Result<std::string> copyToTemporary(const fs::path& from, const fs::path& target, int mode) {
    std::ifstream in(from, std::ios::binary);
    if (!in)
        return Error{"the previous file cannot be read", ErrorKind::Io};
    Bytes bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (in.bad())
        return Error{"the previous file cannot be read", ErrorKind::Io};
    const std::span<const std::uint8_t> one[] = {bytes};
    return writeTemporary(target, one, mode, ".tmp");
}

/**
 * Makes backup a copy of file (a hard link when the file system has them, so nothing is copied),
 * replacing an older backup in one rename. The Error says what went wrong (no path in front).
 */
Status makeBackup(const fs::path& file, const fs::path& backup, int mode) {
    std::string temporary;
    const int linked = withUniqueName(backup, ".tmp", temporary, [&](const std::string& n) {
        return ::link(file.c_str(), n.c_str());
    });
    if (linked != 0) {
        Result<std::string> copy = copyToTemporary(file, backup, mode);
        if (!copy)
            return Error{"no backup of the previous file can be kept (" + copy.error() + ")",
                         ErrorKind::Io};
        temporary = std::move(copy).value();
    }
    if (::rename(temporary.c_str(), backup.c_str()) != 0) {
        const int err = errno;
        ::unlink(temporary.c_str());
        return Error{"no backup of the previous file can be kept as " + backup.string() + " (" +
                         errnoText(err) + ")",
                     ErrorKind::Io};
    }
    // When the backup already was a link to the file (a save killed between making the backup
    // and replacing the file), rename() does nothing and leaves the temporary link: remove it.
    ::unlink(temporary.c_str());
    return {};
}

} // namespace

Status writePartsAtomically(const std::string& path,
                            std::span<const std::span<const std::uint8_t>> parts, bool backup) {
    auto fail = [&](const std::string& detail) {
        return Status(Error{path + ": cannot be saved: " + detail, ErrorKind::Io});
    };
    if (path.empty())
        return Status(Error{"(no file name): no file was given"});
    fs::path target(path);
    std::error_code ec;
    // Replace the file a link points to, not the link.
    if (fs::is_symlink(target, ec)) {
        const fs::path real = fs::canonical(target, ec);
        if (ec)
            return fail("it is a symbolic link to a missing file");
        target = real;
    }
    if (target.parent_path().empty())
        target = fs::path(".") / target;
    if (!target.has_filename())
        return fail("the path names a folder");

    struct stat old {};
    const bool exists = ::stat(target.c_str(), &old) == 0;
    if (exists && !S_ISREG(old.st_mode))
        return fail(S_ISDIR(old.st_mode) ? "a folder of that name exists"
                                         : "it exists and is not a regular file");
    const int mode = exists ? static_cast<int>(old.st_mode & 07777) : -1;

    Result<std::string> temporary = writeTemporary(target, parts, mode, ".tmp");
    if (!temporary)
        return fail(temporary.error());
    RemoveOnExit cleanup;
    cleanup.set(temporary.value());
    if (exists && backup) {
        fs::path backupPath = target;
        backupPath += ".bak";
        if (const Status kept = makeBackup(target, backupPath, mode); !kept)
            return fail(kept.error());
    }
    if (::rename(temporary.value().c_str(), target.c_str()) != 0)
        return fail("the file cannot be replaced (" + errnoText(errno) + ")");
    cleanup.release();
    syncFolder(target.parent_path());
    removeStaleTemporaries(target);
    return {};
}

Status writeFileAtomically(const std::string& path, const void* data, std::size_t size,
                           bool keepBackup) {
    try {
        const std::span<const std::uint8_t> spans[] = {
            {static_cast<const std::uint8_t*>(data), size}};
        return writePartsAtomically(path, spans, keepBackup);
    } catch (const std::exception& e) {
        return Status(Error{path + ": cannot be saved (" + std::string(e.what()) + ")"});
    }
}

} // namespace core
