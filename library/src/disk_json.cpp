#include "penumbra/library/disk_json.hpp"

#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>

namespace penumbra {

// Each float widens to double exactly and nlohmann writes doubles in their
// shortest round-trip form, so reading a value back into float restores its bits.
nlohmann::json disk_points_json(const Disk& disk) {
  nlohmann::json points = nlohmann::json::array();
  for (const Point2& p : disk.points) {
    points.push_back({static_cast<double>(p[0]), static_cast<double>(p[1])});
  }
  return points;
}

nlohmann::json disk_info_json(const Disk& disk) {
  return {{"name", disk.name},
          {"method", disk.method},
          {"seed", disk.seed},
          {"count", disk.points.size()},
          {"normalized_min_distance", disk.normalized_min_distance}};
}

nlohmann::json disk_to_json(const Disk& disk) {
  nlohmann::json out = disk_info_json(disk);
  out["points"] = disk_points_json(disk);
  return out;
}

// "count" is not read: the points are the count.
Disk disk_from_json(const nlohmann::json& points, const nlohmann::json& info) {
  Disk disk;
  disk.name = info.value("name", "");
  disk.method = info.value("method", "");
  // Read wide and narrowed by hand: nlohmann's get<float>() of 1e39, or an
  // unsigned get of 1e300, is undefined behaviour. A coordinate beyond
  // float's range becomes infinite, for the reader's range check to refuse.
  const nlohmann::json seed = info.value("seed", nlohmann::json(0));
  disk.seed = seed.is_number_unsigned() ? seed.get<std::uint64_t>() : 0;
  disk.normalized_min_distance = info.value("normalized_min_distance", 0.0);
  auto coordinate = [](const nlohmann::json& value) {
    const double d = value.get<double>();
    constexpr float kInfinity = std::numeric_limits<float>::infinity();
    if (std::abs(d) <= std::numeric_limits<float>::max()) return static_cast<float>(d);
    return d > 0 ? kInfinity : -kInfinity;
  };
  for (const nlohmann::json& p : points) {
    disk.points.push_back({coordinate(p.at(0)), coordinate(p.at(1))});
  }
  return disk;
}

}  // namespace penumbra
