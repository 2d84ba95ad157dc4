#include "pass.hpp"

#include <cstring>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "formats.hpp"
#include "vk/buffer.hpp"
#include "vk/framebuffer.hpp"
#include "vk/render_pass.hpp"

namespace penumbra::detail {
namespace {

vk::RenderPassDesc render_pass_desc(const PassTarget& target) {
  vk::RenderPassDesc desc;
  desc.colour = {target.colour->desc().format, target.colour_final};
  if (target.depth) {
    desc.depth = vk::AttachmentDesc{target.depth->desc().format, target.depth_final};
  }
  desc.next_stages = target.next_stages;
  desc.next_access = target.next_access;
  return desc;
}

Result<std::optional<vk::Buffer>> create_vertices(const vk::Device& device,
                                                  std::span<const float> positions) {
  // A buffer cannot be empty; a pass without vertices only clears its target.
  if (positions.empty()) return std::optional<vk::Buffer>();
  auto buffer = vk::Buffer::create(device, positions.size_bytes(),
                                   VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, "the vertex buffer");
  if (!buffer) return buffer.error();
  std::memcpy(buffer->bytes().data(), positions.data(), positions.size_bytes());
  return std::optional<vk::Buffer>(std::move(*buffer));
}

// Vulkan's framebuffer y grows with the row index, so with y = 0 and a
// positive height clip y = -1 lands on row 0, docs/shader-interface.md's v = 0. A vertex
// stage written for Direct3D's viewport (y up) negates clip y; a negative
// height, anchored at the bottom edge, negates it back.
VkViewport pass_viewport(VkExtent2D extent, bool d3d_viewport) {
  const auto width = static_cast<float>(extent.width);
  const auto height = static_cast<float>(extent.height);
  if (d3d_viewport) return {0.0f, height, width, -height, 0.0f, 1.0f};
  return {0.0f, 0.0f, width, height, 0.0f, 1.0f};
}

// A negative viewport height is core in Vulkan 1.1; before that it needs
// VK_KHR_maintenance1, which the runtime does not enable.
Status check_viewport_support(const Context& context, const PassDraw& draw) {
  if (draw.program->gl_clip_depth && !context.device->depth_clip_control()) {
    return make_error(Error::Kind::device, std::string(draw.shape.name),
                      "the program writes OpenGL clip-space depth (gl_clip_depth), which needs "
                      "VK_EXT_depth_clip_control; " +
                          context.info.name + " does not offer it");
  }
  if (!draw.program->d3d_viewport || context.device->api_version() >= VK_API_VERSION_1_1) {
    return {};
  }
  return make_error(Error::Kind::device, std::string(draw.shape.name),
                    "the program asks for a Direct3D viewport (d3d_viewport), which needs a "
                    "negative viewport height: Vulkan 1.1, and " +
                        context.info.name + " offers Vulkan 1.0");
}

Error io_error(const PassDraw& draw, std::string message) {
  return make_error(Error::Kind::bad_input, std::string(draw.shape.name), std::move(message));
}

// The vertex input and the targets the reflection describes are the ones
// the pass creates.
Status check_reflected_io(const PassDraw& draw) {
  const PassReflection& reflection = draw.program->reflection;
  const std::string pass(draw.shape.name);
  const std::uint32_t components = draw.shape.position_components;
  const auto& inputs = reflection.vertex_inputs;
  if (inputs.size() != 1 || inputs[0].components != components ||
      inputs[0].location.value_or(0) != 0) {
    std::string given;
    for (const VertexAttribute& input : inputs) {
      given += (given.empty() ? "" : ", ") + input.name + " (" + std::to_string(input.components) +
               " floats)";
    }
    return io_error(draw, "index.json's reflection gives the vertex inputs " +
                              (given.empty() ? std::string("none") : given) + "; the " + pass +
                              " supplies position (" + std::to_string(components) +
                              " floats) at location 0");
  }
  const auto& targets = reflection.render_targets;
  const VkFormat colour = draw.target.colour->desc().format;
  const std::string drawn = std::string(api_name(draw.program->target, colour));
  if (targets.size() != 1 || targets[0].index != 0) {
    return io_error(draw, "index.json's reflection gives " + std::to_string(targets.size()) +
                              " render targets; the " + pass + " draws into one " + drawn +
                              " target, index 0");
  }
  TextureFormat format{};
  PENUMBRA_TRY_ASSIGN(format, reflected_format(draw.program->target, targets[0].format, pass));
  if (vk_format(format) != colour) {
    return io_error(draw, "index.json's reflection gives render target '" + targets[0].name +
                              "' the format " + targets[0].format + "; the " + pass +
                              " draws into " + drawn);
  }
  if (reflection.depth_target.empty() == (draw.target.depth != nullptr)) {
    return io_error(draw,
                    std::string("index.json's reflection ") +
                        (draw.target.depth ? "gives no depth target; the " + pass + " writes one"
                                           : "gives a depth target; the " + pass + " writes none"));
  }
  return {};
}

void record_draw(VkCommandBuffer cmd, const PassDraw& draw, VkRenderPass render_pass,
                 VkFramebuffer framebuffer, const PassPipeline& pipeline,
                 const PassDescriptors& descriptors, const std::optional<vk::Buffer>& vertices,
                 const vk::TimestampQueries* timer) {
  const VkExtent2D extent = draw.target.colour->extent();
  // The far plane, in the map's depth (reversed-Z: 0).
  const float far = draw.shape.depth_greater ? 0.0f : 1.0f;
  VkClearValue clears[2]{};
  clears[0].color.float32[0] = far;
  clears[1].depthStencil.depth = far;
  VkRenderPassBeginInfo begin{};
  begin.sType = VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO;
  begin.renderPass = render_pass;
  begin.framebuffer = framebuffer;
  begin.renderArea = {{0, 0}, extent};
  begin.clearValueCount = draw.target.depth ? 2 : 1;
  begin.pClearValues = clears;
  if (timer) timer->begin(cmd);
  vkCmdBeginRenderPass(cmd, &begin, VK_SUBPASS_CONTENTS_INLINE);
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline.get());
  const auto& sets = descriptors.sets();
  if (!sets.empty()) {
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline.layout(), 0,
                            static_cast<std::uint32_t>(sets.size()), sets.data(), 0, nullptr);
  }
  const VkViewport viewport = pass_viewport(extent, draw.program->d3d_viewport);
  const VkRect2D scissor{{0, 0}, extent};
  vkCmdSetViewport(cmd, 0, 1, &viewport);
  vkCmdSetScissor(cmd, 0, 1, &scissor);
  if (vertices) {
    const VkBuffer buffer = vertices->get();
    const VkDeviceSize offset = 0;
    vkCmdBindVertexBuffers(cmd, 0, 1, &buffer, &offset);
    const auto count =
        static_cast<std::uint32_t>(draw.positions.size() / draw.shape.position_components);
    vkCmdDraw(cmd, count, 1, 0, 0);
  }
  vkCmdEndRenderPass(cmd);
  if (timer) timer->end(cmd);
}

}  // namespace

