// The one subprocess helper (support/child_process.h): a child fed
// through its standard input as ffmpeg is, and one run to completion as a
// figure script is; what each says on standard error and how it ended.

#include <cerrno>
#include <fstream>
#include <iostream>
#include <iterator>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support/child_process.h"
#include "tests/support/scratch_dir.h"

namespace railjoint {
namespace {

TEST(ChildProcess, AFedChildReadsItsInputAndItsMessagesAreLoggedAndKept) {
  const std::filesystem::path log = testing_support::scratch_path("cat.log");
  // cat echoes its input on standard output, which joins standard error here.
  ChildProcess cat("/bin/cat", {}, {.input_from_railjoint = true, .output_to_error = true, .error_log = log});
  ASSERT_TRUE(cat.started()) << cat.start_error();
  const std::string text = "first line\nlast line\n  \n";
  EXPECT_EQ(cat.write_input(text.data(), text.size()), 0);
  const ChildOutcome outcome = cat.wait();
  std::cout << outcome.how << ", last line '" << outcome.last_error << "'\n";
  EXPECT_TRUE(outcome.succeeded());
  EXPECT_EQ(outcome.last_error, "last line") << "the last line that is not blank";
  std::ifstream logged(log, std::ios::binary);
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(logged), {}), text);
}

// ffmpeg that exits early: the write fails with EPIPE and the test process
// is not ended by SIGPIPE.
TEST(ChildProcess, AChildThatStopsReadingFailsTheWriteWithoutSigpipe) {
  ChildStreams fed;
  fed.input_from_railjoint = true;
  ChildProcess child("/bin/sh", {"-c", "echo refused >&2; exit 1"}, fed);
  ASSERT_TRUE(child.started());
  const std::vector<char> frames(1 << 20, 'x');  // more than a pipe holds
  EXPECT_EQ(child.write_input(frames.data(), frames.size()), EPIPE);
  const ChildOutcome outcome = child.wait();
  EXPECT_EQ(outcome.exit_status, 1);
  EXPECT_EQ(outcome.how, "exit status 1");
  EXPECT_EQ(outcome.last_error, "refused");
}

TEST(ChildProcess, RunChildSaysHowItEnded) {
  const ChildOutcome failed = run_child("/bin/sh", {"-c", "echo one >&2; echo two >&2; exit 3"});
  EXPECT_FALSE(failed.succeeded());
  EXPECT_EQ(failed.how, "exit status 3");
  EXPECT_EQ(failed.last_error, "two");
  const ChildOutcome killed = run_child("/bin/sh", {"-c", "kill -9 $$"});
  EXPECT_EQ(killed.exit_status, -1);
  EXPECT_EQ(killed.how, "killed by signal 9");
  EXPECT_TRUE(run_child("/bin/true", {}).succeeded());
}

}  // namespace
}  // namespace railjoint
