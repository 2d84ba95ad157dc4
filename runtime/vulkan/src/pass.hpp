// One draw of a pass program into a render target: what the depth pass and
// the query pass share, from reflection to the finished submission.
#pragma once

#include <vulkan/vulkan.h>

#include <span>

#include "context.hpp"
#include "pass_descriptors.hpp"
#include "pass_pipeline.hpp"
#include "vk/image.hpp"

namespace penumbra::detail {

// The images a pass draws into (all attachments are cleared to 1.0 first),
// the layouts it leaves them in, and where they are used next.
struct PassTarget {
  const vk::Image* colour = nullptr;  // single-level, output location 0
  VkImageLayout colour_final = VK_IMAGE_LAYOUT_UNDEFINED;
  const vk::Image* depth = nullptr;  // D32_SFLOAT or none
  VkImageLayout depth_final = VK_IMAGE_LAYOUT_UNDEFINED;
  VkPipelineStageFlags next_stages = 0;
  VkAccessFlags next_access = 0;
};

struct PassDraw {
  const PassProgram* program = nullptr;
  PassShape shape;
  PassResources resources;
  std::span<const float> positions;  // shape.position_components floats per vertex
  PassTarget target;
};

// A colour target that the next pass samples and a transfer may copy or read
// back: left in SHADER_READ_ONLY_OPTIMAL (the min-max levels, a chain's
// screen buffers).
PassTarget sampled_target(const vk::Image& colour);

// Binds the program's resources by reflection, draws the positions as a
// triangle list over the whole target (through a flipped viewport for a
// program with d3d_viewport), and waits for the result. Returns the render
// pass's GPU time when the context has timestamp queries, else nullopt.
Result<std::optional<double>> draw_pass(Context& context, const PassDraw& draw);

// `total` plus `elapsed`: a sum of pass times that stays absent while no pass
// was timed.
void add_gpu_time(std::optional<double>& total, std::optional<double> elapsed);

}  // namespace penumbra::detail
