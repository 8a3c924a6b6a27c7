// New, Open and the imports grow their field on a worker (app/document_job.h): the window goes
// on drawing meanwhile, the job says what it does, and what it grew, or why it could not, comes
// back whole once it is done.
#include "app/document_job.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <future>
#include <thread>

#include "scene/scene.h"

namespace grass::test {
namespace {

using namespace std::chrono_literals;

// A 2 m plane of grass: grows in milliseconds, without GL.
core::LoadedProject tinyPlane() {
    core::LoadedProject loaded;
    loaded.project.name = "tiny";
    loaded.project.mesh.procedural.size = 2.0f;
    loaded.project.layers.front().scatter.density = 200.0f;
    return loaded;
}

// A window at rest sleeps until an event comes (editor/app/idle_wait.h): a job's end wakes it,
// and the frame it wakes must find the job done, whatever its outcome (a cancelled one too).
TEST(DocumentJob, ItsEndIsToldOnceTheJobIsDone) {
    for (const bool cancel : {false, true}) {
        std::promise<void> release;
        std::shared_future<void> released = release.get_future().share();
        std::atomic<int> told{0};
        std::atomic<bool> doneWhenTold{false};
        editor::DocumentJob* seen = nullptr;
        editor::DocumentJob job(
            editor::DocumentAction::New, "", "starting",
            [released](editor::DocumentJob&) -> Result<editor::GrownDocument> {
                released.wait();
                return makeError("test", "nothing grown");
            },
            cancel ? 5000ms : 0ms,
            [&] {
                doneWhenTold = seen != nullptr && seen->done();
                ++told;
            });
        seen = &job;
        EXPECT_EQ(told.load(), 0);
        if (cancel)
            job.cancel();  // ends the delay: the work never runs
        release.set_value();
        job.wait();
        EXPECT_EQ(told.load(), 1) << (cancel ? "cancelled" : "failed");
        EXPECT_TRUE(doneWhenTold.load());
    }
}

TEST(DocumentJob, GrowsOnAWorkerAndHandsBackTheField) {
    std::promise<void> release;
    std::shared_future<void> released = release.get_future().share();
    editor::DocumentJob job(editor::DocumentAction::Open, "somewhere/project.json",
                            "reading project.json",
                            [released](editor::DocumentJob& self) -> Result<editor::GrownDocument> {
                                released.wait();
                                self.setStage("growing tiny");
                                auto field = editor::growField(tinyPlane(), true);
                                if (!field)
                                    return field.error();
                                return editor::GrownDocument{std::move(*field), "note"};
                            });
    // The work waits for the test: the caller's thread is free, and told what the job does.
    EXPECT_FALSE(job.done());
    EXPECT_EQ(job.stage(), "reading project.json");
    EXPECT_EQ(job.action(), editor::DocumentAction::Open);
    release.set_value();
    job.wait();
    ASSERT_TRUE(job.done());
    EXPECT_EQ(job.stage(), "growing tiny");
    auto grown = job.take();
    ASSERT_TRUE(grown.ok()) << grown.error().str();
    EXPECT_EQ(grown->note, "note");
    EXPECT_EQ(grown->field.loaded.project.name, "tiny");
    ASSERT_TRUE(grown->field.physics.has_value());
    // The same field as a build on this thread.
    auto here = core::buildScene(tinyPlane());
    ASSERT_TRUE(here.ok());
    ASSERT_GT(here->totalBlades(), 100u);
    EXPECT_EQ(grown->field.scene->totalBlades(), here->totalBlades());
}

TEST(DocumentJob, AFailureComesBackAsItsError) {
    editor::DocumentJob job(editor::DocumentAction::ImportMesh, "rock.glb", "reading rock.glb",
                            [](editor::DocumentJob&) -> Result<editor::GrownDocument> {
                                return makeError("rock.glb", "not a glTF file");
                            });
    job.wait();
    auto grown = job.take();
    ASSERT_FALSE(grown.ok());
    EXPECT_EQ(grown.error().str(), "rock.glb: not a glTF file");
}

// A job left unfinished (the window closed while a large mesh loads) is waited for, never cut
// off while its worker still writes into it.
TEST(DocumentJob, AnUnfinishedJobIsWaitedForWhenDropped) {
    std::atomic<bool> finished{false};
    {
        editor::DocumentJob job(editor::DocumentAction::New, {}, "starting a new project",
                                [&finished](editor::DocumentJob&) -> Result<editor::GrownDocument> {
                                    std::this_thread::sleep_for(50ms);
                                    finished = true;
                                    return makeError("new project", "stopped");
                                });
        EXPECT_FALSE(job.done());
    }
    EXPECT_TRUE(finished.load());
}

// --load-delay-ms (tests of a slow load) holds the work back by that much.
TEST(DocumentJob, TheDelayHoldsTheWorkBack) {
    const auto start = std::chrono::steady_clock::now();
    std::chrono::steady_clock::time_point began;
    editor::DocumentJob job(
        editor::DocumentAction::New, {}, "starting a new project",
        [&began](editor::DocumentJob&) -> Result<editor::GrownDocument> {
            began = std::chrono::steady_clock::now();
            return makeError("new project", "stopped");
        },
        60ms);
    job.wait();
    EXPECT_GE(began - start, 60ms);
}

// A cancel ends the delay at once and the work never starts; the work sees a cancel that comes
// while it runs (the editor's stops between the read and the growing).
TEST(DocumentJob, ACancelEndsTheDelayAndTheWorkSeesIt) {
    std::atomic<bool> ran{false};
    {
        editor::DocumentJob job(
            editor::DocumentAction::Open, "meadow", "reading meadow",
            [&ran](editor::DocumentJob&) -> Result<editor::GrownDocument> {
                ran = true;
                return makeError("meadow", "stopped");
            },
            std::chrono::hours(1));
        job.cancel();
        job.wait();  // an hour without the cancel
        auto result = job.take();
        ASSERT_FALSE(result.ok());
        EXPECT_NE(result.error().str().find("cancelled"), std::string::npos)
            << result.error().str();
    }
    EXPECT_FALSE(ran.load());

    std::atomic<bool> started{false};
    editor::DocumentJob job(editor::DocumentAction::Open, "meadow", "reading meadow",
                            [&started](editor::DocumentJob& self) -> Result<editor::GrownDocument> {
                                started = true;
                                while (!self.cancelled())
                                    std::this_thread::sleep_for(1ms);
                                return makeError("meadow", "saw the cancel");
                            });
    while (!started.load())
        std::this_thread::sleep_for(1ms);
    job.cancel();
    job.wait();
    EXPECT_EQ(job.take().error().message, "saw the cancel");
}

}  // namespace
}  // namespace grass::test
