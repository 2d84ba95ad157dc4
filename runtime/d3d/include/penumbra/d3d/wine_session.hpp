// WineSession: what the Direct3D runtimes need on Linux, for as long as it
// lives: an X display (wined3d draws through GLX) and a Wine prefix.
//
// Lifecycle: start() once; hand it to every D3dEngine (shared); when the
// last holder lets go, it ends what it started: the wineserver of a private
// prefix (and the prefix), and its Xvfb.
#pragma once

#include <sys/types.h>

#include <atomic>
#include <filesystem>
#include <map>
#include <memory>
#include <string>

#include "penumbra/support/result.hpp"

namespace penumbra {

struct WineSessionOptions {
  // The Wine launcher; found on PATH when not a path.
  std::string wine = "wine";
  // A prefix to use as it is (already initialized, shared with others); ""
  // makes a private one in the temporary folder, removed at the end.
  std::filesystem::path prefix;
  // An X display to use (":5"); "" starts a private Xvfb, ended at the end.
  std::string display;
};

class WineSession {
 public:
  // Finds wine and Xvfb and starts what `options` leaves to it. Errors
  // (Error::Kind::device) say what is missing and how to install it.
  static Result<std::shared_ptr<WineSession>> start(const WineSessionOptions& options);
  // The options from the environment: WINEPREFIX and DISPLAY when set
  // (scripts/test.sh sets both for the whole suite).
  static WineSessionOptions options_from_environment();
  // What start() would miss (wine, or Xvfb when no display is given), with
  // the package to install; empty when nothing. Starts nothing.
  static std::string missing_programs(const WineSessionOptions& options);

  WineSession(const WineSession&) = delete;
  WineSession& operator=(const WineSession&) = delete;
  ~WineSession();

  const std::string& wine() const { return wine_; }
  // WINEPREFIX, DISPLAY, WINEDEBUG, DLL overrides and wined3d settings (no
  // command-stream thread, unless WINE_D3D_CONFIG is set) for a Wine process.
  std::map<std::string, std::string> environment() const;
  // Where the hosts' stderr (Wine's messages) goes.
  std::filesystem::path log() const { return scratch_ / "wine.log"; }
  // A folder of this session's for job files.
  const std::filesystem::path& scratch() const { return scratch_; }
  // A new job's number, from 1: unique however many engines, on however many
  // threads, share the session, so that its folder in scratch() is its own.
  int new_job_number() { return ++jobs_; }

 private:
  WineSession() = default;

  std::string wine_;
  std::filesystem::path prefix_;
  bool private_prefix_ = false;
  std::string display_;
  pid_t xvfb_ = -1;
  std::filesystem::path scratch_;
  std::atomic<int> jobs_ = 0;
};

}  // namespace penumbra
