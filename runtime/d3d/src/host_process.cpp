#include "host_process.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <climits>
#include <cstring>

extern char** environ;

namespace penumbra::d3d {
namespace {

Error io_error(const std::string& where, const std::string& what) {
  return make_error(Error::Kind::io, where, what + ": " + std::strerror(errno));
}

// This process's environment with `extra` set over it, as posix_spawn takes it.
std::vector<std::string> merged_environment(const std::map<std::string, std::string>& extra) {
  std::vector<std::string> out;
  for (char** e = environ; *e; ++e) {
    const std::string entry = *e;
    const std::string key = entry.substr(0, entry.find('='));
    if (!extra.contains(key)) out.push_back(entry);
  }
  for (const auto& [key, value] : extra) out.push_back(key + "=" + value);
  return out;
}

std::vector<char*> pointers(std::vector<std::string>& strings) {
  std::vector<char*> out;
  for (std::string& s : strings) out.push_back(s.data());
  out.push_back(nullptr);
  return out;
}

}  // namespace

HostProcess::HostProcess(pid_t pid, int in, int out, std::string name)
    : pid_(pid), in_(in), out_(out), name_(std::move(name)) {}

HostProcess::HostProcess(HostProcess&& other) noexcept
    : pid_(other.pid_),
      in_(other.in_),
      out_(other.out_),
      name_(std::move(other.name_)),
      pending_(std::move(other.pending_)) {
  other.pid_ = -1;
  other.in_ = -1;
  other.out_ = -1;
}

HostProcess::~HostProcess() {
  if (in_ >= 0) ::close(in_);  // its end of input: the host quits
  if (out_ >= 0) ::close(out_);
  if (pid_ > 0) {
    // Give it a moment to end by itself, then end its whole group.
    for (int i = 0; i < 50 && ::waitpid(pid_, nullptr, WNOHANG) == 0; ++i) ::usleep(20000);
    ::kill(-pid_, SIGKILL);
    ::waitpid(pid_, nullptr, 0);
  }
}

Result<HostProcess> HostProcess::start(const std::vector<std::string>& argv,
                                       const std::map<std::string, std::string>& environment,
                                       const std::string& log) {
  int to_child[2];
  int from_child[2];
  // Close-on-exec, so that no other child inherits our ends (and keeps the
  // host's input open after we close it).
  if (::pipe2(to_child, O_CLOEXEC) != 0) return io_error(argv[0], "cannot make a pipe");
  if (::pipe2(from_child, O_CLOEXEC) != 0) {
    ::close(to_child[0]);
    ::close(to_child[1]);
    return io_error(argv[0], "cannot make a pipe");
  }
  posix_spawn_file_actions_t actions;
  posix_spawnattr_t attributes;
  posix_spawn_file_actions_init(&actions);
  posix_spawnattr_init(&attributes);
  posix_spawn_file_actions_adddup2(&actions, to_child[0], STDIN_FILENO);
  posix_spawn_file_actions_adddup2(&actions, from_child[1], STDOUT_FILENO);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, log.c_str(),
                                   O_WRONLY | O_CREAT | O_APPEND, 0644);
  posix_spawnattr_setpgroup(&attributes, 0);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETPGROUP);
  std::vector<std::string> args = argv;
  std::vector<std::string> env = merged_environment(environment);
  auto arg_pointers = pointers(args);
  auto env_pointers = pointers(env);
  pid_t pid = -1;
  const int spawned = ::posix_spawnp(&pid, argv[0].c_str(), &actions, &attributes,
                                     arg_pointers.data(), env_pointers.data());
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attributes);
  ::close(to_child[0]);
  ::close(from_child[1]);
  if (spawned != 0) {
    ::close(to_child[1]);
    ::close(from_child[0]);
    return make_error(Error::Kind::io, argv[0],
                      std::string("cannot start: ") + std::strerror(spawned));
  }
  // A host that died must fail our writes, not kill us.
  ::signal(SIGPIPE, SIG_IGN);
  return HostProcess(pid, to_child[1], from_child[0], argv[0]);
}

Status HostProcess::write(const std::string& text) {
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = ::write(in_, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) return io_error(name_, "cannot send the job list");
    done += static_cast<std::size_t>(n);
  }
  return {};
}

Result<std::string> HostProcess::read_line(std::chrono::milliseconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  for (;;) {
    if (const auto end = pending_.find('\n'); end != std::string::npos) {
      std::string line = pending_.substr(0, end);
      pending_.erase(0, end + 1);
      if (!line.empty() && line.back() == '\r') line.pop_back();
      return line;
    }
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
        deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) {
      return make_error(Error::Kind::device, name_,
                        "no answer within " + std::to_string(timeout.count() / 1000) + " s");
    }
    pollfd ready{out_, POLLIN, 0};
    if (::poll(&ready, 1, static_cast<int>(std::min<long long>(left.count(), INT_MAX))) <= 0) {
      continue;  // the deadline is checked above; EINTR retries
    }
    char buffer[4096];
    const ssize_t n = ::read(out_, buffer, sizeof buffer);
    if (n > 0) {
      pending_.append(buffer, static_cast<std::size_t>(n));
    } else if (n == 0) {
      return make_error(Error::Kind::device, name_, "exited before answering");
    } else if (errno != EINTR) {
      return io_error(name_, "cannot read its answer");
    }
  }
}

}  // namespace penumbra::d3d
