#include "verify_plan.hpp"

#include <algorithm>

#include "penumbra/model/model.hpp"
#include "penumbra/verify/paths.hpp"

namespace penumbra {
namespace {

bool wanted(const std::vector<std::string>& names, const std::string& name) {
  return names.empty() || std::ranges::find(names, name) != names.end();
}

bool wanted(const std::vector<Target>& targets, Target target) {
  return targets.empty() || std::ranges::find(targets, target) != targets.end();
}

// (i + j) mod N spreads both ways: a variant's targets over the shards, and
// a target's variants (one technique's costly reference is not all in one
// shard; nor is one target's bytecode or GL path).
bool in_shard(const Shard& shard, std::size_t variant_index, Target target) {
  const auto j =
      static_cast<std::size_t>(std::ranges::find(kAllTargets, target) - kAllTargets.begin());
  return (variant_index + j) % static_cast<std::size_t>(shard.count) ==
         static_cast<std::size_t>(shard.index - 1);
}

Status check_options(const Library& library, const VerifyOptions& options) {
  if (library.variants.empty()) {
    return make_error(Error::Kind::bad_input, library.root.string(), "the library has no variants");
  }
  for (const std::string& name : options.variants) {
    if (!library.find(name)) {
      return make_error(Error::Kind::bad_input, name,
                        "no such variant in " + library.root.string());
    }
  }
  for (const auto& [kind, names] :
       {std::pair{"path ", &options.paths}, std::pair{"skipped path ", &options.skipped}}) {
    for (const std::string& path : *names) {
      if (!is_path_name(path)) {
        return make_error(Error::Kind::bad_input, kind + path,
                          "no such execution path; allowed: " + path_names());
      }
    }
  }
  if (options.shard.count < 1 || options.shard.index < 1 ||
      options.shard.index > options.shard.count) {
    return make_error(Error::Kind::bad_input, "shard " + to_string(options.shard),
                      "I must be in 1..N");
  }
  return {};
}

// The first wanted variant of each target and encoding (and of the min-max
// ones): found over the whole library, so every shard agrees.
void find_preparers(const Library& library, const VerifyOptions& options, VerifyPlan& plan) {
  for (std::size_t i = 0; i < library.variants.size(); ++i) {
    const Variant& variant = library.variants[i].variant;
    if (!wanted(options.variants, variant.name)) continue;
    for (Target target : variant.targets) {
      if (!wanted(options.targets, target)) continue;
      plan.depth_preparers.emplace(map_key(variant, target), i);
      if (uses_minmax_mip(variant.technique)) {
        plan.minmax_preparers.emplace(map_key(variant, target), i);
      }
    }
  }
}

}  // namespace

MapKey map_key(const Variant& variant, Target target) {
  return {target, map_encoding(variant.keys)};
}

std::size_t VerifyPlan::pair_count() const {
  std::size_t count = 0;
  for (const PlannedVariant& variant : variants) count += variant.pairs.size();
  return count;
}

bool VerifyPlan::runs_path(const std::string& name) const {
  return std::ranges::find(paths, name) != paths.end();
}

bool VerifyPlan::reports_depth(const MapKey& key) const {
  return in_shard(shard, depth_preparers.at(key), key.first);
}

bool VerifyPlan::reports_minmax(const MapKey& key) const {
  return in_shard(shard, minmax_preparers.at(key), key.first);
}

Result<VerifyPlan> plan_verify(const Library& library, const VerifyOptions& options) {
  PENUMBRA_TRY(check_options(library, options));
  VerifyPlan plan;
  plan.shard = options.shard;
  for (const ExecutionPath& path : execution_paths()) {
    if (wanted(options.paths, std::string(path.name))) plan.paths.emplace_back(path.name);
  }
  find_preparers(library, options, plan);
  for (std::size_t i = 0; i < library.variants.size(); ++i) {
    const Variant& variant = library.variants[i].variant;
    if (!wanted(options.variants, variant.name)) continue;
    PlannedVariant& planned = plan.variants.emplace_back(PlannedVariant{.index = i});
    for (Target target : variant.targets) {
      if (!wanted(options.targets, target)) continue;
      if (!in_shard(options.shard, i, target)) {
        planned.other_shards = true;
        continue;
      }
      const MapKey key = map_key(variant, target);
      PlannedPair pair{
          .target = target, .maps = key, .depth_preparer = plan.depth_preparers.at(key)};
      if (uses_minmax_mip(variant.technique)) pair.minmax_preparer = plan.minmax_preparers.at(key);
      planned.pairs.push_back(pair);
    }
  }
  return plan;
}

}  // namespace penumbra
