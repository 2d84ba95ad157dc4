#include "targets/rules.hpp"

#include <spirv/unified1/spirv.hpp>
#include <string>

namespace penumbra {
namespace {

struct ForbiddenOp {
  spv::Op op;
  const char* construct;  // as an engine developer would name it in the target
  const char* why;
};

// Shader Model 3.0 limits (contract section 3).
constexpr ForbiddenOp kDx9Forbidden[] = {
    {spv::OpImageSampleDrefImplicitLod, "comparison sampling (SampleCmp)",
     "SM 3.0 has no comparison samplers; compare in the shader"},
    {spv::OpImageSampleDrefExplicitLod, "comparison sampling (SampleCmpLevelZero)",
     "SM 3.0 has no comparison samplers; compare in the shader"},
    {spv::OpImageSampleProjImplicitLod, "tex2Dproj", "projective lookups are not allowed"},
    {spv::OpImageSampleProjExplicitLod, "tex2Dproj", "projective lookups are not allowed"},
    {spv::OpImageSampleProjDrefImplicitLod, "tex2Dproj", "projective lookups are not allowed"},
    {spv::OpImageSampleProjDrefExplicitLod, "tex2Dproj", "projective lookups are not allowed"},
    {spv::OpImageQuerySize, "textureSize",
     "SM 3.0 has no texture-size query; pass sizes as constants"},
    {spv::OpImageQuerySizeLod, "textureSize",
     "SM 3.0 has no texture-size query; pass sizes as constants"},
    {spv::OpImageFetch, "texelFetch", "SM 3.0 has no texel fetch; sample texel centres"},
    {spv::OpShiftLeftLogical, "integer bit shift", "SM 3.0 has no integer bit operations"},
    {spv::OpShiftRightLogical, "integer bit shift", "SM 3.0 has no integer bit operations"},
    {spv::OpShiftRightArithmetic, "integer bit shift", "SM 3.0 has no integer bit operations"},
    {spv::OpBitwiseAnd, "integer bitwise and", "SM 3.0 has no integer bit operations"},
    {spv::OpBitwiseOr, "integer bitwise or", "SM 3.0 has no integer bit operations"},
    {spv::OpBitwiseXor, "integer bitwise xor", "SM 3.0 has no integer bit operations"},
    {spv::OpNot, "integer bitwise not", "SM 3.0 has no integer bit operations"},
};

Status check_dx9(const ShaderJob& job) {
  const auto& words = job.spirv;
  for (std::size_t i = 5; i < words.size();) {  // skip the 5-word header
    const auto op = static_cast<spv::Op>(words[i] & spv::OpCodeMask);
    const std::uint32_t count = words[i] >> spv::WordCountShift;
    for (const ForbiddenOp& forbidden : kDx9Forbidden) {
      if (op == forbidden.op) {
        return make_error(
            Error::Kind::compile, job.describe(),
            std::string(forbidden.construct) + " is not allowed for hlsl_dx9: " + forbidden.why);
      }
    }
    if (count == 0) break;  // malformed; spirv-val has already rejected such modules
    i += count;
  }
  return {};
}

}  // namespace

Status check_target_rules(const ShaderJob& job) {
  if (job.target == Target::hlsl_dx9) return check_dx9(job);
  return {};
}

}  // namespace penumbra
