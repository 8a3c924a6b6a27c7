// snow_quality: the snow passes' speed against the accuracy of their mask (SPEC §11, §13; issue
// "measure snow quality vs. speed"). For every depth-map resolution × sample count it renders
// the project's first camera (or --camera) at 1280×720, one sample per pixel, and reports
//   - the snow cost: frame time with snow on minus the same frame with snow off (median of N
//     frames, wall clock to the end of glFinish and GL_TIME_ELAPSED of the snow depth pass plus
//     the opaque pass, which holds the per-pixel snow shading);
//   - the error: mean |Fp − Fp_ref| over the surface pixels, Fp from the coverage view (mesh.frag
//     draws (Fp, Fe, Fi) unlit) read back as floats, the reference 2048² with 32 samples; and
//     the share of pixels off by more than 0.1 (a visible step in the snow's whiteness).
// The reference is checked against 4096²/32 (beyond the format's range). Results: docs/snow.md.
//
// Usage: snow_quality [project.json] [--out table.md] [--frames N] [--images DIR]
//                     [--camera NAME] [--tess-pixels P] [--row MAPxS] [--exposure pixel|vertex]
// --tess-pixels: RenderOptions::snowTessPixels (1e6 = every edge level 1); --row: one row only;
// --exposure: the rows' Fe per pixel (default) or per tessellated vertex
// (RenderOptions::snowExposurePerVertex); the references are always per pixel.
// Default project: projects/winter, else projects/meadow with snow switched on (fall (0.3, −1,
// 0.2), 0.1 m: lee slopes, and a ball that shelters the ground and overhangs itself).
// Build RelWithDebInfo (-O3 trips GCC 12 false positives under -Werror), -DGRASS_BUILD_BENCH=ON.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "gl/gl_handle.h"
#include "gl/headless_context.h"
#include "render/offscreen_render.h"
#include "project/project.h"
#include "scene/scene.h"
#include "render/scene_renderer.h"
#include "util/arg_parser.h"
#include "util/atomic_file.h"
#include "util/image_file.h"

namespace {

using namespace grass;

constexpr int WIDTH = 1280;
constexpr int HEIGHT = 720;
constexpr int RESOLUTIONS[] = {512, 1024, 2048};
constexpr int SAMPLE_COUNTS[] = {1, 2, 4, 8, 16, 32};
constexpr int REFERENCE_RESOLUTION = 2048;
constexpr int REFERENCE_SAMPLES = 32;
constexpr int CHECK_RESOLUTION = 4096;
// Fp differs by more than this: a step in whiteness that is plain to see on snow (~26/255).
constexpr float VISIBLE_ERROR = 0.1f;
// The sky of the coverage view: (Fp, Fe, Fi) = (1, 0, 1) cannot occur, since Fp = Fe·Fi.
constexpr float SENTINEL_SKY[3] = {1.0f, 0.0f, 1.0f};

// A single-sample RGBA32F colour + depth target: Fp read back exactly, not quantised to 1/255,
// and no multisample resolve blending the ground and a prop at silhouettes.
struct FloatTarget {
    gl::FramebufferHandle framebuffer;
    gl::RenderbufferHandle color, depth;
};

gl::RenderbufferHandle makeRenderbuffer(GLenum format) {
    GLuint id = 0;
    glCreateRenderbuffers(1, &id);
    glNamedRenderbufferStorage(id, format, WIDTH, HEIGHT);
    return gl::RenderbufferHandle(id);
}

FloatTarget makeFloatTarget() {
    FloatTarget target;
    GLuint id = 0;
    glCreateFramebuffers(1, &id);
    target.framebuffer = gl::FramebufferHandle(id);
    target.color = makeRenderbuffer(GL_RGBA32F);
    target.depth = makeRenderbuffer(GL_DEPTH_COMPONENT32F);
    glNamedFramebufferRenderbuffer(id, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, target.color.id());
    glNamedFramebufferRenderbuffer(id, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, target.depth.id());
    target.framebuffer.setLabel("snow quality target");
    return target;
}

// RGBA floats, row 0 = the bottom of the image (GL order).
std::vector<float> readFloats(const FloatTarget& target) {
    std::vector<float> pixels(static_cast<std::size_t>(WIDTH) * HEIGHT * 4);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, target.framebuffer.id());
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, WIDTH, HEIGHT, GL_RGBA, GL_FLOAT, pixels.data());
    return pixels;
}

