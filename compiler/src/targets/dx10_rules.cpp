#include <map>
#include <string>

#include "targets/rules.hpp"

namespace penumbra {
namespace {

// Instructions that take screen-space derivatives of their operands: the
// implicit-LOD samples (Sample, SampleCmp) and the derivatives themselves.
const char* gradient_construct(spv::Op op) {
  switch (op) {
    case spv::OpImageSampleImplicitLod:
      return "implicit-LOD sampling (Sample)";
    case spv::OpImageSampleDrefImplicitLod:
      return "implicit-LOD comparison sampling (SampleCmp)";
    case spv::OpImageSampleProjImplicitLod:
    case spv::OpImageSampleProjDrefImplicitLod:
      return "implicit-LOD projective sampling";
    case spv::OpImageQueryLod:
      return "level-of-detail query (CalculateLevelOfDetail)";
    case spv::OpDPdx:
      return "derivative (ddx)";
    case spv::OpDPdy:
      return "derivative (ddy)";
    case spv::OpDPdxFine:
      return "derivative (ddx_fine)";
    case spv::OpDPdyFine:
      return "derivative (ddy_fine)";
    case spv::OpDPdxCoarse:
      return "derivative (ddx_coarse)";
    case spv::OpDPdyCoarse:
      return "derivative (ddy_coarse)";
    case spv::OpFwidth:
    case spv::OpFwidthFine:
    case spv::OpFwidthCoarse:
      return "derivative (fwidth)";
    default:
      return nullptr;
  }
}

// Whether `id` is a constant zero: a scalar, a null or a vector of zeros.
bool is_zero_constant(const SpirvModule& m, std::uint32_t id) {
  const SpvInstruction* value = m.def(id);
  if (!value) return false;
  if (value->op == spv::OpConstantNull) return true;
  if (value->op == spv::OpConstant) return value->operand(0) == 0;
  if (value->op != spv::OpConstantComposite) return false;
  for (std::size_t k = 0; k < value->operand_count(); ++k) {
    if (!is_zero_constant(m, value->operand(k))) return false;
  }
  return true;
}

// Sampling other than SampleLevel and SampleCmpLevelZero; nullptr when fine.
const char* sampling_construct(const SpirvModule& m, const SpvInstruction& in) {
  // The image-operands mask follows the coordinate (and the depth reference).
  std::size_t mask = 2;
  switch (in.op) {
    case spv::OpImageSampleImplicitLod:
    case spv::OpImageSampleDrefImplicitLod:
    case spv::OpImageSampleProjImplicitLod:
    case spv::OpImageSampleProjDrefImplicitLod:
      return gradient_construct(in.op);
    case spv::OpImageGather:
    case spv::OpImageDrefGather:
      return "gather (Gather)";
    case spv::OpImageSampleExplicitLod:
    case spv::OpImageSampleProjExplicitLod:
      break;
    case spv::OpImageSampleDrefExplicitLod:
    case spv::OpImageSampleProjDrefExplicitLod:
      mask = 3;
      break;
    default:
      return nullptr;
  }
  const std::uint32_t operands = in.operand(mask);
  if (operands & spv::ImageOperandsGradMask) {
    // A comparison with zero gradients is level 0: GLSL's only way to say
    // textureLod on a sampler2DArrayShadow, SampleCmpLevelZero in HLSL.
    const bool level_zero = mask == 3 && is_zero_constant(m, in.operand(mask + 1)) &&
                            is_zero_constant(m, in.operand(mask + 2));
    if (!level_zero) return "gradient sampling (SampleGrad)";
  }
  if (mask == 3 && (operands & spv::ImageOperandsLodMask)) {
    // The level follows the mask; SampleCmpLevelZero has no other level.
    const SpvInstruction* lod = m.def(in.operand(mask + 1));
    if (!lod || lod->op != spv::OpConstant || lod->operand(0) != 0) {
      return "comparison sampling at a level other than 0 (SampleCmpLevel)";
    }
  }
  return nullptr;
}

class GradientFinder {
 public:
  explicit GradientFinder(const SpirvModule& m) : m_(m) {}

  // The first gradient construct in `labels` of `f`, calls followed.
  const char* in_blocks(const SpvFunction& f, const std::set<std::uint32_t>& labels) {
    for (const SpvBlock& b : f.blocks) {
      if (!labels.contains(b.label)) continue;
      for (std::size_t k = b.first; k < b.end; ++k) {
        const SpvInstruction& in = m_.instructions()[k];
        if (const char* found = gradient_construct(in.op)) return found;
        if (in.op != spv::OpFunctionCall) continue;
        if (const char* found = in_function(in.operand(0))) return found;
      }
    }
    return nullptr;
  }

 private:
  const char* in_function(std::uint32_t id) {
    if (auto it = memo_.find(id); it != memo_.end()) return it->second;
    memo_[id] = nullptr;  // SPIR-V has no recursion; this only guards bad input
    const SpvFunction* f = m_.function(id);
    if (!f) return nullptr;
    std::set<std::uint32_t> all;
    for (const SpvBlock& b : f->blocks) all.insert(b.label);
    return memo_[id] = in_blocks(*f, all);
  }

  const SpirvModule& m_;
  std::map<std::uint32_t, const char*> memo_;
};

Status violation(const ShaderJob& job, const std::string& construct, const char* why) {
  return make_error(
      Error::Kind::compile, job.describe(),
      construct + " is not allowed for " + std::string(to_string(job.target)) + ": " + why);
}

}  // namespace

Status check_dx10_rules(const ShaderJob& job, const SpirvModule& module) {
  // Loops first: that message says where the gradient is and why it matters there.
  GradientFinder finder(module);
  for (const SpvFunction& f : module.functions()) {
    for (const SpvBlock& b : f.blocks) {
      if (!b.is_loop_header()) continue;
      if (const char* construct = finder.in_blocks(f, f.loop_construct(b))) {
        return violation(job, std::string(construct) + " inside a loop",
                         "gradients in a loop make FXC unroll it or fail (X3570); sample "
                         "with SampleLevel or take derivatives before the loop");
      }
    }
  }
  for (const SpvInstruction& in : module.instructions()) {
    if (const char* construct = sampling_construct(module, in)) {
      return violation(job, construct,
                       "the library samples with SampleLevel and SampleCmpLevelZero only");
    }
  }
  return {};
}

}  // namespace penumbra
