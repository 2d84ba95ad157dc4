#include "egl_display.hpp"

#include <map>
#include <mutex>
#include <string>
#include <utility>

#include "egl_error.hpp"

namespace penumbra::gl {
namespace {

// eglInitialize is not reference counted: one eglTerminate ends every
// engine's contexts on that display. So Penumbra counts its own users.
struct Registration {
  int users = 0;
  bool terminate_when_unused = false;  // Penumbra initialized it
};

std::mutex& registry_mutex() {
  static std::mutex mutex;
  return mutex;
}

std::map<EGLDisplay, Registration>& registry() {
  static std::map<EGLDisplay, Registration> displays;
  return displays;
}

}  // namespace

Result<DisplayUse> DisplayUse::acquire(EGLDisplay display, std::string_view get_call,
                                       std::string_view what) {
  if (display == EGL_NO_DISPLAY) return egl_failure(get_call, "getting " + std::string(what));
  const std::lock_guard lock(registry_mutex());
  Registration& registration = registry()[display];
  if (registration.users == 0) {
    // An initialized display answers queries; an uninitialized one fails
    // with EGL_NOT_INITIALIZED, which is cleared here.
    const bool initialized_elsewhere = eglQueryString(display, EGL_VERSION) != nullptr;
    if (!initialized_elsewhere) eglGetError();
    EGLint major = 0;
    EGLint minor = 0;
    if (eglInitialize(display, &major, &minor) != EGL_TRUE) {
      registry().erase(display);
      return egl_failure("eglInitialize", "initializing " + std::string(what));
    }
    registration.terminate_when_unused = !initialized_elsewhere;
  }
  ++registration.users;
  return DisplayUse(display);
}

DisplayUse::DisplayUse(DisplayUse&& other) noexcept
    : display_(std::exchange(other.display_, EGL_NO_DISPLAY)) {}

DisplayUse::~DisplayUse() {
  if (display_ == EGL_NO_DISPLAY) return;
  const std::lock_guard lock(registry_mutex());
  const auto found = registry().find(display_);
  if (found == registry().end() || --found->second.users > 0) return;
  if (found->second.terminate_when_unused) eglTerminate(display_);
  registry().erase(found);
}

bool DisplayUse::has_extension(std::string_view name) const {
  return gl::has_extension(eglQueryString(display_, EGL_EXTENSIONS), name);
}

}  // namespace penumbra::gl
