#include "vk/instance.hpp"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <string>

#include "vk/check.hpp"

namespace penumbra::vk {
namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

// Both the loader without drivers and a driver that refuses the instance end
// here; the usual cause on Debian is a missing mesa-vulkan-drivers package.
Error no_device_error(const char* call) {
  const char* icd_files = std::getenv("VK_ICD_FILENAMES");
  return make_error(Error::Kind::device, call,
                    std::string("no Vulkan device found (is mesa-vulkan-drivers installed? "
                                "VK_ICD_FILENAMES=") +
                        (icd_files ? icd_files : "<unset>") + ")");
}

bool validation_layer_present() {
  std::uint32_t count = 0;
  if (vkEnumerateInstanceLayerProperties(&count, nullptr) != VK_SUCCESS) return false;
  std::vector<VkLayerProperties> layers(count);
  if (vkEnumerateInstanceLayerProperties(&count, layers.data()) != VK_SUCCESS) return false;
  return std::any_of(layers.begin(), layers.end(), [](const VkLayerProperties& layer) {
    return std::strcmp(layer.layerName, kValidationLayer) == 0;
  });
}

}  // namespace

Result<std::shared_ptr<const Instance>> Instance::create(bool validation,
                                                         const DiagnosticConsumer& diagnostics) {
  const bool enable_validation = validation && validation_layer_present();
  if (validation && !enable_validation) {
    diagnostics({Severity::warning, "vulkan",
                 std::string(kValidationLayer) +
                     " is not installed (Debian: vulkan-validationlayers); running without it"});
  }

  VkApplicationInfo app{};
  app.sType = VK_STRUCTURE_TYPE_APPLICATION_INFO;
  app.pApplicationName = "penumbra";
  app.pEngineName = "penumbra";
  app.apiVersion = kApiVersion;

  const char* layers[] = {kValidationLayer};
  const char* extensions[] = {VK_EXT_DEBUG_UTILS_EXTENSION_NAME};
  VkInstanceCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO;
  info.pApplicationInfo = &app;
  if (enable_validation) {
    // The validation layer implements VK_EXT_debug_utils itself.
    info.enabledLayerCount = 1;
    info.ppEnabledLayerNames = layers;
    info.enabledExtensionCount = 1;
    info.ppEnabledExtensionNames = extensions;
  }

  VkInstance instance = VK_NULL_HANDLE;
  const VkResult result = vkCreateInstance(&info, nullptr, &instance);
  if (result == VK_ERROR_INCOMPATIBLE_DRIVER) return no_device_error("vkCreateInstance");
  PENUMBRA_TRY(check(result, "vkCreateInstance", "creating the Vulkan instance"));
  return std::shared_ptr<const Instance>(new Instance(instance, enable_validation));
}

Instance::~Instance() {
  vkDestroyInstance(instance_, nullptr);
}

Result<std::vector<VkPhysicalDevice>> Instance::physical_devices() const {
  std::uint32_t count = 0;
  PENUMBRA_TRY(check(vkEnumeratePhysicalDevices(instance_, &count, nullptr),
                     "vkEnumeratePhysicalDevices", "counting the Vulkan devices"));
  if (count == 0) return no_device_error("vkEnumeratePhysicalDevices");
  std::vector<VkPhysicalDevice> devices(count);
  PENUMBRA_TRY(check(vkEnumeratePhysicalDevices(instance_, &count, devices.data()),
                     "vkEnumeratePhysicalDevices", "listing the Vulkan devices"));
  devices.resize(count);
  return devices;
}

}  // namespace penumbra::vk
