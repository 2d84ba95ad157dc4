// Shared by the GL tests: an engine on the default display, a variant's
// emitted query pass for a GLSL target, and a scene's inputs for it.
#pragma once

#include <memory>
#include <ostream>
#include <string>

#include "penumbra/compiler/model.hpp"
#include "penumbra/gl/engine.hpp"
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

struct QueryText {
  std::string vert;  // fullscreen.vert as emitted
  std::string frag;  // query.frag as emitted
};

// The variant's query pass compiled for `target` (glsl330 or glsl450).
Result<QueryText> emitted_query(const Variant& variant, Target target);

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
