// SPDX-License-Identifier: GPL-3.0-or-later
// Atomic saving under failure: a process saving a project over and over is killed (SIGKILL) at
// many different moments, and the file on disk is always the old or the new version, complete;
// a save into a folder the user cannot write to fails, says so and leaves the file as it was.
// The saving runs in save_crash_helper (a real process to kill).
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <thread>
#include <vector>

#include <fcntl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "core/io/project/project_file.h"
#include "tests/core/io/save_crash_versions.h"
#include "tests/core/test_files.h"

namespace fs = std::filesystem;

namespace save_crash_test {

using core_test::readFile;
using core_test::TempDir;

const char* const kHelper = LAYERPAINT_SAVE_CRASH_HELPER;

/** A child process with its stdout on a pipe. */
struct Child {
    pid_t pid = -1;
    FILE* out = nullptr;
};

/**
 * Starts the helper with args; with dropToUid >= 0 the child runs as that user (needs root).
 * pid -1 on failure.
 */
Child spawnHelper(const std::vector<std::string>& args, int dropToUid = -1) {
    int fds[2];
    if (pipe(fds) != 0)
        return {};
    std::vector<char*> argv;
    argv.push_back(const_cast<char*>(kHelper));
    for (const std::string& a : args)
        argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    const pid_t pid = fork();
    if (pid == 0) {
        dup2(fds[1], STDOUT_FILENO);
        close(fds[0]);
        close(fds[1]);
        if (dropToUid >= 0 && (setgid(gid_t(dropToUid)) != 0 || setuid(uid_t(dropToUid)) != 0))
            _exit(126);
        execv(kHelper, argv.data());
        _exit(127);
    }
    close(fds[1]);
    if (pid < 0) {
        close(fds[0]);
        return {};
    }
    return {pid, fdopen(fds[0], "r")};
}

std::string readLine(FILE* in) {
    char buffer[4096];
    if (!std::fgets(buffer, sizeof buffer, in))
        return {};
    std::string line = buffer;
    while (!line.empty() && (line.back() == '\n' || line.back() == '\r'))
        line.pop_back();
    return line;
}

/** What is left to read from in (for failure messages). */
std::string rest(FILE* in) {
    std::string text;
    for (std::string line = readLine(in); !line.empty(); line = readLine(in))
        text += " | " + line;
    return text;
}

int finish(Child& child) {
    int status = 0;
    waitpid(child.pid, &status, 0);
    if (child.out)
        std::fclose(child.out);
    child = {};
    return status;
}

/** Which version path holds (0 = A, 1 = B), or -1 with why set if it is neither, complete. */
int whichVersion(const std::string& path, const save_crash::Version (&versions)[2],
                 std::string& why) {
    core::Result<core::Project> p = core::loadProject(path);
    if (!p) {
        why = p.error();
        return -1;
    }
    if (!p->state) {
        why = "no project state";
        return -1;
    }
    for (int k = 0; k < 2; ++k) {
        const save_crash::Version& v = versions[k];
        if (p->state->source != v.state.source)
            continue;
        if (p->state->brush.radius != v.state.brush.radius)
            why = "state of " + v.state.source + " mixed with another";
        else if (p->mesh.textures.size() != 1 ||
                 p->mesh.textures[0].rgba != v.mesh.textures[0].rgba)
            why = "the texture is not that of " + v.state.source;
        else if (p->mesh.indices != v.mesh.indices || p->mesh.positions != v.mesh.positions)
            why = "the geometry is not that of " + v.state.source;
        else
            return k;
        return -1;
    }
    why = "unknown source \"" + p->state->source + "\"";
    return -1;
}

std::vector<fs::path> temporaries(const fs::path& folder) {
    std::vector<fs::path> out;
    for (const auto& entry : fs::directory_iterator(folder))
        if (entry.path().filename().string().ends_with(".tmp"))
            out.push_back(entry.path());
    return out;
}

TEST(SaveCrash, KilledSavesLeaveTheOldOrTheNewVersionComplete) {
    const save_crash::Version versions[2] = {save_crash::makeVersion(0),
                                             save_crash::makeVersion(1)};
    TempDir dir;
    const std::string path = (dir.path() / "project.glb").string();
    const auto start = std::chrono::steady_clock::now();
    ASSERT_TRUE(core::saveProject(path, versions[0].mesh, versions[0].state).ok());
    const double saveUs =
        std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count();

    constexpr int kKills = 20;
    int seen[2] = {0, 0}, midSave = 0, backups = 0;
    std::size_t leftBefore = 0;
    for (int i = 0; i < kKills; ++i) {
        SCOPED_TRACE("kill " + std::to_string(i));
        Child child = spawnHelper({"loop", path});
        ASSERT_GT(child.pid, 0);
        const std::string ready = readLine(child.out);
        ASSERT_EQ(ready, "ready") << "helper: " << ready << rest(child.out);
        // Half the kills count from the start, half from the end of the first or second save
        // (B over A, A over B); the delays spread over about one and a half saves, visiting
        // early and late points alike.
        for (int k = 0; i % 2 == 1 && k <= (i / 2) % 2; ++k) {
            const std::string line = readLine(child.out);
            ASSERT_EQ(line.rfind("saved ", 0), 0u) << "helper: " << line << rest(child.out);
        }
        const double fraction = double((i * 7) % kKills) / double(kKills);
        std::this_thread::sleep_for(std::chrono::microseconds(long(fraction * 1.5 * saveUs)));
        kill(child.pid, SIGKILL);
        const std::string output = rest(child.out);
        const int status = finish(child);
        ASSERT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL)
            << "the helper ended by itself (status " << status << "): " << output;

        std::string why;
        const int version = whichVersion(path, versions, why);
        ASSERT_GE(version, 0) << why;
        ++seen[version];
        if (fs::exists(path + ".bak")) {
            ++backups;
            // loadMesh picks the format by extension.
            const fs::path copy = dir.path() / "backup-copy.glb";
            fs::copy_file(path + ".bak", copy, fs::copy_options::overwrite_existing);
            const int backup = whichVersion(copy.string(), versions, why);
            EXPECT_GE(backup, 0) << "backup: " << why;
            fs::remove(copy);
        }
        // A kill while the temporary file existed leaves it behind; it never replaces the file.
        const std::size_t left = temporaries(dir.path()).size();
        midSave += left > leftBefore ? 1 : 0;
        leftBefore = left;
    }
    // The next save clears what killed saves left behind.
    ASSERT_TRUE(core::saveProject(path, versions[1].mesh, versions[1].state).ok());
    std::string left;
    for (const fs::path& t : temporaries(dir.path()))
        left += " " + t.filename().string();
    EXPECT_TRUE(left.empty()) << "left behind:" << left;
    std::printf("[ crashes  ] %d kills: %d left version A, %d version B, %d left a temporary "
                "file, %d had a backup\n",
                kKills, seen[0], seen[1], midSave, backups);
    EXPECT_EQ(seen[0] + seen[1], kKills);
}

