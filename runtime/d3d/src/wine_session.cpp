#include "penumbra/d3d/wine_session.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <vector>

#include "penumbra/support/process.hpp"

extern char** environ;

namespace penumbra {
namespace {

// `name` itself when it is a path, else its first match on PATH; empty when none.
std::string find_program(const std::string& name) {
  if (name.find('/') != std::string::npos) return ::access(name.c_str(), X_OK) == 0 ? name : "";
  const char* path = std::getenv("PATH");
  std::istringstream dirs(path ? path : "/usr/bin:/bin");
  std::string dir;
  while (std::getline(dirs, dir, ':')) {
    const std::string candidate = (dir.empty() ? "." : dir) + "/" + name;
    if (::access(candidate.c_str(), X_OK) == 0) return candidate;
  }
  return {};
}

std::string not_found(const std::string& what, const std::string& install) {
  return what + " not found (Debian: apt-get install " + install + ")";
}

// Starts Xvfb on a free display, which it names on a pipe once it accepts
// clients (-displayfd). Returns its pid and sets `display`.
Result<pid_t> start_xvfb(const std::string& xvfb, std::string& display) {
  int ends[2];
  if (::pipe2(ends, O_CLOEXEC) != 0) {
    return make_error(Error::Kind::io, xvfb,
                      std::string("cannot make a pipe: ") + std::strerror(errno));
  }
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, ends[1], 3);  // dup2 clears close-on-exec
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
  std::vector<std::string> args = {xvfb, "-displayfd", "3",         "-screen",
                                   "0",  "640x480x24", "-nolisten", "tcp"};
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = -1;
  const int spawned = ::posix_spawn(&pid, xvfb.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  ::close(ends[1]);
  if (spawned != 0) {
    ::close(ends[0]);
    return make_error(Error::Kind::device, xvfb,
                      std::string("cannot start: ") + std::strerror(spawned));
  }
  std::string number;
  char c = 0;
  pollfd ready{ends[0], POLLIN, 0};
  while (::poll(&ready, 1, 30000) > 0 && ::read(ends[0], &c, 1) == 1 && c != '\n') number += c;
  ::close(ends[0]);
  if (number.empty()) {
    ::kill(pid, SIGKILL);
    ::waitpid(pid, nullptr, 0);
    return make_error(Error::Kind::device, xvfb, "named no display within 30 s");
  }
  display = ":" + number;
  return pid;
}

}  // namespace

WineSessionOptions WineSession::options_from_environment() {
  WineSessionOptions options;
  if (const char* prefix = std::getenv("WINEPREFIX"); prefix && *prefix) options.prefix = prefix;
  if (const char* display = std::getenv("DISPLAY"); display && *display) options.display = display;
  return options;
}

std::string WineSession::missing_programs(const WineSessionOptions& options) {
  if (find_program(options.wine).empty()) return not_found(options.wine, "wine64 wine");
  if (options.display.empty() && find_program("Xvfb").empty()) return not_found("Xvfb", "xvfb");
  return {};
}

Result<std::shared_ptr<WineSession>> WineSession::start(const WineSessionOptions& options) {
  if (std::string missing = missing_programs(options); !missing.empty()) {
    return make_error(Error::Kind::device, "Wine", missing);
  }
  std::shared_ptr<WineSession> session(new WineSession());
  session->wine_ = find_program(options.wine);
  std::string scratch = (std::filesystem::temp_directory_path() / "penumbra-wine-XXXXXX").string();
  if (!::mkdtemp(scratch.data())) {
    return make_error(Error::Kind::io, scratch,
                      std::string("cannot create a folder: ") + std::strerror(errno));
  }
  session->scratch_ = scratch;
  session->prefix_ = options.prefix;
  if (session->prefix_.empty()) {
    session->prefix_ = session->scratch_ / "prefix";  // Wine makes it on first use
    session->private_prefix_ = true;
  }
  session->display_ = options.display;
  if (session->display_.empty()) {
    auto pid = start_xvfb(find_program("Xvfb"), session->display_);
    if (!pid) return pid.error();
    session->xvfb_ = *pid;
  }
  return session;
}

std::map<std::string, std::string> WineSession::environment() const {
  std::map<std::string, std::string> environment = {
      {"WINEPREFIX", prefix_.string()},
      {"DISPLAY", display_},
      {"WINEDEBUG", "-all"},
      // No Mono or Gecko install prompts in a new prefix.
      {"WINEDLLOVERRIDES", "mscoree,mshtml="},
      // What a sanitized test preloads is for our code, not Wine's.
      {"LD_PRELOAD", ""}};
  // wined3d's command-stream thread spin-waits for the application thread,
  // taking a core from the other hosts and from verify's own threads; the
  // draws are the same without it. A user's own setting wins.
  if (!std::getenv("WINE_D3D_CONFIG")) environment.emplace("WINE_D3D_CONFIG", "csmt=0x0");
  return environment;
}

WineSession::~WineSession() {
  if (private_prefix_) {
    // Its wineserver lingers after the last process: end it before the
    // prefix goes. wineserver sits beside wine.
    const std::string server = (std::filesystem::path(wine_).parent_path() / "wineserver").string();
    static_cast<void>(run_process({"/usr/bin/env", "WINEPREFIX=" + prefix_.string(), server, "-k"},
                                  std::chrono::seconds(30)));
  }
  if (xvfb_ > 0) {
    ::kill(xvfb_, SIGTERM);
    ::waitpid(xvfb_, nullptr, 0);
  }
  std::error_code ignored;
  if (!scratch_.empty()) std::filesystem::remove_all(scratch_, ignored);
}

}  // namespace penumbra
