#include "renders/video_assembly.h"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <sstream>
#include <vector>

extern char** environ;

namespace railjoint {

namespace {

constexpr std::size_t kKeptLogBytes = 4096;

std::string last_non_empty_line(const std::string& text) {
  std::string last;
  std::size_t from = 0;
  while (from < text.size()) {
    std::size_t end = text.find('\n', from);
    if (end == std::string::npos) end = text.size();
    const std::string line = text.substr(from, end - from);
    if (line.find_first_not_of(" \t\r") != std::string::npos) last = line;
    from = end + 1;
  }
  return last;
}

// Waits for the child; returns its exit status or -1 with the reason in `failure`.
int wait_for(int pid, std::string& failure) {
  int status = 0;
  while (waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) {
      failure = std::string("waiting for ffmpeg failed: ") + std::strerror(errno);
      return -1;
    }
  }
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  failure = "ffmpeg was killed by signal " + std::to_string(WTERMSIG(status));
  return -1;
}

}  // namespace

std::optional<std::filesystem::path> find_on_path(const std::string& program) {
  const char* path = std::getenv("PATH");
  if (path == nullptr) return std::nullopt;
  std::stringstream directories(path);
  std::string directory;
  while (std::getline(directories, directory, ':')) {
    if (directory.empty()) continue;
    const std::filesystem::path candidate = std::filesystem::path(directory) / program;
    std::error_code ec;
    if (std::filesystem::is_regular_file(candidate, ec) && access(candidate.c_str(), X_OK) == 0) return candidate;
  }
  return std::nullopt;
}

VideoPipe::VideoPipe(const std::filesystem::path& out_dir, int width_px, int height_px, double video_fps)
    : out_dir_(out_dir), log_(out_dir / "ffmpeg.log") {
  const auto ffmpeg = find_on_path("ffmpeg");
  if (!ffmpeg) {
    failure_ = "ffmpeg not found on PATH: no crossing.mp4 / crossing.gif, the PNG frames are kept";
    return;
  }
  ffmpeg_ = ffmpeg->string();
  std::error_code ignored;
  std::filesystem::remove(log_, ignored);
  std::ostringstream rate;
  rate.precision(10);
  rate << video_fps;
  const std::string size = std::to_string(width_px) + "x" + std::to_string(height_px);
  // One input, two outputs: H.264 needs even sides; the GIF gets a palette
  // made from all its frames (palettegen waits for the end of the stream).
  const std::vector<std::string> arguments = {
      ffmpeg_, "-hide_banner", "-loglevel", "error", "-xerror", "-y", "-f", "rawvideo", "-pix_fmt", "rgb24", "-s", size,
      "-framerate", rate.str(), "-i", "-", "-filter_complex",
      "[0:v]split[v][g];[v]scale=trunc(iw/2)*2:trunc(ih/2)*2[mp4];"
      "[g]scale='min(640,iw)':-2:flags=lanczos,split[a][b];[a]palettegen=stats_mode=diff[p];[b][p]paletteuse[gif]",
      "-map", "[mp4]", "-c:v", "libx264", "-preset", "veryfast", "-crf", "20", "-pix_fmt", "yuv420p",
      (out_dir / "crossing.mp4").string(), "-map", "[gif]", (out_dir / "crossing.gif").string()};

  int fds[2];
  int log_fds[2];
  if (pipe(fds) != 0) {
    failure_ = std::string("cannot make a pipe to ffmpeg: ") + std::strerror(errno);
    return;
  }
  if (pipe2(log_fds, O_CLOEXEC) != 0) {
    failure_ = std::string("cannot make a pipe from ffmpeg: ") + std::strerror(errno);
    close(fds[0]);
    close(fds[1]);
    return;
  }
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, fds[0], STDIN_FILENO);
  posix_spawn_file_actions_addclose(&actions, fds[0]);
  posix_spawn_file_actions_addclose(&actions, fds[1]);
  posix_spawn_file_actions_adddup2(&actions, log_fds[1], STDOUT_FILENO);
  posix_spawn_file_actions_adddup2(&actions, log_fds[1], STDERR_FILENO);
  std::vector<char*> argv;
  for (const auto& a : arguments) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, ffmpeg_.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  close(fds[0]);
  close(log_fds[1]);
  if (spawned != 0) {
    close(fds[1]);
    close(log_fds[0]);
    failure_ = std::string("could not start ffmpeg: ") + std::strerror(spawned);
    return;
  }
  pid_ = pid;
  pipe_fd_ = fds[1];
  fcntl(pipe_fd_, F_SETFD, FD_CLOEXEC);  // later children must not hold ffmpeg's input open
  log_fd_ = log_fds[0];
  log_reader_ = std::thread([this] { copy_log(); });
}

