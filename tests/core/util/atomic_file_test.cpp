// Atomic saves and what a killed save leaves (DEVELOPERS.md non-negotiable 4, issue 11).
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <thread>
#include <vector>

#include "support/test_paths.h"
#include "util/atomic_file.h"

namespace grass {
namespace {

namespace fs = std::filesystem;

void touch(const fs::path& file) {
    std::ofstream(file) << "x";
}

// A pid that ran and is gone: a child that exits at once, reaped.
pid_t deadPid() {
    const pid_t child = ::fork();
    if (child == 0)
        ::_exit(0);
    int status = 0;
    ::waitpid(child, &status, 0);
    return child;
}

TEST(AtomicFile, StaleTemporariesOfDeadProcessesAreRemovedAndNothingElse) {
    const fs::path dir = test::scratchDir("atomic-stale");
    const std::string dead = std::to_string(deadPid());
    const std::string alive = std::to_string(::getpid());
    const std::vector<std::string> removed = {
        ".project.tmp-" + dead + ".json", ".grass-density.tmp-" + dead + ".png", ".bin.tmp-" + dead,
        ".project.tmp-" + dead + "-12.json", ".bin.tmp-" + dead + "-3"};
    const std::vector<std::string> kept = {
        "project.json",                     // the file itself
        ".project.tmp-" + alive + ".json",  // a save under way (this process)
        ".project.tmp-abc.json",            // not a pid
        "project.tmp-" + dead + ".json",    // not hidden: not ours
        ".project.tmp-" + dead + "x.json",  // digits must end the tag
        ".project.tmp-" + dead + "-.json",  // a number after the dash
        ".project.tmp-" + dead + "-2x.json",
        ".project.tmp-" + alive + "-4.json",  // this process's, numbered
    };
    for (const auto& name : removed)
        touch(dir / name);
    for (const auto& name : kept)
        touch(dir / name);
    fs::create_directories(dir / ("sub"));
    touch(dir / "sub" / (".map.tmp-" + dead + ".png"));  // subfolders are not searched

    EXPECT_EQ(removeStaleTemporaries(dir), removed.size());
    for (const auto& name : removed)
        EXPECT_FALSE(fs::exists(dir / name)) << name;
    for (const auto& name : kept)
        EXPECT_TRUE(fs::exists(dir / name)) << name;
    EXPECT_TRUE(fs::exists(dir / "sub" / (".map.tmp-" + dead + ".png")));
    EXPECT_EQ(removeStaleTemporaries(dir / "no-such-folder"), 0u);
}

// Two writers of one target in this process (the editor's worker threads) never share a
// temporary; each is still this process's.
TEST(AtomicFile, EachWriteHasATemporaryOfItsOwn) {
    const fs::path dir = test::scratchDir("atomic-unique");
    const fs::path first = temporaryPathFor(dir / "cache.json");
    const fs::path second = temporaryPathFor(dir / "cache.json");
    EXPECT_NE(first, second);
    EXPECT_EQ(first.extension(), ".json");
    touch(first);
    touch(second);
    EXPECT_EQ(removeStaleTemporaries(dir), 0u) << "this process's own are never stale";
    std::vector<std::thread> writers;
    for (int i = 0; i < 4; ++i)
        writers.emplace_back([&dir, i] {
            const std::string text(200000, char('a' + i));
            for (int k = 0; k < 5; ++k)
                EXPECT_TRUE(writeFileAtomic(dir / "shared.json", text).ok());
        });
    for (std::thread& writer : writers)
        writer.join();
    // One writer's bytes whole, never a mix.
    std::ifstream in(dir / "shared.json", std::ios::binary);
    const std::string written((std::istreambuf_iterator<char>(in)), {});
    ASSERT_EQ(written.size(), 200000u);
    EXPECT_EQ(written, std::string(200000, written.front()));
}

std::string fileBytes(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

// Nothing in `dir` but `names`: no temporary left behind.
void expectOnly(const fs::path& dir, std::vector<std::string> names) {
    std::vector<std::string> found;
    for (const auto& entry : fs::directory_iterator(dir))
        found.push_back(entry.path().filename().string());
    std::sort(found.begin(), found.end());
    std::sort(names.begin(), names.end());
    EXPECT_EQ(found, names);
}

// A copy (a mesh brought into a project) goes through a temporary and never replaces a file.
TEST(AtomicFile, ACopyNeverReplacesAFileAndLeavesNoTemporary) {
    const fs::path dir = test::scratchDir("atomic-copy");
    std::ofstream(dir / "a.glb", std::ios::binary) << std::string(100000, 'a');
    std::ofstream(dir / "b.glb", std::ios::binary) << "another mesh";
    fs::create_directories(dir / "to");
    auto copied = copyFileAtomic(dir / "a.glb", dir / "to/rock.glb");
    ASSERT_TRUE(copied.ok()) << copied.error().str();
    EXPECT_TRUE(*copied);
    EXPECT_EQ(fileBytes(dir / "to/rock.glb"), fileBytes(dir / "a.glb"));
    auto again = copyFileAtomic(dir / "b.glb", dir / "to/rock.glb");
    ASSERT_TRUE(again.ok()) << again.error().str();
    EXPECT_FALSE(*again) << "a file there is kept";
    EXPECT_EQ(fileBytes(dir / "to/rock.glb"), fileBytes(dir / "a.glb"));
    // A source that cannot be read: an error naming the target and the source, nothing made.
    auto missing = copyFileAtomic(dir / "gone.glb", dir / "to/gone.glb");
    ASSERT_FALSE(missing.ok());
    EXPECT_EQ(missing.error().path, (dir / "to/gone.glb").string());
    EXPECT_NE(missing.error().message.find("gone.glb"), std::string::npos)
        << missing.error().message;
    expectOnly(dir / "to", {"rock.glb"});
}

// Two copies to one target at once (two threads, as the editor's import worker and its window):
// one is whole under the name, the other is told it found a file there; no error, no mixture.
TEST(AtomicFile, TwoCopiesToOneTargetAtOnceLeaveOneWholeFile) {
    const fs::path dir = test::scratchDir("atomic-copy-race");
    std::ofstream(dir / "a.glb", std::ios::binary) << std::string(1 << 20, 'a');
    std::ofstream(dir / "b.glb", std::ios::binary) << std::string(1 << 20, 'b');
    for (int round = 0; round < 20; ++round) {
        const fs::path to = dir / ("round" + std::to_string(round));
        fs::create_directories(to);
        Result<bool> first = false, second = false;
        std::thread other([&] { second = copyFileAtomic(dir / "b.glb", to / "rock.glb"); });
        first = copyFileAtomic(dir / "a.glb", to / "rock.glb");
        other.join();
        ASSERT_TRUE(first.ok()) << first.error().str();
        ASSERT_TRUE(second.ok()) << second.error().str();
        EXPECT_NE(*first, *second) << "round " << round << ": exactly one copy is the file";
        EXPECT_EQ(fileBytes(to / "rock.glb"), fileBytes(dir / (*first ? "a.glb" : "b.glb")));
        expectOnly(to, {"rock.glb"});
    }
}

TEST(AtomicFile, TemporaryNamesAreFoundAgain) {
    const fs::path dir = test::scratchDir("atomic-names");
    // The writer's own temporary of a save in progress is never taken for stale.
    const fs::path temporary = temporaryPathFor(dir / "project.json");
    touch(temporary);
    EXPECT_EQ(removeStaleTemporaries(dir), 0u);
    EXPECT_TRUE(fs::exists(temporary));
    ASSERT_TRUE(writeFileAtomic(dir / "project.json", "{}").ok());
    EXPECT_TRUE(fs::exists(dir / "project.json"));
}

}  // namespace
}  // namespace grass
