// Shared by the GL tests: an engine on the default display, a variant's
// passes for a GLSL target as a built library holds them (texts and
// reflection, read back from index.json), and a scene's inputs for them.
#pragma once

#include <memory>
#include <ostream>
#include <string>

#include "penumbra/gl/engine.hpp"
#include "penumbra/model/model.hpp"
#include "penumbra/model/pass.hpp"
#include "penumbra/model/target_reflection.hpp"
#include "penumbra/reference/scene.hpp"

namespace penumbra {

// GoogleTest prints Target parameters by name ("glsl450") in test listings.
inline void PrintTo(Target target, std::ostream* out) {
  *out << to_string(target);
}

}  // namespace penumbra

namespace penumbra::testing {

// The default GlEngine; fails the calling test (and returns null) without one.
std::unique_ptr<GlEngine> make_gl_engine();

struct PassText {
  std::string vert;           // the pass's vertex stage as emitted
  std::string frag;           // the pass's fragment stage as emitted
  PassReflection reflection;  // index.json's reflection.<pass>.<target>

  GlPass view() const { return {vert, frag, reflection}; }
};

// The variant's pass `kind` for `target` (glsl330 or glsl450), from a library
// of the variant built for both GLSL targets (once per test process, in a
// temporary directory) and read back with load_library.
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
