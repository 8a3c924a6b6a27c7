// The editor's timeline for keyed motion (issue 8): the span of scene time the wind sources'
// and colliders' paths are keyed over, the current time, and play / pause / step / loop /
// speed; plus the edits of path keys (core/physics/wind.h PathKey) the timeline makes. Times are
// scene seconds (the time of samplePath and of the physics), not wall-clock time; wall time
// enters only through advance(). Pure C++: the editor draws it and steps the physics by it.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "physics/wind.h"
#include "project/project.h"

namespace grass::core {

// Playback speeds (scene seconds per wall second): below a tenth the field seems frozen, above
// 8 the physics cannot keep up in the editor on software GL.
inline constexpr double TIMELINE_MIN_SPEED = 0.1;
inline constexpr double TIMELINE_MAX_SPEED = 8.0;
// The shortest default range: a project without keys (or keyed over a second) still gets a span
// long enough to watch the wind.
inline constexpr double TIMELINE_MIN_DEFAULT_END_S = 10.0;

// What a change of the current time means for the simulation, which can only step forwards.
enum class TimeChange {
    None,         // the time did not move
    Continuous,   // moved forwards by playing or stepping: keep stepping from the current state
    JumpForward,  // scrubbed ahead: the state is still the past of the new time; step the gap
    JumpBack,     // moved backwards (scrub, step back, loop wrap, a shorter range): the state
                  // belongs to a later time, so reset to rest and re-simulate from startS()
};

struct TimeUpdate {
    TimeChange change = TimeChange::None;
    double fromS = 0.0;
    double toS = 0.0;
    bool needsReset() const { return change == TimeChange::JumpBack; }
    bool operator==(const TimeUpdate&) const = default;
};

class Timeline {
public:
    // [0, 10] s, stepped at 60 Hz, paused, not looping, speed 1.
    Timeline() = default;
    // Precondition: finite times, stepS > 0. An end before the start gives an empty range.
    Timeline(double startS, double endS, double stepS);

    double startS() const { return mStartS; }
    double endS() const { return mEndS; }
    double timeS() const { return mTimeS; }
    double stepS() const { return mStepS; }
    double speed() const { return mSpeed; }
    bool playing() const { return mPlaying; }
    bool looping() const { return mLoop; }

    // Non-finite values are ignored (false). The current time is clamped into the new range.
    bool setRange(double startS, double endS, TimeUpdate* update = nullptr);
    // The physics step dtS; refused (false) unless finite and > 0.
    bool setStep(double stepS);
    // Refused (false) unless finite and > 0 (the physics cannot run backwards); otherwise
    // clamped to [TIMELINE_MIN_SPEED, TIMELINE_MAX_SPEED].
    bool setSpeed(double speed);
    void setLoop(bool loop) { mLoop = loop; }

    // Playing from the end of a range that does not loop starts again from the start.
    TimeUpdate play();
    void pause() { mPlaying = false; }
    TimeUpdate toggle();

    // One editor frame: moves the time by wallElapsedS·speed while playing. Past the end it wraps
    // to the start when looping (any number of times over), or stops at the end and pauses.
    // NaN, infinite and negative elapsed times are ignored.
    TimeUpdate advance(double wallElapsedS);
    // One physics step forwards (clamped to the end) or backwards (to the start); both pause.
    TimeUpdate stepForward();
    TimeUpdate stepBack();
    // Moves to timeS clamped into the range (NaN is ignored); playback state is unchanged.
    TimeUpdate scrub(double timeS);

private:
    TimeUpdate moveTo(double timeS, TimeChange forwards);
    double mStartS = 0.0;
    double mEndS = TIMELINE_MIN_DEFAULT_END_S;
    double mTimeS = 0.0;
    double mStepS = 1.0 / 60.0;
    double mSpeed = 1.0;
    bool mPlaying = false;
    bool mLoop = false;
};

// The default timeline of a project: from 0 to max(its last key time, 10 s), stepped at its
// physics dtS.
Timeline timelineFor(const Project& project);

// Every key time of every wind and collider path, sorted, each once: the timeline's ticks.
std::vector<float> keyTimes(const Project& project);

// One key of a path with the object it moves: what the timeline strip draws as a tick and
// selects on a click.
struct OwnedKey {
    float timeS = 0.0f;
    bool wind = true;        // a wind source's path, else a collider's
    std::size_t index = 0;   // into project.wind or project.colliders
    bool operator==(const OwnedKey&) const = default;
};
// Every key of every path, by time (wind sources before colliders at equal times).
std::vector<OwnedKey> ownedKeys(const Project& project);
// The key whose tick is nearest `timeS`, within `toleranceS` (the first of equals).
std::optional<OwnedKey> nearestOwnedKey(const std::vector<OwnedKey>& keys, float timeS,
                                        float toleranceS);

// --- Key edits. Paths stay sorted by time (samplePath's precondition). ----------------------

// Keys posWorld at timeS: the nearest key within toleranceS (the editor passes half a physics
// step: the same frame) gets the new position and keeps its time, so re-keying a scrubbed frame
// does not shift the timing; otherwise a new key is inserted in time order. Returns its index.
// Precondition: finite timeS and posWorld, toleranceS ≥ 0.
std::size_t setKey(std::vector<PathKey>& path, float timeS, glm::vec3 posWorld, float toleranceS);

// Removes the key nearest timeS if it lies within toleranceS; false when there is none.
bool removeKey(std::vector<PathKey>& path, float timeS, float toleranceS);

// The index of the key nearest timeS (the earlier one on a tie), within maxDistanceS; nullopt
// for an empty path or when every key is farther.
std::optional<std::size_t> nearestKey(const std::vector<PathKey>& path, float timeS,
                                      float maxDistanceS = 3.4e38f);

}  // namespace grass::core
