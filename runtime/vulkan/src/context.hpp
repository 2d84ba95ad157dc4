// Context: everything an Engine owns on its device, shared by the passes.
#pragma once

#include <memory>
#include <optional>
#include <string_view>

#include "penumbra/vulkan/engine.hpp"
#include "validation_log.hpp"
#include "vk/command_context.hpp"
#include "vk/debug_messenger.hpp"
#include "vk/device.hpp"
#include "vk/instance.hpp"
#include "vk/timestamp_queries.hpp"

namespace penumbra::detail {

// Members are destroyed bottom-up: device objects before the device, the
// messenger before the instance, the log after the messenger writing to it.
struct Context {
  DiagnosticConsumer diagnostics;
  std::unique_ptr<ValidationLog> validation;  // on the heap: the messenger holds its address
  std::shared_ptr<const vk::Instance> instance;
  std::optional<vk::DebugMessenger> messenger;
  std::shared_ptr<const vk::Device> device;  // shared with every ShadowMap
  DeviceInfo info;
  std::optional<vk::CommandContext> commands;
  std::optional<vk::TimestampQueries> timestamps;  // none when the queue writes no timestamps

  // A bad_input Error unless 1 <= width, height <= maxImageDimension2D.
  Status check_extent(int width, int height, std::string_view what) const;
};

// Creates the instance, selects and opens the device, checks its formats.
Result<std::unique_ptr<Context>> create_context(const EngineOptions& options,
                                                DiagnosticConsumer diagnostics);

}  // namespace penumbra::detail
