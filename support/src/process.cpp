#include "penumbra/support/process.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <climits>
#include <cstring>
#include <thread>

extern char** environ;

namespace penumbra {
namespace {

using std::chrono::milliseconds;
using std::chrono::steady_clock;

// Closes a descriptor when it goes out of scope.
struct Fd {
  int fd = -1;
  ~Fd() {
    if (fd >= 0) ::close(fd);
  }
};

// posix_spawn's two option objects, destroyed with this.
struct SpawnSetup {
  posix_spawn_file_actions_t actions;
  posix_spawnattr_t attributes;
  SpawnSetup() {
    posix_spawn_file_actions_init(&actions);
    posix_spawnattr_init(&attributes);
  }
  ~SpawnSetup() {
    posix_spawn_file_actions_destroy(&actions);
    posix_spawnattr_destroy(&attributes);
  }
};

// Reads the program's output until every writer closed it or `deadline`
// passed (false: the deadline).
bool read_until_closed(int fd, steady_clock::time_point deadline, std::string& output) {
  char buffer[4096];
  for (;;) {
    const auto left = std::chrono::duration_cast<milliseconds>(deadline - steady_clock::now());
    if (left.count() <= 0) return false;
    pollfd ready{fd, POLLIN, 0};
    const int polled =
        ::poll(&ready, 1, static_cast<int>(std::min<long long>(left.count(), INT_MAX)));
    if (polled <= 0) continue;  // the deadline is checked above; EINTR retries
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n > 0) {
      output.append(buffer, static_cast<std::size_t>(n));
    } else if (n == 0 || errno != EINTR) {
      return true;
    }
  }
}

}  // namespace

Result<ProcessRun> run_process(const std::vector<std::string>& argv, milliseconds timeout) {
  if (argv.empty()) return make_error(Error::Kind::internal, "run_process", "no program given");
  int ends[2];
  // Close-on-exec: a program another thread starts meanwhile must not inherit
  // the write end, or this one's end of output would wait for that one too.
  if (::pipe2(ends, O_CLOEXEC) != 0) {
    return make_error(Error::Kind::io, argv[0],
                      std::string("cannot make a pipe: ") + std::strerror(errno));
  }
  Fd read_end{ends[0]};
  Fd write_end{ends[1]};

  SpawnSetup setup;
  posix_spawn_file_actions_addopen(&setup.actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_adddup2(&setup.actions, write_end.fd, 1);
  posix_spawn_file_actions_adddup2(&setup.actions, write_end.fd, 2);
  // A group of its own, so that a timeout kills what a wrapper script started.
  posix_spawnattr_setpgroup(&setup.attributes, 0);
  posix_spawnattr_setflags(&setup.attributes, POSIX_SPAWN_SETPGROUP);
  std::vector<char*> args;
  for (const std::string& arg : argv) args.push_back(const_cast<char*>(arg.c_str()));
  args.push_back(nullptr);
  pid_t pid = 0;
  const int spawned =
      ::posix_spawn(&pid, argv[0].c_str(), &setup.actions, &setup.attributes, args.data(), environ);
  if (spawned != 0) {
    return make_error(Error::Kind::io, argv[0],
                      std::string("cannot run the program: ") + std::strerror(spawned));
  }
  ::close(write_end.fd);
  write_end.fd = -1;

  ProcessRun run;
  const steady_clock::time_point deadline = steady_clock::now() + timeout;
  run.timed_out = !read_until_closed(read_end.fd, deadline, run.output);
  int status = 0;
  bool reaped = false;
  // Output closed does not mean exited: wait, within the same deadline.
  while (!run.timed_out) {
    const pid_t done = ::waitpid(pid, &status, WNOHANG);
    reaped = done == pid;
    if (reaped || (done < 0 && errno != EINTR)) break;
    if (steady_clock::now() >= deadline) {
      run.timed_out = true;
    } else {
      std::this_thread::sleep_for(milliseconds(2));
    }
  }
  if (run.timed_out) {
    ::kill(-pid, SIGKILL);
    while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    return run;
  }
  run.exit_code = reaped && WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return run;
}

}  // namespace penumbra
