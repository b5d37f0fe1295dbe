// SPDX-License-Identifier: MIT
// The progress line: shown on a terminal once the run has lasted long enough, silent otherwise.
#include "alembert/sim/progress.hpp"

#include <gtest/gtest.h>
#include <pty.h>
#include <unistd.h>

#include <cstdio>
#include <string>

namespace alembert {
namespace {

// runs `body` with standard error on a pseudo-terminal and returns what it wrote there
template <class F>
std::string on_terminal(F body) {
    int master = -1, slave = -1;
    if (::openpty(&master, &slave, nullptr, nullptr, nullptr) != 0) return "no pty";
    std::fflush(stderr);
    const int saved = ::dup(2);
    ::dup2(slave, 2);
    body();
    std::fflush(stderr);
    ::dup2(saved, 2);
    ::close(saved);
    ::close(slave);
    // the terminal may hand the text over in pieces: read until it is drained (with the slave
    // side closed, read() ends with EIO once nothing is left)
    std::string text;
    char buf[512];
    for (ssize_t n; (n = ::read(master, buf, sizeof buf)) > 0;)
        text.append(buf, static_cast<std::size_t>(n));
    ::close(master);
    return text;
}

TEST(ProgressIndicator, ShowsTimeAndPercentOnATerminalAndErasesItAtTheEnd) {
    std::string text = on_terminal([] {
        ProgressIndicator p("simulating 'rod'", 0.0, 4.0, true, std::chrono::milliseconds(0));
        p.update(1.0);
        EXPECT_TRUE(p.shown());
    });
    EXPECT_NE(text.find("simulating 'rod': t = 1 of 4 s (25%)"), std::string::npos) << text;
    // the destructor erases the line: the last erase follows the text
    const std::size_t erase = text.rfind("\r\033[K");
    ASSERT_NE(erase, std::string::npos);
    EXPECT_GT(erase, text.find("(25%)"));
}

TEST(ProgressIndicator, StaysSilentForShortRunsAndOffATerminal) {
    std::string text = on_terminal([] {
        ProgressIndicator p("quick", 0.0, 1.0);  // one second must pass first
        p.update(0.5);
        EXPECT_FALSE(p.shown());
    });
    EXPECT_EQ(text.find("quick"), std::string::npos);
    // standard error is not a terminal under CTest: nothing is ever shown
    if (::isatty(2) == 0) {
        ProgressIndicator p("piped", 0.0, 1.0, true, std::chrono::milliseconds(0));
        p.update(0.5);
        EXPECT_FALSE(p.shown());
    }
}

}  // namespace
}  // namespace alembert
