// A Poisson disk as index.json and `penumbra disk` write it, and read back.
#pragma once

#include <nlohmann/json_fwd.hpp>

#include "penumbra/model/model.hpp"

namespace penumbra {

// {"name", "method", "seed", "count", "normalized_min_distance", "points"};
// points are [x, y] pairs that read back into float with the same bits.
nlohmann::json disk_to_json(const Disk& disk);
// The two halves of that object: the bare array of points, and everything
// else.
nlohmann::json disk_points_json(const Disk& disk);
nlohmann::json disk_info_json(const Disk& disk);
// The disk back from those halves (index.json's `disks` table passes a record
// and its `points`); a member missing from `info` stays at its default. Throws
// nlohmann::json::exception on a malformed point.
Disk disk_from_json(const nlohmann::json& points, const nlohmann::json& info);

}  // namespace penumbra