void VideoPipe::copy_log() {
  std::ofstream log;  // opened at ffmpeg's first word: a silent ffmpeg leaves no log
  char buffer[4096];
  for (;;) {
    const ssize_t n = read(log_fd_, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    if (!log.is_open()) log.open(log_, std::ios::binary | std::ios::app);
    log.write(buffer, n);
    log.flush();  // best effort: on a full disk the tail below still says why
    log_tail_.append(buffer, static_cast<std::size_t>(n));
    if (log_tail_.size() > 2 * kKeptLogBytes) log_tail_.erase(0, log_tail_.size() - kKeptLogBytes);
  }
  close(log_fd_);
}

VideoPipe::~VideoPipe() {
  if (finished_) return;
  try {
    finish();  // the run failed already: its own error is the one reported
  } catch (const std::exception&) {
  }
}

void VideoPipe::write(const RgbImage& frame) {
  if (!running() || write_failed_) return;
  ++frames_;
  // A closed pipe (ffmpeg died) must be an error from write(), not SIGPIPE:
  // held back on this thread while it writes, and taken if the write raised it.
  sigset_t pipe_signal, previous;
  sigemptyset(&pipe_signal);
  sigaddset(&pipe_signal, SIGPIPE);
  pthread_sigmask(SIG_BLOCK, &pipe_signal, &previous);
  const std::uint8_t* data = frame.rgb.data();
  std::size_t left = frame.rgb.size();
  while (left > 0) {
    const ssize_t n = ::write(pipe_fd_, data, left);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const int error = errno;
      write_failed_ = true;
      failure_ = std::string("writing frames to ffmpeg failed: ") + std::strerror(error);
      if (error == EPIPE) {
        const timespec no_wait{};
        sigtimedwait(&pipe_signal, nullptr, &no_wait);
      }
      break;
    }
    data += n;
    left -= static_cast<std::size_t>(n);
  }
  pthread_sigmask(SIG_SETMASK, &previous, nullptr);
}

VideoResult VideoPipe::finish() {
  if (finished_) return result_;
  finished_ = true;
  if (!running()) {
    result_.note = failure_;
    return result_;
  }
  close(pipe_fd_);
  std::string wait_failure;
  const int status = wait_for(pid_, wait_failure);
  pid_ = -1;
  log_reader_.join();  // ffmpeg gone: its end of the pipe is closed
  if (frames_ == 0) {
    result_.note = "no frames to assemble";
    return result_;
  }
  if (status == 0 && failure_.empty()) {
    result_.mp4 = out_dir_ / "crossing.mp4";
    result_.gif = out_dir_ / "crossing.gif";
    result_.note = "videos made by " + ffmpeg_ + " from " + std::to_string(frames_) + " raw frames piped to it";
    return result_;
  }
  // ffmpeg's own status first: a closed pipe is the consequence of its exit.
  const std::string why = status > 0 ? "exit status " + std::to_string(status) : status < 0 ? wait_failure : failure_;
  const std::string logged = last_non_empty_line(log_tail_);
  throw std::runtime_error("ffmpeg failed making crossing.mp4 / crossing.gif (" + why +
                           (logged.empty() ? std::string() : ": " + logged) + ")");
}

}  // namespace railjoint
