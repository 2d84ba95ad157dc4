// DeviceObject: owns one Vulkan handle made from a VkDevice and destroys it
// with its vkDestroy*/vkFree* function. Move-only; the base of every wrapper.
#pragma once

#include <vulkan/vulkan.h>

#include <utility>

namespace penumbra::vk {

template <typename Handle>
using DestroyFunction = void (*)(VkDevice, Handle, const VkAllocationCallbacks*);

template <typename Handle, DestroyFunction<Handle> Destroy>
class DeviceObject {
 public:
  DeviceObject() = default;
  DeviceObject(VkDevice device, Handle handle) : device_(device), handle_(handle) {}
  DeviceObject(DeviceObject&& other) noexcept
      : device_(other.device_), handle_(std::exchange(other.handle_, VK_NULL_HANDLE)) {}
  DeviceObject& operator=(DeviceObject&& other) noexcept {
    if (this != &other) {
      reset();
      device_ = other.device_;
      handle_ = std::exchange(other.handle_, VK_NULL_HANDLE);
    }
    return *this;
  }
  DeviceObject(const DeviceObject&) = delete;
  DeviceObject& operator=(const DeviceObject&) = delete;
  ~DeviceObject() { reset(); }

  Handle get() const { return handle_; }

 private:
  void reset() {
    if (handle_ != VK_NULL_HANDLE) Destroy(device_, handle_, nullptr);
    handle_ = VK_NULL_HANDLE;
  }

  VkDevice device_ = VK_NULL_HANDLE;
  Handle handle_ = VK_NULL_HANDLE;
};

}  // namespace penumbra::vk
