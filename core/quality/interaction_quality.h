// Adaptive interaction quality (issue 24): while the user orbits, paints, drags a gizmo or plays
// the simulation, the viewport keeps a frame budget by drawing a reduced picture, and once input
// stops it draws the full one again — what Blender's and Substance's viewports do. This is the
// decision alone (GL-free, tested); the editor maps a level onto its render settings.
//
// The ladder's order is measured, not guessed (meadow, 1280×720, llvmpipe on 2 cores, issue 24;
// docs/editing.md): 4× MSAA costs 3× the frame (944 → 304 ms), and what is left is vertex work
// per drawn blade (~7.5 µs): halving the resolution saved nothing measurable, a quarter of the
// blades saves three quarters. So: MSAA first, then thinning, then fewer segments, then
// resolution last.
#pragma once

#include <array>
#include <optional>

namespace grass::core {

// One rung: what the viewport draws instead of the project's settings.
struct Reduction {
    bool msaaOff = false;
    int keepEvery = 1;              // draw one blade in N (uniform thinning)
    float lodDistanceScale = 1.0f;  // < 1: fewer segments nearer the camera
    float resolutionScale = 1.0f;   // share of the viewport's pixels per axis
    const char* label = "";         // what the viewport's indicator says
};

inline constexpr std::array<Reduction, 6> REDUCTION_LADDER{{
    {false, 1, 1.0f, 1.0f, "full quality"},
    {true, 1, 1.0f, 1.0f, "MSAA off"},
    {true, 2, 1.0f, 1.0f, "MSAA off, 1/2 blades"},
    {true, 4, 0.5f, 1.0f, "MSAA off, 1/4 blades, LOD"},
    {true, 8, 0.25f, 0.75f, "MSAA off, 1/8 blades, LOD, 3/4 res"},
    {true, 16, 0.0f, 0.5f, "MSAA off, 1/16 blades, LOD, 1/2 res"},
}};

struct InteractionQualitySettings {
    bool enabled = true;
    double budgetMs = 80.0;  // a frame while interacting: 12.5 fps
    // No interaction for this long: the next frame is the full picture.
    double settleS = 0.3;
};

class InteractionQuality {
public:
    InteractionQuality() = default;
    explicit InteractionQuality(InteractionQualitySettings settings) : mSettings(settings) {}

    // Once a frame, before drawing it: the last frame's wall time (at the level it was drawn
    // at), whether the user is interacting now, and the time (seconds, any steady clock).
    // Returns the level to draw this frame at (0: full quality): the least reduced rung whose
    // frame is expected within the budget, the last rung if none is. `lastFrameDrawn` false: the
    // last frame showed the picture before it again (the editor at rest, editor/app/
    // view_redraw.h), so its time says nothing of the rung's cost; the rung's measurement, if
    // any, still holds (the same view costs the same) and stays trusted.
    int update(double lastFrameMs, bool interacting, double nowS, bool lastFrameDrawn = true);

    int level() const { return mLevel; }
    double lastInteractionS() const { return mLastInteractionS; }
    // While reduced: when (on update's clock) the full picture is due if no input comes, so a
    // window at rest wakes for it (editor/app/idle_wait.h). Unset at full quality.
    std::optional<double> fullPictureAtS() const;
    const Reduction& reduction() const { return REDUCTION_LADDER[std::size_t(mLevel)]; }
    const InteractionQualitySettings& settings() const { return mSettings; }
    void setSettings(const InteractionQualitySettings& settings) { mSettings = settings; }

private:
    // A rung's frame time: measured (smoothed, forgotten after a while as the view changes) or,
    // when not measured lately, estimated from the nearest measured rung (each rung ~halves it).
    double estimateMs(int level, double nowS) const;

    InteractionQualitySettings mSettings;
    int mLevel = 0;
    double mLastInteractionS = -1e9;
    struct Measured {
        double ms = 0.0;
        double atS = -1e9;
    };
    std::array<Measured, REDUCTION_LADDER.size()> mMeasured{};
};

}  // namespace grass::core
