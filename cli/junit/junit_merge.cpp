// A merge that passes must mean the whole run passed: a shard missing (its
// job died before writing), given twice, or run against another split would
// otherwise leave checks out, or count them twice, without a trace.
#include <map>
#include <optional>

#include "junit.hpp"

namespace penumbra::cli {
namespace {

Error bad(const std::string& where, const std::string& message) {
  return make_error(Error::Kind::bad_input, where, message);
}

// The one shard all of `report`'s suites name.
Result<Shard> shard_of(const std::string& file, const JunitReport& report) {
  std::optional<Shard> shard;
  for (const JunitSuite& suite : report.suites) {
    const std::string* value = suite.property(kJunitShardProperty);
    if (!value) continue;
    auto parsed = parse_shard(*value, "property " + std::string(kJunitShardProperty));
    if (!parsed) return bad(file, parsed.error().to_string());
    if (shard && *shard != *parsed) {
      return bad(file, "suites of shards " + to_string(*shard) + " and " + to_string(*parsed) +
                           "; allowed: one shard per file");
    }
    shard = *parsed;
  }
  if (!shard) {
    return bad(file, "no <property name=\"" + std::string(kJunitShardProperty) +
                         "\">; allowed: reports written by penumbra verify --junit");
  }
  return *shard;
}

}  // namespace

Result<JunitReport> merge_junit_shards(
    const std::vector<std::pair<std::string, JunitReport>>& reports) {
  if (reports.empty()) return bad("junit-merge", "no reports to merge");
  std::map<int, std::size_t> by_index;  // shard index -> position in `reports`
  std::optional<Shard> first;
  for (std::size_t i = 0; i < reports.size(); ++i) {
    const auto& [file, report] = reports[i];
    auto shard = shard_of(file, report);
    if (!shard) return shard.error();
    if (first && shard->count != first->count) {
      return bad(file, "shard " + to_string(*shard) + " but " + reports.front().first +
                           " is shard " + to_string(*first) + "; allowed: shards of one N");
    }
    if (!first) first = *shard;
    if (auto [at, added] = by_index.emplace(shard->index, i); !added) {
      return bad(file, "shard " + to_string(*shard) + " is also in " + reports[at->second].first +
                           "; allowed: each shard once");
    }
  }
  if (by_index.size() != static_cast<std::size_t>(first->count)) {
    std::string missing;
    for (int index = 1; index <= first->count; ++index) {
      if (by_index.contains(index)) continue;
      missing += (missing.empty() ? "" : ", ") + to_string({index, first->count});
    }
    return bad("junit-merge", "missing shard " + missing + "; allowed: every shard 1.." +
                                  std::to_string(first->count) + " of the run, each once");
  }
  JunitReport merged;
  std::map<std::pair<std::string, std::string>, const std::string*> owner;  // testcase -> file
  for (const auto& [index, position] : by_index) {
    const auto& [file, report] = reports[position];
    if (merged.name.empty()) merged.name = report.name;
    for (const JunitSuite& suite : report.suites) {
      for (const JunitCase& c : suite.cases) {
        auto [at, added] = owner.emplace(std::pair(c.classname, c.name), &file);
        if (!added) {
          return bad(file, "testcase " + c.classname + " " + c.name + " is also in " + *at->second +
                               "; allowed: shards that do not overlap");
        }
      }
      merged.suites.push_back(suite);
    }
  }
  return merged;
}

}  // namespace penumbra::cli