Result<void> writeImage(const std::filesystem::path& file, const std::vector<float>& pixels) {
    std::vector<std::uint8_t> rgba(pixels.size());
    const std::size_t row = static_cast<std::size_t>(WIDTH) * 4;
    for (std::size_t y = 0; y < HEIGHT; ++y)
        for (std::size_t i = 0; i < row; ++i) {
            const float v = std::clamp(pixels[(HEIGHT - 1 - y) * row + i], 0.0f, 1.0f);
            rgba[y * row + i] = i % 4 == 3 ? 255 : static_cast<std::uint8_t>(std::lround(255 * v));
        }
    return writeRgba8Image(file, WIDTH, HEIGHT, rgba);
}

struct Coverage {
    std::vector<float> Fp;  // per pixel; NaN where the sky shows
};

bool isSky(const float* rgb) {
    return rgb[0] == SENTINEL_SKY[0] && rgb[1] == SENTINEL_SKY[1] && rgb[2] == SENTINEL_SKY[2];
}

struct MaskError {
    double meanAbs = 0.0;
    double visibleShare = 0.0;   // share of surface pixels off by more than VISIBLE_ERROR
    std::size_t pixels = 0;      // surface in both images
    std::size_t silhouette = 0;  // surface in one, sky in the other (the snow surface moved)
};

MaskError compare(const Coverage& a, const Coverage& reference) {
    MaskError error;
    std::size_t visible = 0;
    for (std::size_t i = 0; i < a.Fp.size(); ++i) {
        const bool skyA = std::isnan(a.Fp[i]), skyRef = std::isnan(reference.Fp[i]);
        if (skyA || skyRef) {
            error.silhouette += skyA != skyRef ? 1 : 0;
            continue;
        }
        const double d = std::abs(static_cast<double>(a.Fp[i]) - reference.Fp[i]);
        error.meanAbs += d;
        visible += d > VISIBLE_ERROR ? 1 : 0;
        ++error.pixels;
    }
    const double n = static_cast<double>(std::max<std::size_t>(error.pixels, 1));
    error.meanAbs /= n;
    error.visibleShare = static_cast<double>(visible) / n;
    return error;
}

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    return values.empty() ? 0.0 : values[values.size() / 2];
}

struct Timing {
    double wallMs = 0.0, wallMinMs = 0.0, wallMaxMs = 0.0;
    double gpuMs = 0.0;  // snow depth pass + opaque pass, GL_TIME_ELAPSED
    double snowMs = 0.0, meshMs = 0.0;
};

struct Bench {
    render::SceneRenderer& renderer;
    const core::OrbitCamera& camera;
    const FloatTarget& target;
    render::RenderOptions shaded;  // the project's look, snow params set per run
    int frames = 5;
    std::string imageFolder;

    // One untimed frame first: it allocates the depth map of a new resolution and pays the
    // driver's shader compile.
    Timing time(const core::SnowParams& snow) const {
        render::RenderOptions options = shaded;
        options.snow = snow;
        std::vector<double> wall, gpu, snowMs, meshMs;
        for (int frame = 0; frame <= frames; ++frame) {
            const auto start = std::chrono::steady_clock::now();
            renderer.render(camera, WIDTH, HEIGHT, target.framebuffer, options);
            glFinish();
            const std::chrono::duration<double, std::milli> elapsed =
                std::chrono::steady_clock::now() - start;
            if (frame == 0)
                continue;
            const render::FrameTimings t = renderer.lastTimings();
            wall.push_back(elapsed.count());
            gpu.push_back(t.snowMs + t.meshMs);
            snowMs.push_back(t.snowMs);
            meshMs.push_back(t.meshMs);
        }
        const auto [low, high] = std::minmax_element(wall.begin(), wall.end());
        return {median(wall), *low, *high, median(gpu), median(snowMs), median(meshMs)};
    }

