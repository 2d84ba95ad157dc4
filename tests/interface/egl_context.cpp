#include "egl_context.hpp"

#include <EGL/eglext.h>

#include <cstring>
#include <map>
#include <string>

namespace penumbra::testing {
namespace {

Error egl_error(std::string_view call) {
  char code[16];
  std::snprintf(code, sizeof code, "0x%04x", static_cast<unsigned>(eglGetError()));
  return make_error(Error::Kind::device, std::string(call), std::string("failed with ") + code);
}

bool has_extension(const char* list, std::string_view name) {
  if (list == nullptr) return false;
  for (std::string_view rest = list; !rest.empty();) {
    const std::size_t end = rest.find(' ');
    if (rest.substr(0, end) == name) return true;
    if (end == std::string_view::npos) break;
    rest.remove_prefix(end + 1);
  }
  return false;
}

// Initialized once; terminated by the process's exit.
Result<EGLDisplay> display() {
  static EGLDisplay initialized = EGL_NO_DISPLAY;
  if (initialized != EGL_NO_DISPLAY) return initialized;
  const bool surfaceless = has_extension(eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS),
                                         "EGL_MESA_platform_surfaceless");
  const EGLDisplay chosen = surfaceless ? eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA,
                                                                EGL_DEFAULT_DISPLAY, nullptr)
                                        : eglGetDisplay(EGL_DEFAULT_DISPLAY);
  if (chosen == EGL_NO_DISPLAY) return egl_error("eglGetDisplay");
  if (eglInitialize(chosen, nullptr, nullptr) != EGL_TRUE) {
    return egl_error("eglInitialize (EGL needs Debian's libegl-mesa0 and libgl1-mesa-dri)");
  }
  initialized = chosen;
  return initialized;
}

}  // namespace

Result<EglContext*> EglContext::current(GlApi api) {
  // Never destroyed: Mesa may be gone when static destructors run.
  static auto& contexts = *new std::map<GlApi, std::unique_ptr<EglContext>>;
  auto found = contexts.find(api);
  if (found == contexts.end()) {
    PENUMBRA_TRY_ASSIGN(const EGLDisplay egl, display());
    const bool es = api == GlApi::es;
    if (eglBindAPI(es ? EGL_OPENGL_ES_API : EGL_OPENGL_API) != EGL_TRUE) {
      return egl_error("eglBindAPI");
    }
    const char* extensions = eglQueryString(egl, EGL_EXTENSIONS);
    EGLConfig config = EGL_NO_CONFIG_KHR;
    EGLSurface surface = EGL_NO_SURFACE;
    if (!has_extension(extensions, "EGL_KHR_surfaceless_context") ||
        !has_extension(extensions, "EGL_KHR_no_config_context")) {
      const EGLint wanted[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE,
                               es ? EGL_OPENGL_ES3_BIT : EGL_OPENGL_BIT, EGL_NONE};
      EGLint count = 0;
      if (eglChooseConfig(egl, wanted, &config, 1, &count) != EGL_TRUE || count == 0) {
        return egl_error("eglChooseConfig (a pbuffer config)");
      }
      constexpr EGLint size[] = {EGL_WIDTH, 1, EGL_HEIGHT, 1, EGL_NONE};
      surface = eglCreatePbufferSurface(egl, config, size);
      if (surface == EGL_NO_SURFACE) return egl_error("eglCreatePbufferSurface");
    }
    // clang-format off
    const EGLint desktop[] = {EGL_CONTEXT_MAJOR_VERSION, 4,
                              EGL_CONTEXT_MINOR_VERSION, 5,
                              EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                              EGL_NONE};
    const EGLint gles[] = {EGL_CONTEXT_MAJOR_VERSION, 3,
                           EGL_CONTEXT_MINOR_VERSION, 0,
                           EGL_NONE};
    // clang-format on
    const EGLContext context = eglCreateContext(egl, config, EGL_NO_CONTEXT, es ? gles : desktop);
    if (context == EGL_NO_CONTEXT) {
      if (surface != EGL_NO_SURFACE) eglDestroySurface(egl, surface);
      return egl_error(es ? "eglCreateContext (OpenGL ES 3.0)"
                          : "eglCreateContext (OpenGL 4.5 core)");
    }
    found =
        contexts.emplace(api, std::unique_ptr<EglContext>(new EglContext(egl, context, surface)))
            .first;
  }
  // glvnd dispatches to one context per thread, whatever its API.
  for (const auto& [other_api, other] : contexts) {
    eglBindAPI(other_api == GlApi::es ? EGL_OPENGL_ES_API : EGL_OPENGL_API);
    if (other_api != api && eglGetCurrentContext() == other->context_) {
      eglMakeCurrent(other->display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    }
  }
  EglContext& chosen = *found->second;
  if (eglBindAPI(api == GlApi::es ? EGL_OPENGL_ES_API : EGL_OPENGL_API) != EGL_TRUE ||
      eglMakeCurrent(chosen.display_, chosen.surface_, chosen.surface_, chosen.context_) !=
          EGL_TRUE) {
    return egl_error("eglMakeCurrent");
  }
  return &chosen;
}

}  // namespace penumbra::testing