PassTarget sampled_target(const vk::Image& colour) {
  PassTarget target;
  target.colour = &colour;
  target.colour_final = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
  target.next_stages = VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT;
  target.next_access = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_TRANSFER_READ_BIT;
  return target;
}

void add_gpu_time(std::optional<double>& total, std::optional<double> elapsed) {
  if (elapsed) total = total.value_or(0.0) + *elapsed;
}

Result<std::optional<double>> draw_pass(Context& context, const PassDraw& draw) {
  PENUMBRA_TRY(check_viewport_support(context, draw));
  const VkDevice device = context.device->get();
  PENUMBRA_TRY(check_reflected_io(draw));
  auto plan = plan_bindings(*draw.program, draw.shape.name);
  if (!plan) return plan.error();

  auto render_pass = vk::create_render_pass(device, render_pass_desc(draw.target));
  if (!render_pass) return render_pass.error();
  std::vector<VkImageView> views{draw.target.colour->view()};
  if (draw.target.depth) views.push_back(draw.target.depth->view());
  auto framebuffer =
      vk::create_framebuffer(device, render_pass->get(), views, draw.target.colour->extent());
  if (!framebuffer) return framebuffer.error();

  auto pipeline =
      PassPipeline::create(device, *draw.program, *plan, draw.shape, render_pass->get(),
                           context.device->properties().deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU);
  if (!pipeline) return pipeline.error();
  auto descriptors = PassDescriptors::create(context, *plan, *pipeline, draw.resources,
                                             draw.program->target, draw.shape.name);
  if (!descriptors) return descriptors.error();
  auto vertices = create_vertices(*context.device, draw.positions);
  if (!vertices) return vertices.error();

  const vk::TimestampQueries* timer = context.timestamps ? &*context.timestamps : nullptr;
  PENUMBRA_TRY(context.commands->submit(
      [&](VkCommandBuffer cmd) {
        record_draw(cmd, draw, render_pass->get(), framebuffer->get(), *pipeline, *descriptors,
                    *vertices, timer);
      },
      "the " + std::string(draw.shape.name)));
  if (!timer) return std::optional<double>();
  auto ms = timer->elapsed_ms();
  if (!ms) return ms.error();
  return std::optional<double>(*ms);
}

}  // namespace penumbra::detail