    Coverage coverage(const core::SnowParams& snow, const std::string& name) const {
        render::RenderOptions options = shaded;
        options.snow = snow;
        options.snowCoverageView = true;
        options.skyColor = {SENTINEL_SKY[0], SENTINEL_SKY[1], SENTINEL_SKY[2]};
        renderer.render(camera, WIDTH, HEIGHT, target.framebuffer, options);
        const std::vector<float> pixels = readFloats(target);
        Coverage result;
        result.Fp.resize(pixels.size() / 4);
        for (std::size_t i = 0; i < result.Fp.size(); ++i)
            result.Fp[i] =
                isSky(&pixels[4 * i]) ? std::numeric_limits<float>::quiet_NaN() : pixels[4 * i];
        if (!imageFolder.empty())
            (void)writeImage(std::filesystem::path(imageFolder) / (name + "_coverage.png"), pixels);
        return result;
    }

    void shadedImage(const core::SnowParams& snow, const std::string& name) const {
        if (imageFolder.empty())
            return;
        render::RenderOptions options = shaded;
        options.snow = snow;
        renderer.render(camera, WIDTH, HEIGHT, target.framebuffer, options);
        (void)writeImage(std::filesystem::path(imageFolder) / (name + ".png"), readFloats(target));
    }
};

struct Row {
    int resolution = 0, samples = 0;
    Timing timing;
    MaskError error;
    bool pareto = false;
};

bool isReference(const Row& row) {
    return row.resolution == REFERENCE_RESOLUTION && row.samples == REFERENCE_SAMPLES;
}

// On the front: no other row is at most as costly and as wrong, and strictly better in one. Cost
// is wall clock (llvmpipe's timer queries are unreliable); the reference (error 0) is left out.
void markPareto(std::vector<Row>& rows, const Timing& baseline) {
    for (Row& row : rows) {
        row.pareto = !isReference(row);
        const double cost = row.timing.wallMs - baseline.wallMs;
        for (const Row& other : rows) {
            if (isReference(other))
                continue;
            const double otherCost = other.timing.wallMs - baseline.wallMs;
            const bool noWorse = otherCost <= cost && other.error.meanAbs <= row.error.meanAbs;
            const bool better = otherCost < cost || other.error.meanAbs < row.error.meanAbs;
            if (&other != &row && noWorse && better)
                row.pareto = false;
        }
    }
}

std::string formatTable(const std::vector<Row>& rows, const Timing& baseline,
                        const MaskError& referenceError, const std::string& header) {
    std::string out = header;
    char line[512];
    std::snprintf(line, sizeof line,
                  "\nSnow off (baseline): wall %.1f ms (min %.1f, max %.1f), GPU opaque %.2f ms.\n"
                  "Reference %d²/%d against %d²/%d: mean |ΔFp| %.4f, %.2f %% of pixels off by "
                  "> %.1f.\n\n",
                  baseline.wallMs, baseline.wallMinMs, baseline.wallMaxMs, baseline.gpuMs,
                  REFERENCE_RESOLUTION, REFERENCE_SAMPLES, CHECK_RESOLUTION, REFERENCE_SAMPLES,
                  referenceError.meanAbs, 100.0 * referenceError.visibleShare,
                  static_cast<double>(VISIBLE_ERROR));
    out += line;
    out +=
        "| map | samples | snow cost wall ms | frame wall ms (min–max) | depth pass ms | "
        "opaque ms | snow cost GPU ms | mean abs ΔFp | off by > 0.1 | front |\n"
        "|---:|---:|---:|---:|---:|---:|---:|---:|---:|:---:|\n";
    for (const Row& row : rows) {
        std::snprintf(line, sizeof line,
                      "| %d² | %d | %.1f | %.1f (%.1f–%.1f) | %.2f | %.2f | %.2f | %.4f | "
                      "%.2f %% | %s |\n",
                      row.resolution, row.samples, row.timing.wallMs - baseline.wallMs,
                      row.timing.wallMs, row.timing.wallMinMs, row.timing.wallMaxMs,
                      row.timing.snowMs, row.timing.meshMs, row.timing.gpuMs - baseline.gpuMs,
                      row.error.meanAbs, 100.0 * row.error.visibleShare,
                      isReference(row) ? "ref"
                      : row.pareto     ? "*"
                                       : "");
        out += line;
    }
    return out;
}

