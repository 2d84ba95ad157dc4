// A long-running child process fed lines on its stdin and answering lines on
// its stdout: the Direct3D host under Wine. Its own process group, killed
// (with every child: wine's loader) when the object goes.
#pragma once

#include <sys/types.h>

#include <chrono>
#include <map>
#include <string>
#include <vector>

#include "penumbra/support/result.hpp"

namespace penumbra::d3d {

class HostProcess {
 public:
  // Starts `argv` (argv[0] a path) with `environment` added to this
  // process's; its stderr goes to `log` (appended).
  static Result<HostProcess> start(const std::vector<std::string>& argv,
                                   const std::map<std::string, std::string>& environment,
                                   const std::string& log);
  HostProcess(HostProcess&& other) noexcept;
  HostProcess& operator=(HostProcess&&) = delete;
  HostProcess(const HostProcess&) = delete;
  ~HostProcess();

  Status write(const std::string& text);
  // The next line it prints, without the newline; an error when it exits or
  // stays silent past `timeout`.
  Result<std::string> read_line(std::chrono::milliseconds timeout);

 private:
  HostProcess(pid_t pid, int in, int out, std::string name);

  pid_t pid_ = -1;
  int in_ = -1;   // its stdin, our write end
  int out_ = -1;  // its stdout, our read end
  std::string name_;
  std::string pending_;  // read past the last line returned
};

}  // namespace penumbra::d3d
