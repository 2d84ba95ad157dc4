#include <nlohmann/json.hpp>

#include "penumbra/compiler/disk.hpp"

namespace penumbra {

// Each float widens to double exactly and nlohmann writes doubles in their
// shortest round-trip form, so reading a value back into float restores its bits.
nlohmann::json disk_to_json(const Disk& disk) {
  nlohmann::json points = nlohmann::json::array();
  for (const Point2& p : disk.points) {
    points.push_back({static_cast<double>(p[0]), static_cast<double>(p[1])});
  }
  return {{"name", disk.name},
          {"method", disk.method},
          {"seed", disk.seed},
          {"count", disk.points.size()},
          {"normalized_min_distance", disk.normalized_min_distance},
          {"points", std::move(points)}};
}

}  // namespace penumbra
