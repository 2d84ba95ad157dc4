#include "select_variants.hpp"

#include <algorithm>
#include <numeric>

namespace penumbra::cli {
namespace {

std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  std::iota(row.begin(), row.end(), std::size_t{0});
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

std::string join(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& name : names) out += (out.empty() ? "" : ", ") + name;
  return out;
}

// Every name when there are few, else the five closest to `name`.
std::string allowed_variants(const std::vector<Variant>& variants, const std::string& name) {
  constexpr std::size_t kListAll = 12;
  constexpr std::size_t kClosest = 5;
  std::vector<std::string> names;
  for (const Variant& v : variants) names.push_back(v.name);
  if (names.size() <= kListAll) return "allowed: " + join(names);
  // Names holding what was given first (a prefix such as pcss_b16), then by edit distance.
  std::ranges::stable_sort(names, {}, [&](const std::string& n) {
    return std::pair(n.find(name) == std::string::npos, edit_distance(n, name));
  });
  names.resize(kClosest);
  return "closest: " + join(names) + " (penumbra list prints all " +
         std::to_string(variants.size()) + ")";
}

}  // namespace

Result<std::vector<Variant>> select_variants(std::vector<Variant> variants,
                                             const std::vector<std::string>& names,
                                             const std::vector<std::string>& targets,
                                             const std::string& manifest) {
  for (const std::string& name : names) {
    if (std::ranges::none_of(variants, [&](const Variant& v) { return v.name == name; })) {
      return make_error(Error::Kind::bad_input, "--variant " + name,
                        "no such variant in " + manifest + "; " + allowed_variants(variants, name));
    }
  }
  std::vector<Target> wanted;
  for (const std::string& name : targets) {
    const auto target = parse_target(name);
    if (!target) {
      return make_error(Error::Kind::bad_input, "--target " + name,
                        "unknown target; allowed: " + allowed_targets());
    }
    wanted.push_back(*target);
  }
  std::vector<Variant> selected;
  for (Variant& variant : variants) {
    if (!names.empty() && std::ranges::find(names, variant.name) == names.end()) continue;
    if (!wanted.empty()) {
      std::erase_if(variant.targets,
                    [&](Target t) { return std::ranges::find(wanted, t) == wanted.end(); });
    }
    if (!variant.targets.empty()) selected.push_back(std::move(variant));
  }
  if (selected.empty()) {
    std::string where = names.empty() ? "" : "--variant " + join(names);
    if (!targets.empty())
      where += (where.empty() ? "" : " ") + std::string("--target ") + join(targets);
    return make_error(Error::Kind::bad_input, where,
                      "no variant of " + manifest + " is built for the selected targets");
  }
  return selected;
}

}  // namespace penumbra::cli
