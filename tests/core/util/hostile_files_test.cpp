// Hostile files and careless paths (issue 22): the core pieces that keep the promises of
// docs/reliability.md "Hostile input". The command-line side of each class is in
// tests/cli/hostile_input_test.sh.
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>

#include "physics/step_count.h"
#include "project/json_reader.h"
#include "project/project.h"
#include "project/project_inputs.h"
#include "support/test_paths.h"
#include "util/atomic_file.h"
#include "util/folder_lock.h"
#include "util/json_text.h"
#include "util/path_inside.h"

namespace grass {
namespace {

namespace fs = std::filesystem;

void write(const fs::path& file, const std::string& text) {
    std::ofstream(file, std::ios::binary) << text;
}

std::string contents(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// Runs `body` in a child whose writes fail past `limitBytes` (RLIMIT_FSIZE: EFBIG, what a full
// disk gives as ENOSPC; SIGXFSZ ignored so the write returns the error). The child exits 0 when
// `body` returns true. Only for code that starts no threads: a forked child has none but the
// one that forked.
bool inChildWithFileSizeLimit(rlim_t limitBytes, const std::function<bool()>& body) {
    const pid_t child = ::fork();
    if (child == 0) {
        ::signal(SIGXFSZ, SIG_IGN);
        const rlimit limit{limitBytes, limitBytes};
        ::setrlimit(RLIMIT_FSIZE, &limit);
        ::_exit(body() ? 0 : 1);
    }
    int status = 0;
    ::waitpid(child, &status, 0);
    return WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

// --- JSON nesting -------------------------------------------------------------------------------

TEST(JsonText, DepthCountsBracketsOutsideStrings) {
    EXPECT_EQ(jsonDepth("1"), 0u);
    EXPECT_EQ(jsonDepth(R"({"a": [1, {"b": []}]})"), 4u);
    EXPECT_EQ(jsonDepth(R"({"a": "[[[[\"[["})"), 1u);
}

TEST(JsonText, TooDeepIsRefusedBeforeParsing) {
    const std::string deep = std::string(50000, '[') + std::string(50000, ']');
    const auto parsed = parseJsonText(deep, "deep.json");
    ASSERT_FALSE(parsed);
    EXPECT_EQ(parsed.error().path, "deep.json");
    EXPECT_NE(parsed.error().message.find("256 levels"), std::string::npos);
    EXPECT_TRUE(parseJsonText(std::string(256, '[') + std::string(256, ']'), "ok.json"));
    EXPECT_FALSE(parseJsonText("{\"a\": ", "cut.json"));
}

TEST(JsonText, ProjectNestedTooDeepIsRefusedWithItsName) {
    const std::string text = R"({"format": "grass-project", "version": 1, "x": )" +
                             std::string(100000, '[') + std::string(100000, ']') + "}";
    const auto project = core::parseProject(text, "deep/project.json");
    ASSERT_FALSE(project);
    EXPECT_NE(project.error().str().find("deep/project.json"), std::string::npos);
    EXPECT_NE(project.error().str().find("nested"), std::string::npos);
}

// --- Special files and size caps ----------------------------------------------------------------

TEST(ReadFile, RefusesAFifoWithoutWaiting) {
    const fs::path dir = test::scratchDir("hostile-fifo");
    ASSERT_EQ(::mkfifo((dir / "project.json").c_str(), 0600), 0);
    const auto read = readFile(dir / "project.json");  // would block for ever if opened plainly
    ASSERT_FALSE(read);
    EXPECT_NE(read.error().message.find("FIFO"), std::string::npos);
    EXPECT_FALSE(checkRegularFile(dir / "project.json"));
}

TEST(ReadFile, RefusesDevicesEvenThroughALink) {
    const fs::path dir = test::scratchDir("hostile-device");
    fs::create_symlink("/dev/zero", dir / "mesh.glb");
    const auto read = readFile(dir / "mesh.glb");
    ASSERT_FALSE(read);
    EXPECT_EQ(read.error().path, (dir / "mesh.glb").string());
    EXPECT_NE(read.error().message.find("device"), std::string::npos);
    EXPECT_FALSE(readFile(dir));  // a folder
}

TEST(ReadFile, RefusesAFileOverTheCapBeforeReadingIt) {
    const fs::path dir = test::scratchDir("hostile-big");
    write(dir / "project.json", "");
    fs::resize_file(dir / "project.json", 200u << 20);  // sparse: no disk used
    const auto read = readFile(dir / "project.json", MAX_JSON_FILE_BYTES);
    ASSERT_FALSE(read);
    EXPECT_NE(read.error().message.find("200 MiB"), std::string::npos);
    EXPECT_NE(read.error().message.find("64 MiB"), std::string::npos);
    write(dir / "small.json", "{}");
    EXPECT_EQ(*readFile(dir / "small.json", MAX_JSON_FILE_BYTES), "{}");
}

// --- Writes that fail part way --------------------------------------------------------------------

TEST(DiskFull, WriteFileAtomicFailsAndKeepsTheOldFile) {
    const fs::path dir = test::scratchDir("hostile-full-text");
    write(dir / "report.json", "old");
    EXPECT_TRUE(inChildWithFileSizeLimit(4096, [&] {
        const auto written = writeFileAtomic(dir / "report.json", std::string(100000, 'x'));
        return !written && written.error().path == (dir / "report.json").string();
    }));
    EXPECT_EQ(contents(dir / "report.json"), "old");
    EXPECT_EQ(removeStaleTemporaries(dir), 0u);  // the failed write removed its temporary
    EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
}

// The image writers (PNG, TIFF and EXR maps, PNG and EXR renders) under the same limit are
// tested in processes of their own by cli.hostile_disk_full: a forked child of this test
// process cannot run them, since OpenEXR's and OpenImageIO's thread pools, started by earlier
// tests, have no threads in the child and the write would wait on them for ever.

TEST(DiskFull, AnEmptyTemporaryNeverReplacesAFile) {
    const fs::path dir = test::scratchDir("hostile-empty-temp");
    write(dir / "map.png", "old");
    const fs::path temporary = temporaryPathFor(dir / "map.png");
    write(temporary, "");
    EXPECT_FALSE(commitTemporaryFile(temporary, dir / "map.png"));
    EXPECT_EQ(contents(dir / "map.png"), "old");
    EXPECT_FALSE(fs::exists(temporary));
}

TEST(CheckFileWritable, TriesTheWriteBeforeALongRun) {
    EXPECT_FALSE(checkFileWritable("/proc/grass-report.json", "report.json"));
    const fs::path dir = test::scratchDir("hostile-writable");
    EXPECT_TRUE(checkFileWritable(dir / "report.json", "report.json"));
    EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 0);
}

// --- Paths ---------------------------------------------------------------------------------------

TEST(ProjectPaths, LinksLeadingOutsideTheProjectAreRefused) {
    const fs::path dir = test::scratchDir("hostile-links");
    fs::create_directories(dir / "p" / "real");
    fs::create_directories(dir / "outside");
    write(dir / "outside" / "secret.png", "secret");
    write(dir / "p" / "real" / "ok.png", "ok");
    fs::create_symlink(dir / "outside" / "secret.png", dir / "p" / "file-link.png");
    fs::create_symlink("../outside", dir / "p" / "folder-link");
    fs::create_symlink(dir / "outside" / "not-yet.png", dir / "p" / "dangling.png");
    fs::create_symlink("real/ok.png", dir / "p" / "inside-link.png");
    for (const char* refused : {"file-link.png", "folder-link/secret.png", "dangling.png"}) {
        const auto path = core::resolveAssetPath(dir / "p", refused, "/layers/0/density_map");
        ASSERT_FALSE(path) << refused;
        EXPECT_EQ(path.error().path, "/layers/0/density_map");
        EXPECT_NE(path.error().message.find("outside the project folder"), std::string::npos);
    }
    EXPECT_TRUE(core::resolveAssetPath(dir / "p", "inside-link.png", "/mesh/file"));
    EXPECT_TRUE(core::resolveAssetPath(dir / "p", "maps/new.png", "/mesh/file"));
}

TEST(ProjectPaths, RealPathEndsALoopOfLinks) {
    const fs::path dir = test::scratchDir("hostile-loop");
    fs::create_symlink(dir / "b", dir / "a");
    fs::create_symlink(dir / "a", dir / "b");
    EXPECT_FALSE(realPath(dir / "a" / "x").empty());
}

TEST(ProjectNames, ControlCharactersAreRefusedWithTheirPointer) {
    const std::string head = R"({"format": "grass-project", "version": 1, )";
    for (const std::string& members :
         {std::string(R"("name": "a\u001b[31mred")"), std::string(R"("name": "two\nlines")"),
          std::string(R"("layers": [{"name": "gr\u0000ass"}])")}) {
        const auto project = core::parseProject(head + members + "}", "p.json");
        ASSERT_FALSE(project) << members;
        EXPECT_NE(project.error().message.find("control characters"), std::string::npos);
        EXPECT_NE(project.error().message.find("/name"), std::string::npos);
    }
    EXPECT_TRUE(core::parseProject(head + R"("name": "Wiese ünd Mähne — 2"})", "p.json"));
    EXPECT_EQ(core::fileSafeName("/tmp/abs"), "_tmp_abs");
    EXPECT_EQ(core::fileSafeName("../x"), "___x");
}

// --- Outputs that are inputs ------------------------------------------------------------------

TEST(ProjectInputs, AnOutputThatIsAnInputIsRefusedNamingBoth) {
    const fs::path dir = test::scratchDir("hostile-inputs");
    write(dir / "project.json", "{}");
    fs::create_directories(dir / "maps");
    write(dir / "maps" / "d.png", "map");
    core::LoadedProject loaded;
    loaded.folder = dir;
    loaded.file = dir / "project.json";
    loaded.project.layers.front().densityMap = "maps/d.png";
    fs::create_symlink(dir / "project.json", dir / "alias.json");
    for (const fs::path& output : {dir / "project.json", dir / "." / "project.json",
                                   dir / "alias.json", dir / "maps" / ".." / "project.json"}) {
        const auto refused = core::refuseOverwritingInput(loaded, output, "--report");
        ASSERT_FALSE(refused) << output;
        EXPECT_EQ(refused.error().path, "--report");
        EXPECT_NE(refused.error().message.find("project file"), std::string::npos);
    }
    const auto map = core::refuseOverwritingInput(loaded, dir / "maps" / "d.png", "--out");
    ASSERT_FALSE(map);
    EXPECT_NE(map.error().message.find("/layers/0/density_map"), std::string::npos);
    EXPECT_TRUE(core::refuseOverwritingInput(loaded, dir / "render.png", "--out"));
}

// --- Concurrency, bounds ------------------------------------------------------------------------

TEST(FolderLock, ASecondWriterIsToldWhyItCannot) {
    const fs::path dir = test::scratchDir("hostile-lock");
    {
        auto first = FolderLock::acquire(dir, "grass export");
        ASSERT_TRUE(first);
        const auto second = FolderLock::acquire(dir, "grass export");
        ASSERT_FALSE(second);
        EXPECT_EQ(second.error().path, dir.string());
        EXPECT_NE(second.error().message.find("another grass export is writing"),
                  std::string::npos);
    }
    EXPECT_TRUE(FolderLock::acquire(dir, "grass export"));  // released with the first
}

TEST(SimulationSteps, AreBoundedInsteadOfOverflowing) {
    EXPECT_EQ(*core::simulationSteps(2.0, 0.01, "--seconds"), 200u);
    EXPECT_EQ(*core::simulationSteps(0.0, 1e-30, "--seconds"), 0u);
    for (const double dt : {1e-30, 0.0, -1.0, std::nan("")}) {
        const auto steps = core::simulationSteps(3600.0, dt, "--seconds");
        ASSERT_FALSE(steps) << dt;
        EXPECT_EQ(steps.error().path, "--seconds");
    }
    EXPECT_FALSE(core::simulationSteps(3600.0, 1e-5, "--time"));
}

TEST(ProjectBounds, StepHeightWidthAndListSizesHaveLimits) {
    const std::string head = R"({"format": "grass-project", "version": 1, )";
    const auto refusedAt = [&](const std::string& members, const std::string& pointer) {
        const auto project = core::parseProject(head + members + "}", "p.json");
        ASSERT_FALSE(project) << members;
        EXPECT_EQ(project.error().message.rfind(pointer, 0), 0u) << project.error().message;
    };
    refusedAt(R"("physics": {"step_s": 1e-30})", "/physics/step_s");
    refusedAt(R"("layers": [{"blade": {"height": [1e30, 1e30]}}])", "/layers/0/blade/height/0");
    refusedAt(R"("layers": [{"blade": {"width": [0.01, 50]}}])", "/layers/0/blade/width/1");
    refusedAt(R"("lighting": {"ao_radius": 0.00001})", "/lighting/ao_radius");
    EXPECT_TRUE(core::parseProject(head + R"("physics": {"step_s": 1e-5})" + "}", "p.json"));
    std::string layers = R"("layers": [)";
    for (int i = 0; i < 300; ++i)
        layers += (i ? ", " : "") + std::string(R"({"name": "l)") + std::to_string(i) + "\"}";
    refusedAt(layers + "]", "/layers");
}

TEST(ProjectBounds, DuplicateNamesAreFoundBySortingWithTheFirstPairReported) {
    struct Named {
        std::string name;
    };
    std::vector<Named> items;
    for (int i = 0; i < 100000; ++i)
        items.push_back({"n" + std::to_string(i)});
    core::json::Reader unique("p.json");
    core::json::checkUniqueNames(unique, items, "/layers", "layer");
    EXPECT_TRUE(unique.ok());
    items[99990].name = "n7";
    items[50000].name = "n99";
    core::json::Reader duplicated("p.json");
    core::json::checkUniqueNames(duplicated, items, "/layers", "layer");
    ASSERT_FALSE(duplicated.ok());
    // The first item (in list order) that repeats an earlier name, and that earlier item.
    EXPECT_NE(duplicated.error().message.find("/layers/50000/name"), std::string::npos);
    EXPECT_NE(duplicated.error().message.find("also /layers/99/name"), std::string::npos);
}

}  // namespace
}  // namespace grass
