#include "project/project.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <fstream>

#include "support/test_paths.h"
#include "util/atomic_file.h"
#include "util/rng.h"
#include "support/project_errors.h"

namespace grass::core {
namespace {

namespace fs = std::filesystem;

// The name bad documents are parsed under; every error must carry it.
const std::string SOURCE = "projects/test/project.json";

// A minimal valid document with `members` (JSON text, may be empty) after the header.
std::string document(const std::string& members) {
    return R"({"format": "grass-project", "version": 1)" +
           (members.empty() ? std::string() : ", " + members) + "}";
}

// The one-line error for `text`, or "" when it parses.
std::string errorOf(const std::string& text) {
    const auto parsed = parseProject(text, SOURCE);
    return parsed ? std::string() : parsed.error().str();
}

void expectError(const std::string& text, const std::string& pointer, const std::string& problem) {
    test::expectProjectError(text, SOURCE, pointer, problem);
}

void writeText(const fs::path& file, const std::string& text) {
    std::ofstream out(file, std::ios::binary);
    out << text;
}

fs::path meadowFolder() {
    return test::sourceDir() / "projects" / "meadow";
}

TEST(Project, MeadowLoadsAsTheDefaultScene) {
    const auto loaded = loadProject(meadowFolder());
    ASSERT_TRUE(loaded) << loaded.error().str();
    const Project& project = loaded->project;
    EXPECT_EQ(project.name, "meadow");
    EXPECT_FALSE(project.mesh.isFile);
    EXPECT_EQ(project.mesh.procedural.shape, ProceduralShape::Hills);
    EXPECT_FLOAT_EQ(project.mesh.procedural.size, 20.0f);
    ASSERT_EQ(project.layers.size(), 1u);
    EXPECT_GT(project.layers[0].scatter.clumpSpacing, 0.0f);
    // About 60,000 blades on ~20 × 20 × 1.05 m² (the clumps add a few per cent).
    const float uniformBlades = project.layers[0].scatter.density * 20.0f * 20.0f * 1.05f;
    EXPECT_NEAR(uniformBlades, 60000.0f, 6000.0f);
    ASSERT_EQ(project.cameras.size(), 1u);
    EXPECT_EQ(project.render.width, 1280);
    EXPECT_EQ(project.render.height, 720);
    EXPECT_EQ(project.render.geometry, GeometryPath::Auto);
    EXPECT_EQ(loaded->folder, meadowFolder());
    EXPECT_EQ(loaded->file, meadowFolder() / "project.json");
}

TEST(Project, RoundTripIsExactAndStable) {
    const auto loaded = loadProject(meadowFolder());
    ASSERT_TRUE(loaded) << loaded.error().str();
    const std::string first = serializeProject(loaded->project);
    const auto reparsed = parseProject(first, "first save");
    ASSERT_TRUE(reparsed) << reparsed.error().str();
    EXPECT_EQ(*reparsed, loaded->project);
    EXPECT_EQ(serializeProject(*reparsed), first);
    EXPECT_EQ(first.back(), '\n');
    EXPECT_EQ(first.substr(0, 4), "{\n  ");
}

TEST(Project, DefaultsDocumentLoads) {
    const auto parsed = parseProject(R"({"format":"grass-project","version":1})", SOURCE);
    ASSERT_TRUE(parsed) << parsed.error().str();
    EXPECT_EQ(*parsed, Project{});
    const auto again = parseProject(serializeProject(Project{}), SOURCE);
    ASSERT_TRUE(again) << again.error().str();
    EXPECT_EQ(*again, Project{});
}

TEST(Project, SerializedKeysFollowTheDocumentedOrder) {
    const std::string text = serializeProject(Project{});
    const char* keys[] = {"\"format\"", "\"version\"", "\"name\"",    "\"seed\"",
                          "\"mesh\"",   "\"layers\"",  "\"cameras\"", "\"sun\"",
                          "\"render\"", "\"physics\"", "\"wind\"",    "\"colliders\""};
    std::size_t previous = 0;
    for (const char* key : keys) {
        const std::size_t at = text.find(key);
        ASSERT_NE(at, std::string::npos) << key;
        EXPECT_GT(at, previous) << key << " out of order";
        previous = at;
    }
    EXPECT_NE(text.find("\"position\": [8.0, 5.0, 8.0]"), std::string::npos) << text;
}

TEST(Project, FloatsRoundTripBitExactly) {
    for (std::uint64_t seed = 0; seed < 200; ++seed) {
        Rng rng(seed);
        // Any finite float, from denormals to the largest, through the writer and the reader.
        auto anyFloat = [&rng] {
            for (;;) {
                const float value = std::bit_cast<float>(rng.nextU32());
                if (std::isfinite(value))
                    return value;
            }
        };
        Project project;
        CameraDesc& camera = project.cameras[0];
        camera.position = {anyFloat(), anyFloat(), anyFloat()};
        camera.target = {anyFloat(), anyFloat(), anyFloat()};
        camera.fovYDeg = rng.uniform(1.0f, 179.0f);
        project.layers[0].scatter.density = std::abs(anyFloat());
        project.layers[0].tipColor = {rng.uniform(), rng.uniform(), rng.uniform()};
        project.seed = (std::uint64_t{rng.nextU32()} << 32) | rng.nextU32();
        const auto parsed = parseProject(serializeProject(project), "random");
        ASSERT_TRUE(parsed) << "seed " << seed << ": " << parsed.error().str();
        EXPECT_EQ(*parsed, project) << "seed " << seed;
    }
}

TEST(Project, FileMeshRoundTrips) {
    Project project;
    project.mesh.isFile = true;
    project.mesh.file = "meshes/terrain.glb";
    const auto parsed = parseProject(serializeProject(project), SOURCE);
    ASSERT_TRUE(parsed) << parsed.error().str();
    EXPECT_EQ(*parsed, project);
}

// Issue 26: a file mesh's unit and up axis travel; defaults stay out of the file.
TEST(Project, FileMeshUnitAndUpRoundTrip) {
    for (const auto& [unit, up] : {std::pair{0.001f, UpAxis::Z}, {0.0254f, UpAxis::Y}, {0.5f, UpAxis::Z}}) {
        Project project;
        project.mesh.isFile = true;
        project.mesh.file = "engine.glb";
        project.mesh.metresPerUnit = unit;
        project.mesh.up = up;
        const std::string text = serializeProject(project);
        const auto parsed = parseProject(text, SOURCE);
        ASSERT_TRUE(parsed) << parsed.error().str();
        EXPECT_EQ(*parsed, project) << text;
    }
    const auto named = parseProject(document(R"("mesh": {"file": "e.glb", "unit": "mm", "up": "+Z"})"), SOURCE);
    ASSERT_TRUE(named) << named.error().str();
    EXPECT_EQ(named->mesh.metresPerUnit, 0.001f);
    EXPECT_EQ(named->mesh.up, UpAxis::Z);
    EXPECT_NE(serializeProject(*named).find(R"("unit": "mm")"), std::string::npos);
    Project plain;
    plain.mesh.isFile = true;
    plain.mesh.file = "t.glb";
    EXPECT_EQ(serializeProject(plain).find("\"unit\""), std::string::npos) << "metres are the default";
}

// "file_material": false draws the surface in the ground colour; left out at its default.
TEST(Project, FileMaterialIsReadWrittenAndOnlyForFiles) {
    const auto off =
        parseProject(document(R"("mesh": {"file": "e.glb", "file_material": false})"), SOURCE);
    ASSERT_TRUE(off) << off.error().str();
    EXPECT_FALSE(off->mesh.fileMaterial);
    EXPECT_NE(serializeProject(*off).find(R"("file_material": false)"), std::string::npos);
    const auto reread = parseProject(serializeProject(*off), SOURCE);
    ASSERT_TRUE(reread);
    EXPECT_EQ(*reread, *off);
    Project plain;
    plain.mesh.isFile = true;
    plain.mesh.file = "t.glb";
    EXPECT_EQ(serializeProject(plain).find("file_material"), std::string::npos)
        << "true is the default";
    expectError(document(R"("mesh": {"file": "t.glb", "file_material": "no"})"),
                "/mesh/file_material", "must be true or false");
    expectError(document(R"("mesh": {"procedural": "plane", "file_material": false})"),
                "/mesh/file_material", "only allowed with \"file\"");
}

TEST(Project, FileMeshUnitAndUpAreCheckedAndOnlyForFiles) {
    expectError(document(R"("mesh": {"file": "t.glb", "unit": "parsec"})"), "/mesh/unit", "unknown unit");
    expectError(document(R"("mesh": {"file": "t.glb", "unit": 0})"), "/mesh/unit", "outside 1e-06 to 1e+06");
    expectError(document(R"("mesh": {"file": "t.glb", "unit": true})"), "/mesh/unit", "unit name");
    expectError(document(R"("mesh": {"file": "t.glb", "up": "-Y"})"), "/mesh/up", "+Y or +Z");
    expectError(document(R"("mesh": {"procedural": "plane", "unit": "mm"})"), "/mesh/unit",
                "only allowed with \"file\"");
}

TEST(Project, UnknownFormatIsRejected) {
    expectError(R"({"format": "grass-scene", "version": 1})", "/format", "grass-project");
}

TEST(Project, MissingFormatIsRejected) {
    expectError(R"({"version": 1})", "/format", "missing required key");
}

TEST(Project, UnknownVersionIsRejected) {
    // The version after the newest this build writes (project_migration_test covers both ends).
    expectError(R"({"format": "grass-project", "version": 4})", "/version",
                "this build reads only versions 1 to 3");
    expectError(R"({"format": "grass-project"})", "/version", "missing required key");
}

TEST(Project, NonFiniteDensityIsRejected) {
    // nlohmann refuses 1e999 while parsing; the error still names the field.
    expectError(document(R"("layers": [{"density": 1e999}])"), "/layers/0/density",
                "must be a finite number (got 1e999");
    expectError(document(R"("cameras": [{"position": [0, -1e999, 0]}])"), "/cameras/0/position/1",
                "must be a finite number");
    // Finite as a double, but no float holds it.
    expectError(document(R"("layers": [{"density": 1e39}])"), "/layers/0/density",
                "beyond single precision");
}

TEST(Project, NegativeDensityIsRejected) {
    expectError(document(R"("layers": [{"density": -3}])"), "/layers/0/density",
                "must be a finite number >= 0 (got -3)");
}

TEST(Project, WrongTypeIsRejected) {
    expectError(document(R"("layers": [{"density": "lots"}])"), "/layers/0/density",
                "got string \"lots\"");
    expectError(document(R"("cameras": {"name": "a"})"), "/cameras", "must be an array");
    expectError(document(R"("render": {"width": 1280.5})"), "/render/width", "integer");
    expectError(document(R"("seed": -1)"), "/seed", "got -1");
}

TEST(Project, UnknownKeySuggestsTheClosest) {
    expectError(document(R"("layers": [{"densty": 3}])"), "/layers/0/densty",
                "unknown key (did you mean \"density\"?)");
    expectError(document(R"("rendr": {})"), "/rendr", "did you mean \"render\"?");
    expectError(document(R"("weather": {})"), "/weather", "expected one of");
    // A key with a newline still gives one line: control characters print escaped.
    expectError(document(R"("na\nme": "x")"), R"(/na\nme)", "unknown key");
}

TEST(Project, BadEnumListsTheValidNames) {
    expectError(document(R"("render": {"geometry": "tesselation"})"), "/render/geometry",
                "\"auto\", \"tess\", \"strips\"");
    expectError(document(R"("mesh": {"procedural": "hils"})"), "/mesh/procedural",
                "did you mean \"hills\"?");
}

TEST(Project, ZeroWidthIsRejected) {
    expectError(document(R"("render": {"width": 0})"), "/render/width",
                "must be an integer in 1..16384 (got 0)");
}

TEST(Project, OutOfRangeSettingsAreRejected) {
    expectError(document(R"("render": {"tess_level": 65})"), "/render/tess_level", "1..64");
    expectError(document(R"("render": {"strip_segments": 0})"), "/render/strip_segments", "1..32");
    expectError(document(R"("render": {"msaa": 3})"), "/render/msaa", "0, 1, 2, 4 or 8");
    expectError(document(R"("lighting": {"ao_cell": 0.01})"), "/lighting/ao_cell", "0 (exact");
    expectError(document(R"("lighting": {"ao_cell": 5})"), "/lighting/ao_cell", "[0, 4]");
    expectError(document(R"("render": {"lod_distance": -1})"), "/render/lod_distance",
                "[0, 100000]");
    expectError(document(R"("render": {"thinning_distance": 1e9})"), "/render/thinning_distance",
                "[0, 100000]");
    expectError(document(R"("render": {"lod_distance": "far"})"), "/render/lod_distance",
                "number");
    expectError(document(R"("render": {"patch_size": 100})"), "/render/patch_size",
                "multiple of 32");
    expectError(document(R"("mesh": {"resolution": 2000})"), "/mesh/resolution", "1..1024");
    expectError(document(R"("mesh": {"size": 0})"), "/mesh/size", "> 0");
    expectError(document(R"("cameras": [{"fov_y_deg": 180}])"), "/cameras/0/fov_y_deg", "(0, 180)");
    expectError(document(R"("layers": [{"tip_color": [0.5, 1.5, 0]}])"), "/layers/0/tip_color/1",
                "[0, 1]");
    expectError(document(R"("sun": {"direction": [0, 0, 0]})"), "/sun/direction", "[0, 0, 0]");
}

TEST(Project, RangeWithMinAboveMaxIsRejected) {
    expectError(document(R"("layers": [{"blade": {"height": [0.6, 0.3]}}])"),
                "/layers/0/blade/height", "min must be <= max");
    expectError(document(R"("layers": [{"blade": {"width": [0.01]}}])"), "/layers/0/blade/width",
                "[min, max]");
}

TEST(Project, AbsoluteAssetPathIsRejected) {
    expectError(document(R"("mesh": {"file": "/home/me/terrain.glb"})"), "/mesh/file",
                "must be relative to the project folder");
    expectError(document(R"("layers": [{"density_map": "/tmp/d.png"}])"), "/layers/0/density_map",
                "relative");
}

TEST(Project, EscapingAssetPathIsRejected) {
    expectError(document(R"("mesh": {"file": "../other/terrain.glb"})"), "/mesh/file",
                "leaves the project folder");
    expectError(document(R"("layers": [{"density_map": "maps/../../d.png"}])"),
                "/layers/0/density_map", "leaves the project folder");
    // Staying inside after normalisation is fine.
    EXPECT_EQ(errorOf(document(R"("layers": [{"density_map": "maps/../d.png"}])")), "");
}

TEST(Project, FileMeshRefusesProceduralParameters) {
    expectError(document(R"("mesh": {"file": "t.glb", "size": 3})"), "/mesh/size",
                "not allowed with \"file\"");
    expectError(document(R"("mesh": {"file": "t.obj"})"), "/mesh/file", ".gltf or .glb");
}

TEST(Project, SyntaxErrorGivesLineAndColumn) {
    const std::string text = "{\n  \"format\": \"grass-project\",\n  \"version\": 1,,\n}\n";
    const std::string error = errorOf(text);
    EXPECT_NE(error.find(SOURCE + ":3:16: JSON syntax error"), std::string::npos) << error;
    const std::string missingColon = errorOf("{\n  \"format\" 1\n}");
    EXPECT_NE(missingColon.find(SOURCE + ":2:12: JSON syntax error"), std::string::npos)
        << missingColon;
    EXPECT_NE(errorOf("").find(SOURCE + ":1:1:"), std::string::npos) << errorOf("");
}

TEST(Project, DuplicateKeyIsRejected) {
    expectError(R"({"format": "grass-project", "version": 1, "seed": 1, "seed": 2})", "/seed",
                "duplicate key");
}

TEST(Project, DuplicateCameraNameIsRejected) {
    expectError(document(R"("cameras": [{"name": "a"}, {"name": "b"}, {"name": "a"}])"),
                "/cameras/2/name", "duplicate camera name \"a\" (also /cameras/0/name)");
    expectError(document(R"("cameras": [{"name": ""}])"), "/cameras/0/name", "must not be empty");
    expectError(document(R"("cameras": [])"), "/cameras", "at least one camera");
    expectError(document(R"("layers": [{}, {}])"), "/layers/1/name", "duplicate layer name");
}

TEST(Project, NonObjectDocumentIsRejected) {
    const std::string error = errorOf("[1, 2]");
    EXPECT_NE(error.find(SOURCE + ": "), std::string::npos) << error;
    EXPECT_NE(error.find("JSON object"), std::string::npos) << error;
}

TEST(Project, LoadsFromFolderOrFile) {
    const fs::path dir = test::scratchDir("project_load");
    writeText(dir / "project.json", document(R"("name": "here")"));
    const auto fromFolder = loadProject(dir);
    ASSERT_TRUE(fromFolder) << fromFolder.error().str();
    const auto fromFile = loadProject(dir / "project.json");
    ASSERT_TRUE(fromFile) << fromFile.error().str();
    EXPECT_EQ(fromFolder->project, fromFile->project);
    EXPECT_EQ(fromFile->project.name, "here");
    EXPECT_EQ(fromFolder->folder, dir);
    EXPECT_EQ(fromFile->folder, dir);
}

TEST(Project, LoadErrorsNameTheFile) {
    const fs::path dir = test::scratchDir("project_load_errors");
    writeText(dir / "project.json", document(R"("layers": [{"density": -1}])"));
    const auto loaded = loadProject(dir);
    ASSERT_FALSE(loaded);
    EXPECT_EQ(loaded.error().str(),
              (dir / "project.json").string() +
                  ": /layers/0/density: must be a finite number >= 0 (got -1)");
}

TEST(Project, FolderWithoutProjectJsonIsRejected) {
    const fs::path dir = test::scratchDir("project_empty_folder");
    const auto loaded = loadProject(dir);
    ASSERT_FALSE(loaded);
    EXPECT_NE(loaded.error().str().find(dir.string()), std::string::npos) << loaded.error().str();
    EXPECT_NE(loaded.error().str().find("project.json"), std::string::npos) << loaded.error().str();
    EXPECT_EQ(loaded.error().str().find("holds the mesh"), std::string::npos) << "it holds none";
}

// A folder holding a mesh and no project (a glTF given its folder as a project): the error says
// the way to a project around the mesh, naming the first by name.
TEST(Project, FolderWithAMeshAndNoProjectSaysHowToGrowOnTheMesh) {
    const fs::path dir = test::scratchDir("project_mesh_folder");
    std::ofstream(dir / "notes.txt") << "not a mesh";
    for (const char* name : {"rock.glb", "ground.gltf"})
        fs::copy_file(test::sourceDir() / "tests/data/gltf/cube.glb", dir / name);
    const auto loaded = loadProject(dir);
    ASSERT_FALSE(loaded);
    const std::string said = loaded.error().str();
    EXPECT_NE(said.find("has no project.json"), std::string::npos) << said;
    EXPECT_NE(said.find("it holds the mesh ground.gltf: `grass-editor " +
                        (dir / "ground.gltf").string() + "` makes a project around it"),
              std::string::npos)
        << said;
}

TEST(Project, MissingFileIsReported) {
    const fs::path file = test::scratchDir("project_missing") / "nowhere.json";
    const auto loaded = loadProject(file);
    ASSERT_FALSE(loaded);
    EXPECT_NE(loaded.error().str().find(file.string()), std::string::npos) << loaded.error().str();
}

TEST(Project, SaveReplacesAtomicallyAndCompletely) {
    const fs::path dir = test::scratchDir("project_save");
    const fs::path file = dir / "project.json";
    writeText(file, "old contents");
    Project project;
    project.name = "saved";
    GrassLayer flowers;
    flowers.name = "flowers";
    project.layers.push_back(flowers);
    const auto saved = saveProject(project, file);
    ASSERT_TRUE(saved) << saved.error().str();
    std::size_t entries = 0;
    for (const auto& entry : fs::directory_iterator(dir)) {
        ++entries;
        EXPECT_EQ(entry.path().filename(), "project.json") << "left behind: " << entry.path();
    }
    EXPECT_EQ(entries, 1u);
    const auto text = readFile(file);
    ASSERT_TRUE(text) << text.error().str();
    EXPECT_EQ(*text, serializeProject(project));
    const auto loaded = loadProject(file);
    ASSERT_TRUE(loaded) << loaded.error().str();
    EXPECT_EQ(loaded->project, project);
}

TEST(Project, SaveRefusesAProjectItCouldNotLoad) {
    const fs::path file = test::scratchDir("project_save_invalid") / "project.json";
    writeText(file, "old contents");
    Project project;
    project.layers[0].scatter.density = NAN;
    const auto saved = saveProject(project, file);
    ASSERT_FALSE(saved);
    EXPECT_NE(saved.error().str().find("/layers/0/density"), std::string::npos)
        << saved.error().str();
    const auto text = readFile(file);
    ASSERT_TRUE(text);
    EXPECT_EQ(*text, "old contents");
}

TEST(Project, ResolveAssetPathStaysInsideTheFolder) {
    const fs::path folder = "projects/meadow";
    const auto inside = resolveAssetPath(folder, "maps/./extra/../density.png", "/x");
    ASSERT_TRUE(inside) << inside.error().str();
    EXPECT_EQ(*inside, folder / "maps/density.png");
    for (const char* bad :
         {"", "/abs.png", "..", "../x.png", "a/../../x.png", "maps/", "a\\b.png"}) {
        const auto resolved = resolveAssetPath(folder, bad, "/layers/0/density_map");
        ASSERT_FALSE(resolved) << bad;
        EXPECT_EQ(resolved.error().path, "/layers/0/density_map");
    }
}

TEST(Project, GeometryPathNamesRoundTrip) {
    for (const GeometryPath path :
         {GeometryPath::Auto, GeometryPath::Tessellation, GeometryPath::Strips}) {
        const auto parsed = parseGeometryPath(geometryPathName(path));
        ASSERT_TRUE(parsed);
        EXPECT_EQ(*parsed, path);
    }
    const auto bad = parseGeometryPath("gpu");
    ASSERT_FALSE(bad);
    EXPECT_NE(bad.error().message.find("strips"), std::string::npos);
}

}  // namespace
}  // namespace grass::core
