// libOSMesa is loaded when a command first draws (renders/gl_context.h), not
// linked: the executable does not map Mesa and LLVM at start-up (40 shared
// libraries with OSMesa and EGL linked, `railjoint --version` 21 ms and
// 61 MiB; loaded on demand, 6 ms and 12 MiB, measured with farm-bench).

#include <string>

#include <gtest/gtest.h>

#include "tests/support/run_cli.h"

namespace railjoint {
namespace {

TEST(GlContext, TheExecutableDoesNotLinkMesa) {
  const testing_support::RunResult r = testing_support::run_shell(std::string("ldd ") + RAILJOINT_EXE);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  for (const char* library : {"libOSMesa", "libLLVM", "libEGL", "libGL", "libgallium"}) {
    EXPECT_EQ(r.output.find(library), std::string::npos) << library << " is linked:\n" << r.output;
  }
}

}  // namespace
}  // namespace railjoint
