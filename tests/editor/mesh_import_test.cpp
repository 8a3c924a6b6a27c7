// The artist's own mesh in (issue 26, app/mesh_import.h): File › New from mesh… makes a project
// sized and framed for the mesh; Import mesh… names a mesh inside the project where it is and
// copies one from elsewhere in with the files it names; a broken file copies nothing; Save As
// takes a .gltf's buffers and images along.
#include "app/mesh_import.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <latch>
#include <map>
#include <thread>
#include <utility>
#include <vector>

#include "scene/scene.h"
#include "support/scratch_folder.h"
#include "support/test_paths.h"

namespace grass::test {
namespace {

namespace fs = std::filesystem;

const fs::path STONE = "tests/data/projects/textured_stone/stone.gltf";

TEST(MeshImport, NewFromMeshIsAnUnsavedProjectAroundTheMeshThatGrows) {
    const fs::path mesh = sourceDir() / "tests/data/gltf/cube.glb";
    auto loaded = editor::newProjectFromMesh(mesh);
    ASSERT_TRUE(loaded.ok()) << loaded.error().str();
    EXPECT_TRUE(loaded->file.empty()) << "a new project is not saved until the user says where";
    EXPECT_EQ(loaded->folder, mesh.parent_path());
    EXPECT_TRUE(loaded->project.mesh.isFile);
    EXPECT_EQ(loaded->project.mesh.file, "cube.glb");
    auto scene = core::buildScene(*loaded);
    ASSERT_TRUE(scene.ok()) << scene.error().str();
    // Sized for the mesh: about the blades asked for (clumping off, so within sampling noise).
    const double blades = static_cast<double>(scene->totalBlades());
    EXPECT_GT(blades, 0.8 * editor::NEW_MESH_PROJECT_BLADES);
    EXPECT_LT(blades, 1.2 * editor::NEW_MESH_PROJECT_BLADES);
}

// A project grown on the mesh `read` for it equals the project grown on its file read again:
// the field, the surface's texture and its paintable UVs.
void expectTheReadMeshGrowsTheFilesField(const core::LoadedProject& loaded, core::GltfImport read) {
    const std::size_t faces = read.mesh->n_faces();
    EXPECT_GT(faces, 0u);
    auto fromFile = core::buildScene(loaded);
    auto fromRead = core::buildScene(loaded, &read);
    ASSERT_TRUE(fromFile.ok()) << fromFile.error().str();
    ASSERT_TRUE(fromRead.ok()) << fromRead.error().str();
    EXPECT_EQ(fromRead->mesh->n_faces(), faces);
    EXPECT_EQ(fromRead->bounds, fromFile->bounds);
    EXPECT_EQ(fromRead->look.baseTexture.pixels, fromFile->look.baseTexture.pixels);
    EXPECT_FALSE(fromRead->look.baseTexture.pixels.empty()) << "the stone is textured";
    EXPECT_EQ(fromRead->paintUvs.fingerprint, fromFile->paintUvs.fingerprint);
    const auto& blades = fromRead->layers.at(0).patched.blades;
    const auto& bladesFromFile = fromFile->layers.at(0).patched.blades;
    ASSERT_EQ(blades.size(), bladesFromFile.size());
    ASSERT_GT(fromRead->totalBlades(), 1000u);
    for (std::size_t i = 0; i < blades.size(); ++i)
        ASSERT_EQ(blades[i].v0Theta, bladesFromFile[i].v0Theta) << "blade " << i;
}

// The mesh a new project was sized on is the one it grows on: the file is read once.
TEST(MeshImport, TheMeshReadForANewProjectGrowsTheSameFieldAsTheFile) {
    core::GltfImport read;
    auto loaded = editor::newProjectFromMesh(sourceDir() / STONE, 2000, &read);
    ASSERT_TRUE(loaded.ok()) << loaded.error().str();
    expectTheReadMeshGrowsTheFilesField(*loaded, std::move(read));
}

// The mesh Import mesh… checks is the one the field grows on: the file is read once (here in
// centimetres, the unit the project keeps from its previous glTF surface).
TEST(MeshImport, TheMeshReadForAnImportGrowsTheSameFieldAsTheFile) {
    const ScratchFolder project("import-read-once");
    core::LoadedProject loaded{core::Project{}, project.path(), project.path() / "project.json"};
    loaded.project.mesh.isFile = true;
    loaded.project.mesh.file = "old.glb";
    loaded.project.mesh.metresPerUnit = 0.01f;
    loaded.project.layers.front().scatter.density = 4e6f;  // the stone is a few centimetres
    core::GltfImport read;
    auto next = editor::projectWithImportedMesh(loaded, sourceDir() / STONE, nullptr, &read);
    ASSERT_TRUE(next.ok()) << next.error().str();
    EXPECT_EQ(next->project.mesh.metresPerUnit, 0.01f);
    expectTheReadMeshGrowsTheFilesField(*next, std::move(read));
}

TEST(MeshImport, ABrokenMeshIsRefusedNamingTheFileAndCopiesNothing) {
    const ScratchFolder project("import-broken");
    core::LoadedProject loaded{core::Project{}, project.path(), project.path() / "project.json"};
    const fs::path broken = sourceDir() / "tests/data/gltf/truncated.gltf";
    auto next = editor::projectWithImportedMesh(loaded, broken, nullptr);
    ASSERT_FALSE(next.ok());
    EXPECT_NE(next.error().str().find("truncated.gltf"), std::string::npos) << next.error().str();
    EXPECT_FALSE(fs::exists(project.path() / "meshes"));
    EXPECT_FALSE(editor::newProjectFromMesh(broken).ok());
}

// The editor's Cancel (or its window closed) while a mesh is read stops the read: an error naming
// the file, and nothing copied into the project.
TEST(MeshImport, AStoppedReadIsRefusedNamingTheFileAndCopiesNothing) {
    const ScratchFolder project("import-stopped");
    core::LoadedProject loaded{core::Project{}, project.path(), project.path() / "project.json"};
    std::stop_source source;
    source.request_stop();
    const fs::path stone = sourceDir() / STONE;
    auto next =
        editor::projectWithImportedMesh(loaded, stone, nullptr, nullptr, source.get_token());
    ASSERT_FALSE(next.ok());
    EXPECT_EQ(next.error(), core::readStopped(stone));
    EXPECT_FALSE(fs::exists(project.path() / "meshes"));
    auto fresh = editor::newProjectFromMesh(stone, editor::NEW_MESH_PROJECT_BLADES, nullptr,
                                            source.get_token());
    ASSERT_FALSE(fresh.ok());
    EXPECT_EQ(fresh.error(), core::readStopped(stone));
    EXPECT_TRUE(editor::newProjectFromMesh(stone).ok());
}

TEST(MeshImport, AMeshFromElsewhereIsCopiedInWithTheFilesItNames) {
    const ScratchFolder project("import-copy");
    core::LoadedProject loaded{core::Project{}, project.path(), project.path() / "project.json"};
    std::string note;
    auto next = editor::projectWithImportedMesh(loaded, sourceDir() / STONE, &note);
    ASSERT_TRUE(next.ok()) << next.error().str();
    EXPECT_EQ(next->project.mesh.file, "meshes/stone/stone.gltf");
    for (const char* file : {"stone.gltf", "stone.bin", "stone.png"})
        EXPECT_TRUE(fs::exists(project.path() / "meshes/stone" / file)) << file;
    EXPECT_NE(note.find("meshes/stone"), std::string::npos) << note;
    // The project grows from its copy; the same mesh imported again is named where its copy
    // is (not copied twice), another mesh of the same name gets a folder of its own, with the
    // files it names, and the first copy is left as it was.
    EXPECT_TRUE(core::buildScene(*next).ok());
    auto again = editor::projectWithImportedMesh(*next, sourceDir() / STONE, &note);
    ASSERT_TRUE(again.ok());
    EXPECT_EQ(again->project.mesh.file, "meshes/stone/stone.gltf");
    EXPECT_EQ(note, "uses its copy in " + (project.path() / "meshes/stone").string());
    EXPECT_FALSE(fs::exists(project.path() / "meshes/stone-2"));
    const ScratchFolder elsewhere("import-copy-other");
    for (const char* file : {"stone.gltf", "stone.bin", "stone.png"})
        fs::copy_file(sourceDir() / STONE.parent_path() / file, elsewhere.path() / file);
    std::ofstream(elsewhere.path() / "stone.png", std::ios::app) << "another picture";
    auto other = editor::projectWithImportedMesh(*next, elsewhere.path() / "stone.gltf", nullptr);
    ASSERT_TRUE(other.ok()) << other.error().str();
    EXPECT_EQ(other->project.mesh.file, "meshes/stone-2/stone.gltf");
    EXPECT_TRUE(fs::exists(project.path() / "meshes/stone-2/stone.png"));
    EXPECT_NE(fs::file_size(project.path() / "meshes/stone/stone.png"),
              fs::file_size(project.path() / "meshes/stone-2/stone.png"));
}

// The same mesh brought in twice at once (Colliders › add mesh… reads and copies on a worker
// while the window imports the same file): both succeed, and each names a whole copy the moment
// it names it (the first's, or one of its own when it met the first's half made). Before, the
// second could name the first's files while they were being written, or fail on them ("cannot
// copy … File exists").
TEST(MeshImport, TheSameMeshBroughtInTwiceAtOnceNamesAWholeCopy) {
    // A buffer of 8 MB: its copy takes long enough for the other import to meet it.
    const ScratchFolder source("import-twice-source");
    for (const char* file : {"stone.gltf", "stone.bin", "stone.png"})
        fs::copy_file(sourceDir() / STONE.parent_path() / file, source.path() / file);
    std::ofstream(source.path() / "stone.bin", std::ios::app | std::ios::binary)
        << std::string(8 << 20, '\0');
    const fs::path stone = source.path() / "stone.gltf";
    for (int round = 0; round < 10; ++round) {
        const ScratchFolder project("import-twice-" + std::to_string(round));
        // What an import names, and the sizes of the files in its folder when it is named.
        struct Named {
            Result<std::string> file = std::string();
            std::map<std::string, std::uintmax_t> sizes;
        };
        const auto bringIn = [&](Named& named) {
            named.file = editor::meshInProject(project.path(), stone, nullptr);
            if (!named.file)
                return;
            // The other import's temporaries (".stone.tmp-…") may come and go meanwhile.
            std::error_code ec;
            for (fs::directory_iterator it((project.path() / *named.file).parent_path(), ec), end;
                 !ec && it != end; it.increment(ec))
                if (const std::string name = it->path().filename().string(); name[0] != '.')
                    named.sizes[name] = fs::file_size(it->path(), ec);
        };
        Named first, second;
        std::latch start(2);  // both threads begin together: their copies overlap
        std::thread worker([&] {
            start.arrive_and_wait();
            bringIn(second);
        });
        start.arrive_and_wait();
        bringIn(first);
        worker.join();
        const std::map<std::string, std::uintmax_t> whole{
            {"stone.gltf", fs::file_size(stone)},
            {"stone.bin", fs::file_size(source.path() / "stone.bin")},
            {"stone.png", fs::file_size(source.path() / "stone.png")}};
        for (const Named* named : {&first, &second}) {
            ASSERT_TRUE(named->file.ok()) << named->file.error().str();
            EXPECT_EQ(named->sizes, whole) << "round " << round << ": " << *named->file;
        }
        // Both done: no temporary is left.
        for (const auto& entry : fs::recursive_directory_iterator(project.path()))
            EXPECT_NE(entry.path().filename().string()[0], '.') << entry.path();
    }
}

// Two different meshes of one name at once: each is named where its own bytes are, or refused
// saying to add it again; never named where the other's bytes lie.
TEST(MeshImport, TwoMeshesOfOneNameAtOnceNeverShareACopy) {
    const ScratchFolder elsewhere("import-same-name-other");
    for (const char* file : {"stone.gltf", "stone.bin", "stone.png"})
        fs::copy_file(sourceDir() / STONE.parent_path() / file, elsewhere.path() / file);
    std::ofstream(elsewhere.path() / "stone.png", std::ios::app) << "another picture";
    const fs::path ours = sourceDir() / STONE, theirs = elsewhere.path() / "stone.gltf";
    for (int round = 0; round < 10; ++round) {
        const ScratchFolder project("import-same-name-" + std::to_string(round));
        Result<std::string> first = std::string(), second = std::string();
        std::latch start(2);
        std::thread worker([&] {
            start.arrive_and_wait();
            second = editor::meshInProject(project.path(), theirs, nullptr);
        });
        start.arrive_and_wait();
        first = editor::meshInProject(project.path(), ours, nullptr);
        worker.join();
        for (const auto& [named, source] : {std::pair{&first, ours}, std::pair{&second, theirs}}) {
            if (!named->ok()) {
                EXPECT_NE(named->error().message.find("add this one again"), std::string::npos)
                    << named->error().str();
                continue;
            }
            const fs::path copy = project.path() / **named;
            EXPECT_EQ(fs::file_size(copy.parent_path() / "stone.png"),
                      fs::file_size(source.parent_path() / "stone.png"))
                << "round " << round << ": " << **named << " holds the other mesh's picture";
        }
    }
}

TEST(MeshImport, AMeshInsideTheProjectIsNamedWhereItIsAndKeepsTheUnits) {
    const ScratchFolder project("import-inside");
    fs::create_directories(project.path() / "scans");
    fs::copy_file(sourceDir() / "tests/data/gltf/cube.glb", project.path() / "scans/cube.glb");
    core::LoadedProject loaded{core::Project{}, project.path(), project.path() / "project.json"};
    loaded.project.mesh.isFile = true;
    loaded.project.mesh.file = "old.glb";
    loaded.project.mesh.metresPerUnit = 0.001f;
    auto next = editor::projectWithImportedMesh(loaded, project.path() / "scans/cube.glb", nullptr);
    ASSERT_TRUE(next.ok()) << next.error().str();
    EXPECT_EQ(next->project.mesh.file, "scans/cube.glb");
    EXPECT_EQ(next->project.mesh.metresPerUnit, 0.001f) << "a re-imported model keeps its units";
    EXPECT_FALSE(fs::exists(project.path() / "meshes"));
}

TEST(MeshImport, ANeverSavedProjectMovesToTheMeshInsteadOfCopyingIt) {
    const ScratchFolder cwd("import-unsaved");
    core::LoadedProject loaded{core::Project{}, cwd.path(), {}};
    auto next = editor::projectWithImportedMesh(loaded, sourceDir() / STONE, nullptr);
    ASSERT_TRUE(next.ok()) << next.error().str();
    EXPECT_EQ(next->folder, (sourceDir() / STONE).parent_path().lexically_normal());
    EXPECT_EQ(next->project.mesh.file, "stone.gltf");
    EXPECT_FALSE(fs::exists(cwd.path() / "meshes"));
}

TEST(MeshImport, CopyingAGltfTakesItsBuffersAndImagesAlong) {
    const ScratchFolder to("import-save-as");
    ASSERT_TRUE(editor::copyAssetFiles(sourceDir() / STONE, to.path() / "surface/stone.gltf").ok());
    for (const char* file : {"stone.gltf", "stone.bin", "stone.png"})
        EXPECT_TRUE(fs::exists(to.path() / "surface" / file)) << file;
    EXPECT_EQ(editor::assetFileSet(sourceDir() / STONE).size(), 3u);
}

// Import mesh… keeps the layers: blades tall for the new surface are said with the way out.
// The meadow's (0.3–0.6 m) on Blender's Suzanne (bounds 3.67 m across) stood out as spikes
// without a word; on the meadow's own 20 m hills, or a terrain, nothing is said.
TEST(MeshImport, BladesTallForTheImportedSurfaceAreSaid) {
    core::Project project;
    project.layers.resize(2);
    project.layers[0].scatter.blade.heightMax = 0.2f;
    project.layers[1].scatter.blade.heightMax = 0.6f;
    const std::string note = editor::bladeSizeNote(project, 3.67f);
    EXPECT_NE(note.find("up to 0.6 m"), std::string::npos) << note;
    EXPECT_NE(note.find("3.67 m across"), std::string::npos) << note;
    EXPECT_NE(note.find("New from mesh"), std::string::npos) << note;
    EXPECT_EQ(editor::bladeSizeNote(project, 28.3f), "");
    EXPECT_EQ(editor::bladeSizeNote(project, 6.1f), "") << "a tenth of the diagonal is allowed";
    EXPECT_EQ(editor::bladeSizeNote(project, 0.0f), "");
}

}  // namespace
}  // namespace grass::test