// A project whose snow is off is measured with its own snow settings switched on (as `grass
// render --snow` does): with snow off every row would be the same frame.
Result<core::LoadedProject> loadInput(const std::string& path) {
    const std::filesystem::path source = GRASS_SOURCE_DIR;
    const std::filesystem::path winter = source / "projects/winter/project.json";
    const bool meadow = path.empty() && !std::filesystem::exists(winter);
    auto loaded = core::loadProject(!path.empty() ? std::filesystem::path(path)
                                    : meadow      ? source / "projects/meadow/project.json"
                                                  : winter);
    if (!loaded || loaded->project.snow.enabled != 0u)
        return loaded;
    loaded->project.snow.enabled = 1u;
    if (meadow) {
        // A slanted fall so the hills' lee slopes and the ball's underside are sheltered.
        loaded->project.snow.fallDirection = {0.3f, -1.0f, 0.2f};
        loaded->project.snow.amountM = 0.1f;
    }
    return loaded;
}

}  // namespace

int main(int argc, char** argv) {
    std::string projectPath, outPath, imageFolder, cameraName, onlyRow, exposure = "pixel";
    int frames = 5;
    double tessPixels = render::RenderOptions{}.snowTessPixels;
    ArgParser parser(
        "snow_quality [project.json] [--out table.md] [--frames N] [--images DIR] "
        "[--camera NAME] [--tess-pixels P] [--row MAPxS] [--exposure pixel|vertex]",
        "Snow map resolution × samples: snow cost against the error of the snow "
        "mask Fp (reference 2048², 32 samples); prints a markdown table.");
    parser.positional("project", "project folder or .json (default: winter, else meadow)",
                      &projectPath, false);
    parser.text("--out", "FILE", "also write the table here", &outPath);
    parser.integer("--frames", "timed frames per setting (after one untimed)", &frames, 1, 100);
    parser.text("--images", "DIR", "write coverage and shaded PNGs here", &imageFolder);
    parser.text("--camera", "NAME", "which of the project's cameras (default: the first)",
                &cameraName);
    parser.number("--tess-pixels", "P", "snow surface edge length on screen in px", &tessPixels,
                  1.0, 1e9, "8");
    parser.text("--row", "MAPxS", "measure only this map size and sample count (1024x8)", &onlyRow);
    parser.choice("--exposure", {"pixel", "vertex"},
                  "the rows' snow exposure per pixel or per tessellated vertex (references: "
                  "per pixel)",
                  &exposure);
    if (auto parsed = parser.parse(std::vector<std::string>(argv + 1, argv + argc)); !parsed) {
        std::fprintf(stderr, "snow_quality: %s\n", parsed.error().str().c_str());
        return 2;
    }
    if (parser.helpRequested()) {
        std::fputs(parser.help().c_str(), stdout);
        return 0;
    }
    const auto fail = [](const auto& error) {
        std::fprintf(stderr, "snow_quality: %s\n", error.str().c_str());
        return 1;
    };
    auto loaded = loadInput(projectPath);
    if (!loaded)
        return fail(loaded.error());
    // The mask is measured on the opaque surfaces, which blades would hide; the blades' own
    // snow (white tips, burial) is not part of this measurement.
    loaded->project.layers.clear();
    const core::SnowParams snow = loaded->project.snow;
    auto context = gl::HeadlessContext::create();
    if (!context)
        return fail(context.error());
    auto scene = core::buildScene(*loaded);
    auto camera = render::projectCamera(loaded->project, cameraName);
    if (!scene || !camera)
        return fail(!scene ? scene.error() : camera.error());
    auto renderer = render::SceneRenderer::create(*scene);
    if (!renderer)
        return fail(renderer.error());
    const FloatTarget target = makeFloatTarget();
    const std::string device = gl::rendererDescription();
    std::fprintf(stderr, "GL: %s\nproject: %s, %zu triangles, %zu props\n", device.c_str(),
                 loaded->file.string().c_str(), scene->mesh->n_faces(), scene->props.size());

    Bench bench{**renderer, *camera,
                target,     render::renderOptionsFor(loaded->project, gl::isSoftwareRenderer()),
                frames,     imageFolder};
    bench.shaded.snowTessPixels = static_cast<float>(tessPixels);
    bench.shaded.snowExposurePerVertex = false;  // the references
    core::SnowParams off = snow;
    off.enabled = 0u;
    const Timing baseline = bench.time(off);
    bench.shadedImage(off, "snow_off");
    core::SnowParams reference = snow;
    reference.mapResolution = REFERENCE_RESOLUTION;
    reference.samples = REFERENCE_SAMPLES;
    const Coverage referenceCoverage = bench.coverage(reference, "reference");
    bench.shadedImage(reference, "reference");
    core::SnowParams check = reference;
    check.mapResolution = CHECK_RESOLUTION;
    const MaskError referenceError = compare(referenceCoverage, bench.coverage(check, "check"));

    bench.shaded.snowExposurePerVertex = exposure == "vertex";
    std::vector<Row> rows;
    for (const int resolution : RESOLUTIONS)
        for (const int samples : SAMPLE_COUNTS) {
            if (!onlyRow.empty() &&
                onlyRow != std::to_string(resolution) + "x" + std::to_string(samples))
                continue;
            core::SnowParams params = snow;
            params.mapResolution = resolution;
            params.samples = samples;
            const std::string name =
                "map" + std::to_string(resolution) + "_s" + std::to_string(samples);
            Row row{resolution, samples, bench.time(params),
                    compare(bench.coverage(params, name), referenceCoverage), false};
            std::fprintf(stderr,
                         "%s: wall %.1f ms, gpu %.2f ms, mean |dFp| %.4f (%zu px, %zu "
                         "silhouette)\n",
                         name.c_str(), row.timing.wallMs, row.timing.gpuMs, row.error.meanAbs,
                         row.error.pixels, row.error.silhouette);
            rows.push_back(row);
        }
    markPareto(rows, baseline);

    const glm::vec3 fall = snow.fallDirection;
    char header[768];
    std::snprintf(
        header, sizeof header,
        "Device: %s\nProject: %s (grass layers left out), camera \"%s\", %dx%d, 1 "
        "sample per pixel, %d timed frames per row (medians).\nSnow: fall direction "
        "(%.2f, %.2f, %.2f), amount %.2f m, sample radius %.2f texels, tessellation %g px, "
        "exposure per %s.\n",
        device.c_str(), loaded->project.name.c_str(),
        cameraName.empty() ? loaded->project.cameras.front().name.c_str() : cameraName.c_str(),
        WIDTH, HEIGHT, frames, static_cast<double>(fall.x), static_cast<double>(fall.y),
        static_cast<double>(fall.z), static_cast<double>(snow.amountM),
        static_cast<double>(snow.sampleRadiusTexels), tessPixels, exposure.c_str());
    const std::string table = formatTable(rows, baseline, referenceError, header);
    std::fputs(table.c_str(), stdout);
    if (!outPath.empty())
        if (auto written = writeFileAtomic(outPath, table); !written)
            return fail(written.error());
    return 0;
}
