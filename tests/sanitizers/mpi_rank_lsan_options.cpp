// Linked into `railjoint-mpi` (the executable MPI ranks run) in a sanitizer
// build only (RAILJOINT_SANITIZE).
// Open MPI's leaks (tests/sanitizers/lsan.supp) are told apart only by frames
// the fast unwinder does not reach (its components are unloaded by the time
// LeakSanitizer looks), so a process run as an MPI rank unwinds slowly. Not
// every process: the slow unwinder hung a test whose renderer runs threads
// beside an ffmpeg child (RenderCrossing.AssemblesMp4AndGifWhenFfmpegIsOnPath).
//
// The sanitizer runtime asks for these options before the C library is set
// up (getenv still returns null then), so the environment is read from
// /proc/self/environ with plain system calls, and compared without libc;
// and before the runtime has mapped its shadow memory, so nothing here is
// instrumented.

#define RAILJOINT_UNINSTRUMENTED __attribute__((no_sanitize("address", "undefined")))

#include <fcntl.h>
#include <sys/syscall.h>
#include <unistd.h>

namespace {

RAILJOINT_UNINSTRUMENTED bool starts_with(const char* text, const char* prefix) {
  for (; *prefix != '\0'; ++text, ++prefix) {
    if (*text != *prefix) return false;
  }
  return true;
}

// Whether the process runs as an Open MPI rank (mpirun sets OMPI_COMM_WORLD_SIZE).
RAILJOINT_UNINSTRUMENTED bool is_mpi_rank() {
  static char environment[1 << 16];
  const long fd = syscall(SYS_open, "/proc/self/environ", O_RDONLY);
  if (fd < 0) return false;
  long size = 0;
  for (long n = 1; n > 0 && size < static_cast<long>(sizeof environment) - 1; size += n) {
    n = syscall(SYS_read, fd, environment + size, sizeof environment - 1 - static_cast<unsigned long>(size));
    if (n < 0) n = 0;
  }
  syscall(SYS_close, fd);
  environment[size] = '\0';
  for (long i = 0; i < size;) {
    if (starts_with(environment + i, "OMPI_COMM_WORLD_SIZE=")) return true;
    while (i < size && environment[i] != '\0') ++i;
    ++i;
  }
  return false;
}

}  // namespace

extern "C" RAILJOINT_UNINSTRUMENTED const char* __lsan_default_options() { return is_mpi_rank() ? "fast_unwind_on_malloc=0" : ""; }
