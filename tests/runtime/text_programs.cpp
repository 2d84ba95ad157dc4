#include "text_programs.hpp"

#include <gtest/gtest.h>

#include "test_programs.hpp"

namespace penumbra::test {
namespace {

bool is_hlsl(TextShape shape) {
  return shape != TextShape::glsl330;
}

// The prefix of the shape's compiled files in shaders/CMakeLists.txt.
std::string prefix(TextShape shape) {
  switch (shape) {
    case TextShape::hlsl_dx10:
    case TextShape::hlsl_dx10_split:
      return "d3d10_";
    case TextShape::hlsl_dx9:
      return "d3d9_";
    case TextShape::glsl330:
      return "gl330_";
  }
  return "";
}

}  // namespace

std::string_view to_string(TextShape shape) {
  switch (shape) {
    case TextShape::hlsl_dx10:
      return "hlsl_dx10";
    case TextShape::hlsl_dx10_split:
      return "hlsl_dx10_split";
    case TextShape::hlsl_dx9:
      return "hlsl_dx9";
    case TextShape::glsl330:
      return "glsl330";
  }
  return "";
}

StageCode reflected_stage(const std::string& name) {
  StageCode stage{read_spirv(name), {}};
  auto iface = reflect(stage.spirv);
  if (!iface) {
    ADD_FAILURE() << name << ": " << iface.error().to_string();
    return stage;
  }
  stage.iface = std::move(*iface);
  return stage;
}

PassProgram text_depth_program(TextShape shape) {
  PassProgram program{reflected_stage(prefix(shape) + "depth.vert"),
                      reflected_stage(prefix(shape) + "depth.frag")};
  program.d3d_viewport = is_hlsl(shape);
  return program;
}

PassProgram text_compare_program(TextShape shape) {
  const std::string frag = shape == TextShape::hlsl_dx10_split ? "d3d10_compare_ssb.frag"
                                                               : prefix(shape) + "compare.frag";
  PassProgram program{reflected_stage(prefix(shape) + "fullscreen.vert"), reflected_stage(frag)};
  program.d3d_viewport = is_hlsl(shape);
  return program;
}

}  // namespace penumbra::test