TEST(SaveCrash, ReadOnlyFolderLeavesTheFileIntactAndSaysSo) {
    const save_crash::Version a = save_crash::makeVersion(1);
    TempDir dir;
    const fs::path folder = dir.path() / "read-only";
    fs::create_directory(folder);
    const std::string path = (folder / "project.glb").string();
    ASSERT_TRUE(core::saveProject(path, a.mesh, a.state).ok());
    const std::string before = readFile(path);
    fs::permissions(dir.path(), fs::perms::owner_all | fs::perms::group_read |
                                    fs::perms::group_exec | fs::perms::others_read |
                                    fs::perms::others_exec);
    fs::permissions(folder, fs::perms::owner_read | fs::perms::owner_exec | fs::perms::group_read |
                                fs::perms::group_exec | fs::perms::others_read |
                                fs::perms::others_exec);
    fs::permissions(path, fs::perms::owner_read | fs::perms::group_read | fs::perms::others_read);

    std::string message;
    if (geteuid() == 0) {
        // Root writes anywhere: the save runs as "nobody" in the helper.
        Child child = spawnHelper({"save", path}, 65534);
        ASSERT_GT(child.pid, 0);
        message = readLine(child.out);
        const int status = finish(child);
        ASSERT_TRUE(WIFEXITED(status));
        if (WEXITSTATUS(status) == 126 || WEXITSTATUS(status) == 127)
            GTEST_SKIP() << "the helper cannot run as nobody here (status " << WEXITSTATUS(status)
                         << ")";
        EXPECT_EQ(WEXITSTATUS(status), 1) << message;
    } else {
        const core::Status s = core::saveProject(path, a.mesh, a.state);
        ASSERT_FALSE(s.ok());
        message = s.error();
    }
    EXPECT_EQ(message.rfind(path + ": cannot be saved", 0), 0u) << message;
    EXPECT_NE(message.find("Permission denied"), std::string::npos) << message;
    EXPECT_EQ(readFile(path), before);
    EXPECT_FALSE(fs::exists(path + ".bak"));
    EXPECT_TRUE(temporaries(folder).empty());
}

} // namespace save_crash_test
