#include "util/terminal_line.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdio>
#include <string>
#include <thread>

#include "util/interrupt_stop.h"

namespace grass::test {
namespace {

std::string contents(std::FILE* file) {
    std::fflush(file);
    std::rewind(file);
    std::string text;
    for (int c = std::fgetc(file); c != EOF; c = std::fgetc(file))
        text.push_back(static_cast<char>(c));
    return text;
}

TEST(TerminalLine, AnOpenProgressLineIsEndedOnceByWhoeverWritesFirst) {
    std::FILE* out = std::tmpfile();
    ASSERT_NE(out, nullptr);
    EXPECT_FALSE(core::endProgressLine(out)) << "nothing was open";
    core::markProgressLineOpen();
    EXPECT_TRUE(core::endProgressLine(out));
    EXPECT_FALSE(core::endProgressLine(out)) << "the progress's own end after the message";
    EXPECT_EQ(contents(out), "\n");
    std::fclose(out);
}

// Ctrl+C while `grass sim` rewrites its progress line on a terminal: the note starts a line of
// its own. Before, it was glued to the end of the progress ("… ~40 s leftnote: interrupted").
TEST(TerminalLine, TheInterruptNoteStartsOnALineOfItsOwn) {
    std::FILE* captured = std::tmpfile();
    ASSERT_NE(captured, nullptr);
    std::fflush(stderr);
    const int savedStderr = ::dup(STDERR_FILENO);
    ASSERT_GE(savedStderr, 0);
    ::dup2(::fileno(captured), STDERR_FILENO);
    {
        core::InterruptStop interrupt;
        std::fputs("\rsim: step 40/100", stderr);
        core::markProgressLineOpen();
        std::raise(SIGINT);
        const auto giveUp = std::chrono::steady_clock::now() + std::chrono::seconds(10);
        while (!interrupt.token().stop_requested() && std::chrono::steady_clock::now() < giveUp)
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
        EXPECT_TRUE(interrupt.token().stop_requested());
        EXPECT_EQ(interrupt.signal(), SIGINT);
    }
    std::fflush(stderr);
    ::dup2(savedStderr, STDERR_FILENO);
    ::close(savedStderr);
    EXPECT_FALSE(core::endProgressLine()) << "the note ended the line";
    EXPECT_EQ(contents(captured),
              "\rsim: step 40/100\n"
              "note: interrupted: stopping at the next stage (again to end at once)\n");
    std::fclose(captured);
}

}  // namespace
}  // namespace grass::test
