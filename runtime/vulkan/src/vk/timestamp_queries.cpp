#include "vk/timestamp_queries.hpp"

#include <cstdint>
#include <utility>

#include "vk/check.hpp"

namespace penumbra::vk {

Result<std::optional<TimestampQueries>> TimestampQueries::create(const Device& device) {
  const float period = device.properties().limits.timestampPeriod;
  if (device.timestamp_valid_bits() == 0 || !(period > 0.0f)) {
    return std::optional<TimestampQueries>();
  }
  VkQueryPoolCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO;
  info.queryType = VK_QUERY_TYPE_TIMESTAMP;
  info.queryCount = 2;
  VkQueryPool pool = VK_NULL_HANDLE;
  PENUMBRA_TRY(check(vkCreateQueryPool(device.get(), &info, nullptr, &pool), "vkCreateQueryPool",
                     "creating the timestamp query pool"));
  return std::optional<TimestampQueries>(TimestampQueries(
      device.get(), DeviceObject<VkQueryPool, vkDestroyQueryPool>(device.get(), pool),
      device.timestamp_valid_bits(), period));
}

TimestampQueries::TimestampQueries(VkDevice device,
                                   DeviceObject<VkQueryPool, vkDestroyQueryPool> pool,
                                   std::uint32_t valid_bits, float period_ns)
    : device_(device), pool_(std::move(pool)), valid_bits_(valid_bits), period_ns_(period_ns) {}

void TimestampQueries::begin(VkCommandBuffer commands) const {
  // Queries must be reset before each use; in the command buffer, so the
  // pool needs no host reset (a Vulkan 1.2 feature).
  vkCmdResetQueryPool(commands, pool_.get(), 0, 2);
  vkCmdWriteTimestamp(commands, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, pool_.get(), 0);
}

void TimestampQueries::end(VkCommandBuffer commands) const {
  vkCmdWriteTimestamp(commands, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, pool_.get(), 1);
}

Result<double> TimestampQueries::elapsed_ms() const {
  std::uint64_t ticks[2] = {0, 0};
  PENUMBRA_TRY(check(
      vkGetQueryPoolResults(device_, pool_.get(), 0, 2, sizeof(ticks), ticks, sizeof(std::uint64_t),
                            VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT),
      "vkGetQueryPoolResults", "reading the timestamps"));
  // Only the low timestampValidBits bits count; the difference wraps with them.
  const std::uint64_t mask =
      valid_bits_ >= 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << valid_bits_) - 1;
  const std::uint64_t delta = (ticks[1] - ticks[0]) & mask;
  return static_cast<double>(delta) * static_cast<double>(period_ns_) * 1e-6;
}

}  // namespace penumbra::vk
