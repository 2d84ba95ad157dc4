// Shared by the GL tests: an engine on the default display, a variant's
// emitted passes for a GLSL target, and a scene's inputs for them.
#pragma once

#include <memory>
#include <ostream>
#include <string>

#include "penumbra/compiler/stage.hpp"
#include "penumbra/gl/engine.hpp"
#include "penumbra/model/model.hpp"
#include "penumbra/reference/scene.hpp"
#include "penumbra/runtime/program.hpp"

namespace penumbra {

// GoogleTest prints Target parameters by name ("glsl450") in test listings.
inline void PrintTo(Target target, std::ostream* out) {
  *out << to_string(target);
}

}  // namespace penumbra

namespace penumbra::testing {

// The default GlEngine; fails the calling test (and returns null) without one.
std::unique_ptr<GlEngine> make_gl_engine();

// A variant of permutations/default.json; fails the test when absent.
std::unique_ptr<Variant> default_variant(const std::string& name);

struct PassText {
  std::string vert;  // fullscreen.vert as emitted for the pass
  std::string frag;  // the pass's fragment stage as emitted

  GlPass view() const { return {vert, frag}; }
};

// The variant's pass `kind` compiled for `target` (glsl330 or glsl450).
Result<PassText> emitted_pass(const Variant& variant, Target target, PassKind kind);

struct MinmaxText {
  PassText init;
  PassText reduce;

  GlMinmaxPasses view() const { return {init.view(), reduce.view()}; }
};

// The variant's minmax_init and minmax_reduce passes for `target`.
Result<MinmaxText> emitted_minmax(const Variant& variant, Target target);

// What a query pass over a scene needs: the ray-cast map in linear z and
// normalized by a power of two, the receivers and ShadowParams.
struct SceneInputs {
  reference::Scene scene;
  FloatImage linear_depth;
  FloatImage normalized_depth;
  FloatImage receivers;
  ParamBlock params;
};
SceneInputs scene_inputs(const reference::Scene& scene);

// The first built-in scene's inputs (for tests that need any valid inputs).
SceneInputs any_scene_inputs();

}  // namespace penumbra::testing
