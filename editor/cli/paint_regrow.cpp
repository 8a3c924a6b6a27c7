#include "cli/paint_regrow.h"

#include <algorithm>
#include <cstdio>
#include <limits>
#include <optional>
#include <span>

#include "tools/ms_since.h"

namespace grass::cli {

namespace {

using tools::Clock;
using tools::msSince;

// A stroke of many points reports how far it got at most this often, so a long scripted stroke
// shows it is alive without flooding the output.
constexpr double PROGRESS_INTERVAL_MS = 1000.0;
// Points fed to the brush between progress checks.
constexpr std::size_t PROGRESS_CHUNK_POINTS = 256;

// What the strokes so far changed. The value of every texel before its first change, to count
// the texels the whole run changed (a texel painted by two strokes counts once, one painted back
// not at all); the patches re-grown; the bounds touched.
class RunTally {
public:
    RunTally(std::size_t texels, std::size_t patches) : mTouched(texels, 0), mRegrown(patches, 0) {}

    // A stroke that changed texels: returns how many it changed.
    std::size_t addStroke(const core::PaintRecord& record,
                          const std::vector<std::uint32_t>& regrownPatches, double regrowMs) {
        std::size_t changed = 0;
        for (std::size_t k = 0; k < record.texelIndex.size(); ++k) {
            changed += record.before[k] != record.after[k] ? 1 : 0;
            if (!mTouched[record.texelIndex[k]]) {
                mTouched[record.texelIndex[k]] = 1;
                mOriginal.emplace_back(record.texelIndex[k], record.before[k]);
            }
        }
        mBounds = mAnyTouched ? core::Bounds{glm::min(mBounds.min, record.touchedBounds.min),
                                             glm::max(mBounds.max, record.touchedBounds.max)}
                              : record.touchedBounds;
        mAnyTouched = true;
        mRegrowMs += regrowMs;
        for (const std::uint32_t patch : regrownPatches)
            mRegrown[patch] = 1;
        return changed;
    }

    // Texels whose value now differs from the one before the run.
    std::size_t changedTexels(const core::MapImage& painted) const {
        std::size_t changed = 0;
        for (const auto& [texel, before] : mOriginal)
            changed += painted.texels[texel] != before ? 1 : 0;
        return changed;
    }

    std::size_t regrownPatches() const {
        return static_cast<std::size_t>(
            std::count(mRegrown.begin(), mRegrown.end(), std::uint8_t{1}));
    }
    double regrowMs() const { return mRegrowMs; }
    std::string boundsText() const { return mAnyTouched ? cli::boundsText(mBounds) : "(none)"; }

private:
    std::vector<std::uint8_t> mTouched;
    std::vector<std::pair<std::uint32_t, float>> mOriginal;
    std::vector<std::uint8_t> mRegrown;
    double mRegrowMs = 0.0;
    bool mAnyTouched = false;
    core::Bounds mBounds;
};

// Distance from a point to a box, 0 inside: how far off the mesh a stroke that touched nothing
// was.
float distanceToBounds(glm::vec3 point, const core::Bounds& bounds) {
    return glm::length(point - glm::clamp(point, bounds.min, bounds.max));
}

// Feeds one stroke's points to the painter in chunks, so a stroke of many points can report its
// progress. Returns the dabs it took.
std::size_t feedStroke(core::ScenePainter& painter, const std::vector<glm::vec3>& hits,
                       std::size_t strokeNumber) {
    auto lastReport = Clock::now();
    for (std::size_t start = 0; start < hits.size(); start += PROGRESS_CHUNK_POINTS) {
        const std::size_t count = std::min(PROGRESS_CHUNK_POINTS, hits.size() - start);
        painter.addHits(std::span<const glm::vec3>(hits).subspan(start, count));
        if (msSince(lastReport) > PROGRESS_INTERVAL_MS && start + count < hits.size()) {
            std::printf("  stroke %zu: %zu of %zu points, %zu dabs so far\n", strokeNumber,
                        start + count, hits.size(), painter.dabCount());
            std::fflush(stdout);
            lastReport = Clock::now();
        }
    }
    return painter.dabCount();
}

// A stroke that changed nothing: off the mesh (warned), or painting what the map holds.
void reportUnchangedStroke(std::size_t strokeNumber, const std::vector<glm::vec3>& points,
                           std::size_t dabs, const core::TexelSurface& surface, float radiusM) {
    float nearestM = std::numeric_limits<float>::infinity();
    for (const glm::vec3 point : points)
        nearestM = std::min(nearestM, distanceToBounds(point, surface.bounds()));
    if (nearestM > radiusM)
        std::fprintf(stderr,
                     "warning: stroke %zu touched no texel: its nearest point is %.4g "
                     "from the mesh bounds %s, beyond the radius %.4g (off the mesh?)\n",
                     strokeNumber, static_cast<double>(nearestM),
                     boundsText(surface.bounds()).c_str(), static_cast<double>(radiusM));
    std::printf("stroke %zu: %zu points, %zu dabs, 0 texels changed%s\n", strokeNumber,
                points.size(), dabs,
                nearestM > radiusM ? " (off the mesh)" : " (the map already holds what it paints)");
}

}  // namespace

std::string boundsText(const core::Bounds& bounds) {
    char text[160];
    std::snprintf(text, sizeof text, "[%.3g %.3g %.3g] .. [%.3g %.3g %.3g]",
                  static_cast<double>(bounds.min.x), static_cast<double>(bounds.min.y),
                  static_cast<double>(bounds.min.z), static_cast<double>(bounds.max.x),
                  static_cast<double>(bounds.max.y), static_cast<double>(bounds.max.z));
    return text;
}

Result<std::size_t> paintAndRegrow(const PaintCanvas& canvas, const core::BrushSettings& brush,
                                   const std::vector<std::vector<glm::vec3>>& points) {
    const auto& patches = canvas.field.patched.patches;
    RunTally tally(canvas.painted.texels.size(), patches.size());
    std::size_t totalDabs = 0;
    for (std::size_t s = 0; s < points.size(); ++s) {
        canvas.painter.begin(canvas.layerIndex, canvas.which,
                             {canvas.painted.width, canvas.painted.height}, brush);
        const std::size_t dabs = feedStroke(canvas.painter, points[s], s + 1);
        totalDabs += dabs;
        const auto regrowStart = Clock::now();
        auto report = canvas.painter.regrowChanged();
        const double strokeMs = msSince(regrowStart);
        const std::optional<core::PaintEdit> edit = canvas.painter.end();
        if (!report)
            return report.error();
        if (!edit) {
            reportUnchangedStroke(s + 1, points[s], dabs, canvas.surface, brush.radiusM);
            continue;
        }
        const core::PaintRecord& record = edit->record;
        const std::size_t changed = tally.addStroke(record, report->patches, strokeMs);
        std::printf(
            "stroke %zu: %zu points, %zu dabs, %zu texels changed, bounds %s; re-grew %zu "
            "of %zu patches in %.2f ms\n",
            s + 1, points[s].size(), dabs, changed, boundsText(record.touchedBounds).c_str(),
            report->patches.size(), patches.size(), strokeMs);
        std::fflush(stdout);
    }
    const std::size_t totalChanged = tally.changedTexels(canvas.painted);
    std::printf(
        "total: %zu strokes, %zu dabs, %zu texels changed, bounds %s; re-grew %zu of %zu "
        "patches in %.2f ms\n",
        points.size(), totalDabs, totalChanged, tally.boundsText().c_str(), tally.regrownPatches(),
        patches.size(), tally.regrowMs());
    return totalChanged;
}

}  // namespace grass::cli
