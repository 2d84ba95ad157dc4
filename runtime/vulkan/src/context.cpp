#include "context.hpp"

#include <string>
#include <utility>

#include "device_selection.hpp"
#include "formats.hpp"

namespace penumbra::detail {
namespace {

DeviceInfo describe(const vk::Device& device) {
  const VkPhysicalDeviceProperties& properties = device.properties();
  DeviceInfo info;
  info.name = properties.deviceName;
  info.api_version = properties.apiVersion;
  info.sub_texel_precision_bits = properties.limits.subTexelPrecisionBits;
  // Driver properties are core from Vulkan 1.2; older devices report none.
  if (device.api_version() >= VK_API_VERSION_1_2) {
    VkPhysicalDeviceDriverProperties driver{};
    driver.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES;
    VkPhysicalDeviceProperties2 properties2{};
    properties2.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2;
    properties2.pNext = &driver;
    vkGetPhysicalDeviceProperties2(device.physical(), &properties2);
    info.driver = std::string(driver.driverName) + " (" + driver.driverInfo + ")";
  } else {
    info.driver = "unknown (Vulkan 1.1 or older)";
  }
  return info;
}

}  // namespace

Status Context::check_extent(int width, int height, std::string_view what) const {
  const auto limit = static_cast<int>(device->properties().limits.maxImageDimension2D);
  if (width >= 1 && height >= 1 && width <= limit && height <= limit) return {};
  return make_error(Error::Kind::bad_input, std::string(what),
                    "size " + std::to_string(width) + "x" + std::to_string(height) +
                        " is out of range; each side must be 1.." + std::to_string(limit) + " on " +
                        info.name);
}

Result<std::unique_ptr<Context>> create_context(const EngineOptions& options,
                                                DiagnosticConsumer diagnostics) {
  auto context = std::make_unique<Context>();
  context->diagnostics = std::move(diagnostics);
  context->validation = std::make_unique<ValidationLog>(context->diagnostics);

  auto instance = vk::Instance::create(options.validation, context->diagnostics);
  if (!instance) return instance.error();
  context->instance = std::move(*instance);
  if (context->instance->validation_enabled()) {
    ValidationLog* log = context->validation.get();
    auto messenger = vk::DebugMessenger::create(
        context->instance->get(),
        [log](Severity severity, const std::string& message) { log->report(severity, message); });
    if (!messenger) return messenger.error();
    context->messenger.emplace(std::move(*messenger));
  }

  auto physical_devices = context->instance->physical_devices();
  if (!physical_devices) return physical_devices.error();
  auto physical = select_physical_device(*physical_devices, options.device);
  if (!physical) return physical.error();
  auto device = vk::Device::create(context->instance, *physical);
  if (!device) return device.error();
  context->device = std::move(*device);
  context->info = describe(*context->device);
  PENUMBRA_TRY(check_format_support(*context->device));

  auto commands = vk::CommandContext::create(*context->device);
  if (!commands) return commands.error();
  context->commands.emplace(std::move(*commands));
  auto timestamps = vk::TimestampQueries::create(*context->device);
  if (!timestamps) return timestamps.error();
  context->timestamps = std::move(*timestamps);

  context->diagnostics({Severity::note, "vulkan",
                        "using " + context->info.name + ", driver " + context->info.driver});
  return context;
}

}  // namespace penumbra::detail
