// VulkanDevice: the pass driver's Device (penumbra/runtime/device.hpp) on an
// Engine's Vulkan context. Every draw is one submission the device waits
// for, timed where the queue writes timestamps. Targets rest in
// SHADER_READ_ONLY_OPTIMAL, ready for the next pass and for readback.
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <vector>

#include "context.hpp"
#include "pass_descriptors.hpp"
#include "penumbra/runtime/device.hpp"
#include "penumbra/vulkan/program.hpp"
#include "shadow_map_images.hpp"
#include "vk/image.hpp"

namespace penumbra::detail {

class VulkanDevice final : public runtime::Device {
 public:
  explicit VulkanDevice(Context& context) : context_(context) {}

  // `program` as the driver's Program; it must outlive the device.
  runtime::Program load(const PassProgram& program);
  // An Engine's map (and, once gathered, its mip) as a Texture; the map must
  // outlive the device. A mip gathered onto it replaces the map's own.
  runtime::Texture adopt(ShadowMapImages& map);
  // The map's min-max mip, when it has one.
  std::optional<runtime::Texture> adopt_mip(ShadowMapImages& map);
  // The map a depth pass drew, handed over to the caller.
  std::unique_ptr<ShadowMapImages> take_map(runtime::Texture map);

  Result<runtime::Texture> upload(TextureId as, const FloatImage& image) override;
  Result<runtime::Drawn> draw(const runtime::Draw& draw) override;
  Result<runtime::Texture> gather_mip(runtime::Texture map,
                                      std::span<const runtime::Texture> levels) override;
  Result<std::vector<FloatImage>> read_all(std::span<const runtime::Texture> textures) override;
  void release(runtime::Texture texture) override;

 private:
  // What a Texture stands for: a map (two images), the mip on a map, or one
  // colour image (uploaded or drawn).
  struct Held {
    ShadowMapImages* map = nullptr;
    std::unique_ptr<ShadowMapImages> owned_map;  // a map this device made
    bool mip = false;                            // `map`'s min-max mip
    std::optional<vk::Image> image;
    std::uint32_t components = 0;
  };

  runtime::Texture hold(Held held, int width, int height);
  Result<FloatImage> read_one(runtime::Texture texture);
  Result<const Held*> find(runtime::Texture texture, std::string_view where) const;
  Status offer(const runtime::Draw& draw, PassResources& resources) const;
  Result<runtime::Drawn> draw_map(const runtime::Draw& draw, const PassProgram& program);
  Result<runtime::Drawn> draw_colour(const runtime::Draw& draw, const PassProgram& program,
                                     PassResources& resources);

  Context& context_;
  std::vector<const PassProgram*> programs_;  // Program::id - 1
  std::map<int, Held> textures_;
  int next_id_ = 1;
};

}  // namespace penumbra::detail
