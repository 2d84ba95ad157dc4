#include "device_selection.hpp"

#include <EGL/eglext.h>

#include <utility>
#include <vector>

#include "context_info.hpp"
#include "egl_error.hpp"
#include "penumbra/support/device_selector.hpp"

namespace penumbra::gl {
namespace {

// What a failure to open any display usually means on Debian.
constexpr std::string_view kDriverHint =
    " (EGL needs a vendor library and a driver: Debian's libegl-mesa0 and libgl1-mesa-dri, "
    "whose llvmpipe needs no GPU)";

Result<EglContext> context_on(EGLDisplay display, const char* get_call, const std::string& what) {
  auto use = DisplayUse::acquire(display, get_call, what);
  if (!use) {
    Error error = use.error();
    error.message += kDriverHint;
    return error;
  }
  return EglContext::create(std::move(*use));
}

// Mesa's surfaceless platform needs no window system, so it works headless;
// other EGL libraries get the default display and a pbuffer.
Result<OpenedContext> open_default() {
  if (has_client_extension("EGL_MESA_platform_surfaceless")) {
    const std::string what = "Mesa's surfaceless display (EGL_MESA_platform_surfaceless)";
    auto context = context_on(
        eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr),
        "eglGetPlatformDisplay", what);
    if (!context) return context.error();
    return OpenedContext{std::move(*context), what};
  }
  const std::string what = "the default EGL display (EGL_DEFAULT_DISPLAY)";
  auto context = context_on(eglGetDisplay(EGL_DEFAULT_DISPLAY), "eglGetDisplay", what);
  if (!context) return context.error();
  return OpenedContext{std::move(*context), what};
}

Result<std::vector<EGLDeviceEXT>> egl_devices() {
  const auto query =
      reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
  if (!has_client_extension("EGL_EXT_device_enumeration") ||
      !has_client_extension("EGL_EXT_platform_device") || query == nullptr) {
    return make_error(Error::Kind::device, "EGL",
                      "selecting an EGL device needs EGL_EXT_device_enumeration and "
                      "EGL_EXT_platform_device, which this EGL library lacks; use the default "
                      "device (\"\")");
  }
  EGLint count = 0;
  if (query(0, nullptr, &count) != EGL_TRUE) {
    return egl_failure("eglQueryDevicesEXT", "counting EGL devices");
  }
  std::vector<EGLDeviceEXT> devices(static_cast<std::size_t>(count));
  if (count > 0 && query(count, devices.data(), &count) != EGL_TRUE) {
    return egl_failure("eglQueryDevicesEXT", "listing EGL devices");
  }
  devices.resize(static_cast<std::size_t>(count));
  return devices;
}

Result<EglContext> context_on_device(EGLDeviceEXT device, std::size_t index) {
  return context_on(eglGetPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, device, nullptr),
                    "eglGetPlatformDisplay", "EGL device " + std::to_string(index));
}

// The renderer a device's context reports, or why there is none.
std::string describe(Result<EglContext>& context) {
  if (!context) return "(unusable: " + context.error().message + ")";
  auto current = context->make_current();
  if (!current) return "(unusable: " + current.error().message + ")";
  return current_context_info().renderer;
}

}  // namespace

Result<OpenedContext> open_context(const std::string& selector) {
  if (selector.empty()) return open_default();
  auto devices = egl_devices();
  if (!devices) return devices.error();
  // Devices open one at a time, up to the first match: matching the devices
  // seen so far finds the newest one exactly when it is the first match. A
  // name matches only a device whose context opened.
  std::vector<std::string> renderers;  // what the error lists
  std::vector<std::string> names;      // what a selector matches: "" where no context
  for (std::size_t index = 0; index < devices->size(); ++index) {
    auto context = context_on_device((*devices)[index], index);
    renderers.push_back(describe(context));
    names.push_back(context ? renderers.back() : std::string());
    if (!match_selector(names, selector)) continue;
    if (!context) return context.error();
    return OpenedContext{std::move(*context), "EGL device " + std::to_string(index)};
  }
  const std::string listing = list_choices(renderers);
  return make_error(Error::Kind::bad_input, "GL device '" + selector + "'",
                    "no EGL device matches; give an index or part of a renderer of one of: " +
                        (listing.empty() ? "(no EGL devices)" : listing));
}

}  // namespace penumbra::gl
