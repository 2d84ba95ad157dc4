#include <map>
#include <string>
#include <utility>

#include "targets/rules.hpp"

namespace penumbra {
namespace {

struct ForbiddenOp {
  spv::Op op;
  const char* construct;  // as an engine developer would name it in the target
  const char* why;
};

// Shader Model 3.0 limits (docs/targets.md).
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

// Register files of Shader Model 3.0: ps_3_0 has s0-s15 and c0-c223;
// vs_3_0 has the four vertex-texture samplers s0-s3 and at least c0-c255.
struct Registers {
  const char* profile;
  int samplers;
  int constants;
};

Registers registers_of(ShaderStage stage) {
  return stage == ShaderStage::fragment ? Registers{"ps_3_0", 16, 224}
                                        : Registers{"vs_3_0", 4, 256};
}

std::int64_t array_length(const SpirvModule& m, const SpvInstruction& array) {
  return m.int_constant(array.operand(1)).value_or(1);
}

int count_samplers(const SpirvModule& m) {
  std::int64_t count = 0;
  for (const SpvInstruction& in : m.instructions()) {
    if (in.op != spv::OpVariable || in.operand(0) != spv::StorageClassUniformConstant) continue;
    std::int64_t each = 1;
    const SpvInstruction* type = m.pointee(in.type_id);
    for (; type && type->op == spv::OpTypeArray; type = m.def(type->operand(0))) {
      each *= array_length(m, *type);
    }
    if (type && (type->op == spv::OpTypeSampledImage || type->op == spv::OpTypeSampler)) {
      count += each;
    }
  }
  return static_cast<int>(count);
}

// Bytes a uniform block occupies, from its layout decorations.
class BlockLayout {
 public:
  explicit BlockLayout(const SpirvModule& m) : m_(m) {
    for (const SpvInstruction& in : m.instructions()) {
      if (in.op == spv::OpDecorate && in.operand(1) == spv::DecorationArrayStride) {
        array_stride_[in.operand(0)] = in.operand(2);
      } else if (in.op == spv::OpMemberDecorate && in.operand(2) == spv::DecorationOffset) {
        offset_[{in.operand(0), in.operand(1)}] = in.operand(3);
      }
    }
  }

  std::int64_t bytes(std::uint32_t type_id) const {
    const SpvInstruction* type = m_.def(type_id);
    if (!type) return 0;
    switch (type->op) {
      case spv::OpTypeInt:
      case spv::OpTypeFloat:
        return type->operand(0) / 8;
      case spv::OpTypeVector:
        return type->operand(1) * bytes(type->operand(0));
      case spv::OpTypeMatrix:
        return type->operand(1) * std::int64_t{16};  // a float4 column each (std140)
      case spv::OpTypeArray: {
        const auto stride = array_stride_.find(type_id);
        const std::int64_t each = stride != array_stride_.end()
                                      ? stride->second
                                      : (bytes(type->operand(0)) + 15) / 16 * 16;
        return array_length(m_, *type) * each;
      }
      case spv::OpTypeStruct: {
        std::int64_t end = 0, packed = 0;
        for (std::uint32_t k = 0; k < type->operand_count(); ++k) {
          const auto offset = offset_.find({type_id, k});
          const std::int64_t at = offset != offset_.end() ? offset->second : packed;
          packed = at + bytes(type->operand(k));
          end = std::max(end, packed);
        }
        return end;
      }
      default:
        return 4;  // bool
    }
  }

 private:
  const SpirvModule& m_;
  std::map<std::uint32_t, std::uint32_t> array_stride_;
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> offset_;
};

// float4 registers a `static const` value takes: FXC starts every array
// element, matrix column and struct member on a register of its own.
std::int64_t const_registers(const SpirvModule& m, std::uint32_t type_id) {
  const SpvInstruction* type = m.def(type_id);
  if (!type) return 0;
  switch (type->op) {
    case spv::OpTypeArray:
      return array_length(m, *type) * const_registers(m, type->operand(0));
    case spv::OpTypeMatrix:
      return type->operand(1);
    case spv::OpTypeStruct: {
      std::int64_t sum = 0;
      for (std::size_t k = 0; k < type->operand_count(); ++k) {
        sum += const_registers(m, type->operand(k));
      }
      return sum;
    }
    default:
      return 1;
  }
}

struct ConstantRegisters {
  std::int64_t blocks = 0;  // uniform blocks, at their packoffsets
  std::int64_t arrays = 0;  // SPIRV-Cross's `static const` arrays, which FXC puts in c#
};

ConstantRegisters count_constant_registers(const SpirvModule& m) {
  ConstantRegisters used;
  const BlockLayout layout(m);
  std::set<std::uint32_t> nested;  // constants inside another constant's registers
  for (const SpvInstruction& in : m.instructions()) {
    if (in.op != spv::OpConstantComposite) continue;
    for (std::size_t k = 0; k < in.operand_count(); ++k) nested.insert(in.operand(k));
  }
  for (const SpvInstruction& in : m.instructions()) {
    if (in.op == spv::OpVariable && (in.operand(0) == spv::StorageClassUniform ||
                                     in.operand(0) == spv::StorageClassPushConstant)) {
      const SpvInstruction* block = m.pointee(in.type_id);
      if (block) used.blocks += (layout.bytes(block->result_id) + 15) / 16;
    }
    const SpvInstruction* type = m.def(in.type_id);
    if (in.op == spv::OpConstantComposite && type && type->op == spv::OpTypeArray &&
        !nested.contains(in.result_id)) {
      used.arrays += const_registers(m, in.type_id);
    }
  }
  return used;
}

Status violation(const ShaderJob& job, const std::string& construct, const std::string& why) {
  return make_error(Error::Kind::compile, job.describe(),
                    construct + " is not allowed for hlsl_dx9: " + why);
}

}  // namespace

Status check_dx9_rules(ShaderJob& job, const SpirvModule& module) {
  for (const SpvInstruction& in : module.instructions()) {
    for (const ForbiddenOp& forbidden : kDx9Forbidden) {
      if (in.op == forbidden.op) return violation(job, forbidden.construct, forbidden.why);
    }
  }
  const Registers limits = registers_of(job.stage);
  const std::string profile = limits.profile;
  if (const int samplers = count_samplers(module); samplers > limits.samplers) {
    return violation(job, "using " + std::to_string(samplers) + " samplers",
                     profile + " has " + std::to_string(limits.samplers) +
                         " sampler registers (s0-s" + std::to_string(limits.samplers - 1) + ")");
  }
  const ConstantRegisters constants = count_constant_registers(module);
  if (const std::int64_t total = constants.blocks + constants.arrays; total > limits.constants) {
    return violation(job,
                     "using " + std::to_string(total) + " constant registers (uniform blocks " +
                         std::to_string(constants.blocks) + ", static const arrays " +
                         std::to_string(constants.arrays) + ")",
                     profile + " has " + std::to_string(limits.constants) +
                         " float4 constant registers (c0-c" + std::to_string(limits.constants - 1) +
                         ")");
  }
  return {};
}

}  // namespace penumbra
