// What verify_library() runs, computed from the library and the options
// alone, before any device exists: the (variant, target) pairs of this
// shard in report order, the variant that prepares each target's maps (and
// min-max mips), the paths that run, and the progress total. The executor
// (verify_library.cpp) walks it; tests/verify checks it without a device.
#pragma once

#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "penumbra/library/library.hpp"
#include "penumbra/model/map_encoding.hpp"
#include "penumbra/support/result.hpp"
#include "penumbra/verify/verify.hpp"

namespace penumbra {

// A target's maps in one encoding: drawn by that target's depth pass for it,
// and shared by every variant that reads maps in that encoding.
using MapKey = std::pair<Target, MapEncoding>;

MapKey map_key(const Variant& variant, Target target);

// One (variant, target) this shard runs.
struct PlannedPair {
  Target target = Target::spirv;
  MapKey maps;                     // the scenes' maps it reads
  std::size_t depth_preparer = 0;  // the variant whose depth pass draws them
  std::optional<std::size_t> minmax_preparer =
      {};  // whose min-max passes build the mip; none unused
};

// A variant with its pairs in this shard, in the library's target order.
struct PlannedVariant {
  std::size_t index = 0;  // in Library::variants
  std::vector<PlannedPair> pairs = {};
  bool other_shards = false;  // some of its pairs are in other shards
};

struct VerifyPlan {
  std::vector<PlannedVariant> variants;  // every wanted variant, in library order
  std::vector<std::string> paths;        // the paths whose runs happen, in report order
  // For each target and map encoding, the variant the whole run prepares it
  // with: the first wanted one that has the target and the encoding (and,
  // for the min-max mip, uses it). Every shard prepares with the same one.
  std::map<MapKey, std::size_t> depth_preparers;
  std::map<MapKey, std::size_t> minmax_preparers;
  Shard shard;

  // The pairs in this shard: the progress's total.
  std::size_t pair_count() const;
  bool runs_path(const std::string& name) const;
  // Whether this shard reports the checks of `key`'s maps, or of its
  // min-max mip: the shard that holds the pair that prepares them.
  bool reports_depth(const MapKey& key) const;
  bool reports_minmax(const MapKey& key) const;
};

// The plan for `options` over `library`. Bad input (an unknown variant or
// path, a shard outside 1..N, an empty library) is an error naming it.
Result<VerifyPlan> plan_verify(const Library& library, const VerifyOptions& options);

}  // namespace penumbra
