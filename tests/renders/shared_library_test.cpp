// GL back ends loaded on demand (renders/shared_library.h): the executable
// no longer maps OSMesa with LLVM 15 and Mesa's EGL at start-up (40 shared
// libraries before, `railjoint --version` 21 ms and 61 MiB; 24 after, 6 ms
// and 12 MiB, measured with farm-bench), and a missing library says which
// Debian package provides it.

#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "renders/shared_library.h"
#include "tests/support/run_cli.h"

namespace railjoint {
namespace {

TEST(SharedLibrary, AMissingLibraryNamesItsPackage) {
  try {
    SharedLibrary missing("libRailjointNoSuchLibrary.so.7", "railjoint-no-such-package");
    ADD_FAILURE() << "loaded a library that does not exist";
  } catch (const std::runtime_error& error) {
    const std::string text = error.what();
    EXPECT_NE(text.find("cannot load libRailjointNoSuchLibrary.so.7"), std::string::npos) << text;
    EXPECT_NE(text.find("install Debian's railjoint-no-such-package"), std::string::npos) << text;
  }
}

TEST(SharedLibrary, AMissingSymbolIsNamed) {
  const SharedLibrary c("libc.so.6", "libc6");
  EXPECT_NE(c.symbol("strlen"), nullptr);
  EXPECT_THROW(c.symbol("railjoint_no_such_symbol"), std::runtime_error);
}

TEST(SharedLibrary, TheExecutableDoesNotLinkTheGlBackEnds) {
  const testing_support::RunResult r = testing_support::run_shell(std::string("ldd ") + RAILJOINT_EXE);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  for (const char* library : {"libOSMesa", "libLLVM", "libEGL"}) {
    EXPECT_EQ(r.output.find(library), std::string::npos) << library << " is linked:\n" << r.output;
  }
}

}  // namespace
}  // namespace railjoint
