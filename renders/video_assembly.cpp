#include "renders/video_assembly.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <vector>

extern char** environ;

namespace railjoint {

namespace {

// Runs `arguments` (arguments[0] = program path) with stdin from /dev/null and
// stdout/stderr appended to `log`; returns the exit status or a description of
// why it could not run.
int run(const std::vector<std::string>& arguments, const std::filesystem::path& log, std::string& failure) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, log.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0644);
  posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
  std::vector<char*> argv;
  for (const auto& a : arguments) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, arguments[0].c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) {
    failure = std::string("could not start ffmpeg: ") + std::strerror(spawned);
    return -1;
  }
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

VideoResult assemble_videos(const std::filesystem::path& frame_dir, long long frame_count, double video_fps) {
  VideoResult result;
  const auto ffmpeg = find_on_path("ffmpeg");
  if (!ffmpeg) {
    result.note = "ffmpeg not found on PATH: no crossing.mp4 / crossing.gif, the PNG frames are kept";
    return result;
  }
  if (frame_count <= 0) {
    result.note = "no frames to assemble";
    return result;
  }
  const std::filesystem::path log = frame_dir / "ffmpeg.log";
  std::error_code ignored;
  std::filesystem::remove(log, ignored);
  std::ostringstream rate;
  rate.precision(10);
  rate << video_fps;
  // -frames:v stops at this render's frames even if an older, longer render
  // left higher-numbered frames in the folder.
  const std::vector<std::string> input = {ffmpeg->string(), "-nostdin", "-hide_banner", "-loglevel", "error", "-y",
                                          "-framerate", rate.str(), "-i", (frame_dir / "frame_%05d.png").string(),
                                          "-frames:v", std::to_string(frame_count)};
  struct Output {
    const char* name;
    std::vector<std::string> options;
    std::optional<std::filesystem::path>* slot;
  };
  const Output outputs[] = {
      // H.264 in yuv420p needs even sides.
      {"crossing.mp4",
       {"-vf", "scale=trunc(iw/2)*2:trunc(ih/2)*2", "-c:v", "libx264", "-preset", "veryfast", "-crf", "20", "-pix_fmt",
        "yuv420p"},
       &result.mp4},
      {"crossing.gif",
       {"-vf", "scale='min(640,iw)':-2:flags=lanczos,split[a][b];[a]palettegen=stats_mode=diff[p];[b][p]paletteuse"},
       &result.gif},
  };
  std::vector<std::string> notes;
  for (const auto& output : outputs) {
    std::vector<std::string> arguments = input;
    arguments.insert(arguments.end(), output.options.begin(), output.options.end());
    const std::filesystem::path target = frame_dir / output.name;
    arguments.push_back(target.string());
    std::string failure;
    const int status = run(arguments, log, failure);
    if (status == 0) {
      *output.slot = target;
    } else {
      notes.push_back(std::string(output.name) + " failed (" +
                      (status < 0 ? failure : "ffmpeg exit status " + std::to_string(status)) + "; see " +
                      log.string() + ")");
    }
  }
  if (notes.empty()) {
    result.note = "videos assembled with " + ffmpeg->string();
  } else {
    for (std::size_t i = 0; i < notes.size(); ++i) result.note += (i ? "; " : "") + notes[i];
    result.note += "; the PNG frames are kept";
  }
  return result;
}

}  // namespace railjoint
