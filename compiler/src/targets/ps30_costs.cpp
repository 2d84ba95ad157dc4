#include "targets/ps30_costs.hpp"

#include <spirv/unified1/GLSL.std.450.h>

namespace penumbra {
namespace {

// SM 3.0 arithmetic works on whole float4 registers, so a vector operation
// costs what the scalar one does; only the scalar-only instructions (rcp,
// rsq, exp, log, sincos) are issued once per component.
int glsl_std_450_slots(std::uint32_t instruction, int n) {
  switch (instruction) {
    case GLSLstd450FAbs:
    case GLSLstd450SAbs:
      return 0;  // the _abs source modifier
    case GLSLstd450Fract:
    case GLSLstd450FMin:
    case GLSLstd450UMin:
    case GLSLstd450SMin:
    case GLSLstd450FMax:
    case GLSLstd450UMax:
    case GLSLstd450SMax:
    case GLSLstd450NMin:
    case GLSLstd450NMax:
    case GLSLstd450Fma:
    case GLSLstd450Radians:
    case GLSLstd450Degrees:
      return 1;            // frc, min, max, mad, mul
    case GLSLstd450Floor:  // frc, add
    case GLSLstd450FClamp:
    case GLSLstd450UClamp:
    case GLSLstd450SClamp:
    case GLSLstd450NClamp:  // max, min
    case GLSLstd450FMix:    // lrp
    case GLSLstd450Step:    // add, cmp
    case GLSLstd450Cross:   // crs
    case GLSLstd450FaceForward:
      return 2;
    case GLSLstd450Ceil:
    case GLSLstd450Trunc:
    case GLSLstd450Round:
    case GLSLstd450RoundEven:
    case GLSLstd450FSign:
    case GLSLstd450SSign:
    case GLSLstd450Length:     // dp, rsq, rcp
    case GLSLstd450Normalize:  // nrm
    case GLSLstd450Reflect:
      return 3;
    case GLSLstd450Distance:
      return 4;
    case GLSLstd450SmoothStep:
      return 6;
    case GLSLstd450Exp2:
    case GLSLstd450Log2:
    case GLSLstd450InverseSqrt:
      return n;  // exp, log, rsq per component
    case GLSLstd450Exp:
    case GLSLstd450Log:
    case GLSLstd450Sqrt:  // rsq, rcp
      return 2 * n;
    case GLSLstd450Pow:
      return 3 * n;
    case GLSLstd450Sin:
    case GLSLstd450Cos:
      return 8 * n;  // sincos
    case GLSLstd450Tan:
      return 10 * n;
    default:
      return 4 * n;  // inverse trigonometry and the rest: a short polynomial each
  }
}

bool has_image_operand(const SpvInstruction& in, spv::ImageOperandsMask operand) {
  return in.operand_count() > 2 && (in.operand(2) & operand) != 0;  // the mask follows coordinate
}

bool samples_cube(const SpirvModule& module, const SpvInstruction& in) {
  const SpvInstruction* sampled = module.def(in.operand(0));
  const SpvInstruction* type = sampled ? module.def(sampled->type_id) : nullptr;
  const SpvInstruction* image =
      type && type->op == spv::OpTypeSampledImage ? module.def(type->operand(0)) : nullptr;
  return image && image->op == spv::OpTypeImage && image->operand(1) == spv::DimCube;
}

bool is_output_variable(const SpirvModule& module, std::uint32_t pointer) {
  const SpvInstruction* def = module.def(pointer);
  return def && def->op == spv::OpVariable && def->operand(0) == spv::StorageClassOutput;
}

}  // namespace

int ps30_instruction_slots(const SpirvModule& module, const SpvInstruction& in) {
  const int n = static_cast<int>(module.components(in.type_id));
  switch (in.op) {
    // Register bookkeeping: swizzles, write masks, modifiers, inlined calls.
    case spv::OpLoad:
    case spv::OpAccessChain:
    case spv::OpInBoundsAccessChain:
    case spv::OpCompositeExtract:
    case spv::OpVectorShuffle:
    case spv::OpCopyObject:
    case spv::OpVariable:
    case spv::OpPhi:
    case spv::OpFNegate:
    case spv::OpSNegate:
    case spv::OpConvertSToF:
    case spv::OpConvertUToF:
    case spv::OpBitcast:
    case spv::OpSampledImage:
    case spv::OpImage:
    case spv::OpUndef:
    case spv::OpFunctionCall:
    case spv::OpFunctionParameter:
    case spv::OpLine:
    case spv::OpNoLine:
    case spv::OpSelectionMerge:
    case spv::OpLoopMerge:
    case spv::OpBranch:
    case spv::OpBranchConditional:
    case spv::OpSwitch:
    case spv::OpReturn:
    case spv::OpReturnValue:
    case spv::OpUnreachable:
      return 0;
    case spv::OpStore:  // a mov only into an output register (oC#, oDepth)
      return is_output_variable(module, in.operand(0)) ? 1 : 0;
    case spv::OpCompositeConstruct: {  // a mov unless a splat or made of literals
      bool splat = true, literal = true;
      for (std::size_t k = 0; k < in.operand_count(); ++k) {
        splat = splat && in.operand(k) == in.operand(0);
        literal = literal && module.is_constant(in.operand(k));
      }
      return splat || literal ? 0 : 1;
    }
    // Texture slots from the ps_3_0 table, which charges more for cube maps.
    case spv::OpImageSampleImplicitLod:
      if (has_image_operand(in, spv::ImageOperandsBiasMask)) return 6;  // texldb
      return samples_cube(module, in) ? 4 : 1;                          // texld
    case spv::OpImageSampleExplicitLod:
      if (has_image_operand(in, spv::ImageOperandsGradMask)) return 3;  // texldd
      return samples_cube(module, in) ? 5 : 2;                          // texldl
    case spv::OpKill:
      return 2;  // texkill
    case spv::OpFDiv:
    case spv::OpSDiv:
    case spv::OpUDiv:
      return n + 1;  // rcp per component, mul
    case spv::OpFMod:
    case spv::OpFRem:
    case spv::OpSMod:
    case spv::OpSRem:
    case spv::OpUMod:
      return n + 3;  // rcp per component, mul, frc, mul
    case spv::OpConvertFToS:
    case spv::OpConvertFToU:
      return 2;  // frc, add
    case spv::OpDot: {
      const SpvInstruction* a = module.def(in.operand(0));
      return a && module.components(a->type_id) == 2 ? 2 : 1;  // dp2add : dp3, dp4
    }
    case spv::OpMatrixTimesVector:
    case spv::OpVectorTimesMatrix:
      return n;  // one dp per result component
    case spv::OpExtInst:
      return in.operand(0) == module.glsl_std_450() ? glsl_std_450_slots(in.operand(1), n) : n;
    default:
      return 1;  // add, mul, mad, cmp, comparisons, selects, ...
  }
}

}  // namespace penumbra
