// SPDX-License-Identifier: GPL-3.0-or-later
// Resource limits, Landlock and seccomp for layerpaint-import. Landlock's ABI is probed at run
// time: ABI 1 restricts file access, 2 adds renames across folders, 3 truncation, 4 TCP, 5 device
// ioctls, 6 abstract Unix sockets and signals to other processes; a kernel without it (or with
// it disabled) leaves file access unrestricted and everything else still applies.
#include "app/import_sandbox.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include <fcntl.h>
#include <linux/audit.h>
#include <linux/filter.h>
#include <linux/seccomp.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <unistd.h>

#ifndef SYS_landlock_create_ruleset
#define SYS_landlock_create_ruleset 444
#define SYS_landlock_add_rule 445
#define SYS_landlock_restrict_self 446
#endif
#ifndef SYS_close_range
#define SYS_close_range 436
#endif

#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define LAYERPAINT_SHADOW_MEMORY 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer) ||                         \
    __has_feature(memory_sanitizer)
#define LAYERPAINT_SHADOW_MEMORY 1
#endif
#endif

namespace importer {

namespace {

// The kernel's Landlock interface (linux/landlock.h), spelled out here because the installed
// headers may predate the ABI versions the running kernel offers.
struct RulesetAttr {
    std::uint64_t handledAccessFs;
    std::uint64_t handledAccessNet; // ABI 4
    std::uint64_t scoped;           // ABI 6
};
struct __attribute__((packed)) PathBeneathAttr {
    std::uint64_t allowedAccess;
    std::int32_t parentFd;
};
constexpr std::uint32_t kCreateRulesetVersion = 1u << 0;
constexpr int kRulePathBeneath = 1;
constexpr std::uint64_t kExecute = 1u << 0;
constexpr std::uint64_t kReadFile = 1u << 2;
constexpr std::uint64_t kReadDir = 1u << 3;
constexpr std::uint64_t kFsAbi1 = (1u << 13) - 1;        // execute .. make symlink
constexpr std::uint64_t kRefer = 1u << 13;               // ABI 2
constexpr std::uint64_t kTruncate = 1u << 14;            // ABI 3
constexpr std::uint64_t kIoctlDev = 1u << 15;            // ABI 5
constexpr std::uint64_t kNetTcp = (1u << 0) | (1u << 1); // ABI 4: bind, connect
constexpr std::uint64_t kScopes = (1u << 0) | (1u << 1); // ABI 6: abstract sockets, signals

int landlockAbi() {
    const long abi = ::syscall(SYS_landlock_create_ruleset, nullptr, 0, kCreateRulesetVersion);
    return abi > 0 ? static_cast<int>(abi) : 0;
}

bool addRule(int ruleset, const std::string& path, std::uint64_t access) {
    const int fd = ::open(path.c_str(), O_PATH | O_CLOEXEC);
    if (fd < 0)
        return false;
    struct stat st {};
    if (::fstat(fd, &st) != 0) {
        ::close(fd);
        return false;
    }
    // Files take only the rights that apply to files.
    if (!S_ISDIR(st.st_mode))
        access &= kExecute | kReadFile;
    PathBeneathAttr rule{access, fd};
    const bool ok = ::syscall(SYS_landlock_add_rule, ruleset, kRulePathBeneath, &rule, 0) == 0;
    ::close(fd);
    return ok;
}

bool applyLandlock(int abi, const std::vector<std::string>& readable) {
    RulesetAttr attr{kFsAbi1, 0, 0};
    if (abi >= 2)
        attr.handledAccessFs |= kRefer;
    if (abi >= 3)
        attr.handledAccessFs |= kTruncate;
    if (abi >= 5)
        attr.handledAccessFs |= kIoctlDev;
    if (abi >= 4)
        attr.handledAccessNet = kNetTcp;
    if (abi >= 6)
        attr.scoped = kScopes;
    const std::size_t size = abi >= 6   ? sizeof(RulesetAttr)
                             : abi >= 4 ? offsetof(RulesetAttr, scoped)
                                        : offsetof(RulesetAttr, handledAccessNet);
    const int ruleset = static_cast<int>(::syscall(SYS_landlock_create_ruleset, &attr, size, 0u));
    if (ruleset < 0)
        return false;
    for (const std::string& path : readable)
        addRule(ruleset, path, kReadFile | kReadDir);
    // Libraries loaded late (plugins, character set tables) and this process's own /proc entry.
    for (const char* system : {"/usr", "/lib", "/lib64", "/proc/self"})
        addRule(ruleset, system, kReadFile | kReadDir | kExecute);
    const bool ok = ::syscall(SYS_landlock_restrict_self, ruleset, 0u) == 0;
    ::close(ruleset);
    return ok;
}

bool applySeccomp() {
#if defined(__x86_64__)
    constexpr std::uint32_t arch = AUDIT_ARCH_X86_64;
#elif defined(__aarch64__)
    constexpr std::uint32_t arch = AUDIT_ARCH_AARCH64;
#else
    return false;
#endif
#if defined(__x86_64__) || defined(__aarch64__)
    // Refused with EACCES: new sockets (no network, no connection to local services), running
    // programs, and reading or writing other processes.
    const std::uint32_t denied[] = {SYS_socket, SYS_execve,           SYS_execveat,
                                    SYS_ptrace, SYS_process_vm_readv, SYS_process_vm_writev};
    std::vector<sock_filter> filter = {
        BPF_STMT(BPF_LD | BPF_W | BPF_ABS, offsetof(seccomp_data, arch)),
        // Another system call convention (e.g. 32-bit calls on x86-64) would bypass the rest.
        BPF_JUMP(BPF_JMP | BPF_JEQ | BPF_K, arch, 1, 0),
        BPF_STMT(BPF_RET | BPF_K, SECCOMP_RET_KILL_PROCESS),
        BPF_STMT(BPF_LD | BPF_W | BPF_ABS, offsetof(seccomp_data, nr)),
    };
#if defined(__x86_64__)
    // x32 calls have bit 30 set.
    filter.push_back(BPF_JUMP(BPF_JMP | BPF_JGE | BPF_K, 0x40000000u, 0, 1));
    filter.push_back(BPF_STMT(BPF_RET | BPF_K, SECCOMP_RET_ERRNO | EACCES));
#endif
    for (const std::uint32_t nr : denied) {
        filter.push_back(BPF_JUMP(BPF_JMP | BPF_JEQ | BPF_K, nr, 0, 1));
        filter.push_back(BPF_STMT(BPF_RET | BPF_K, SECCOMP_RET_ERRNO | EACCES));
    }
    filter.push_back(BPF_STMT(BPF_RET | BPF_K, SECCOMP_RET_ALLOW));
    const sock_fprog program{static_cast<unsigned short>(filter.size()), filter.data()};
    return ::prctl(PR_SET_SECCOMP, SECCOMP_MODE_FILTER, &program) == 0;
#endif
}

void setLimit(int resource, rlim_t soft, rlim_t hard) {
    rlimit current{};
    if (::getrlimit(resource, &current) == 0 && current.rlim_max != RLIM_INFINITY)
        hard = std::min(hard, current.rlim_max);
    const rlimit limit{std::min(soft, hard), hard};
    ::setrlimit(resource, &limit);
}

} // namespace

SandboxReport applySandbox(const SandboxOptions& options) {
    SandboxReport report;
    // Only standard input (/dev/null), output (the pipe) and error stay open.
    ::syscall(SYS_close_range, 3u, ~0u, 0u);

    setLimit(RLIMIT_CORE, 0, 0);
    setLimit(RLIMIT_FSIZE, 0, 0);
    setLimit(RLIMIT_NOFILE, 64, 64);
    const double seconds = std::clamp(options.maxSeconds, 1.0, 1e7);
    const auto cpu = static_cast<rlim_t>(std::ceil(seconds)) + 1;
    setLimit(RLIMIT_CPU, cpu, cpu + 5); // SIGXCPU at the soft limit, SIGKILL at the hard one
#ifndef LAYERPAINT_SHADOW_MEMORY
    // Generous: the machine's memory (at least 4 GiB) plus room for libraries and threads.
    const long pages = ::sysconf(_SC_PHYS_PAGES), pageSize = ::sysconf(_SC_PAGESIZE);
    const std::uint64_t physical =
        pages > 0 && pageSize > 0 ? std::uint64_t(pages) * std::uint64_t(pageSize) : 0;
    const std::uint64_t bytes = std::max<std::uint64_t>(physical, 4ull << 30) + (2ull << 30);
    setLimit(RLIMIT_AS, bytes, bytes);
    report.addressSpaceLimit = true;
#endif

    // No parent-death signal: it follows the thread that started the process, and a process
    // started ahead outlives that thread. If the application dies, this process ends on the
    // end of its input (still waiting), on its next write, or at its processor-time limit.
    report.noNewPrivs = ::prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0) == 0;
    report.landlockAbi = landlockAbi();
    if (report.landlockAbi > 0 && report.noNewPrivs)
        report.landlock = applyLandlock(report.landlockAbi, options.readable);
    if (report.noNewPrivs)
        report.seccomp = applySeccomp();
    return report;
}

} // namespace importer
