#include "select_variants.hpp"

#include <algorithm>
#include <numeric>
#include <optional>
#include <string_view>

#include "penumbra/model/pass.hpp"

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

// The targets or forms named in `names`, parsed by `parse`; errors name
// `flag` and the `allowed` names.
template <typename T, typename Parse>
Result<std::vector<T>> parse_names(const std::vector<std::string>& names, Parse parse,
                                   std::string_view flag, std::string_view what,
                                   const std::string& allowed) {
  std::vector<T> out;
  for (const std::string& name : names) {
    const std::optional<T> value = parse(name);
    if (!value) {
      return make_error(Error::Kind::bad_input, std::string(flag) + " " + name,
                        "unknown " + std::string(what) + "; allowed: " + allowed);
    }
    out.push_back(*value);
  }
  return out;
}

template <typename T>
void keep_wanted(std::vector<T>& values, const std::vector<T>& wanted) {
  if (wanted.empty()) return;
  std::erase_if(values, [&](const T& v) { return std::ranges::find(wanted, v) == wanted.end(); });
}

}  // namespace

Result<std::vector<Variant>> select_variants(std::vector<Variant> variants,
                                             const Selection& selection,
                                             const std::string& manifest) {
  const std::vector<std::string>& names = selection.variants;
  for (const std::string& name : names) {
    if (std::ranges::none_of(variants, [&](const Variant& v) { return v.name == name; })) {
      return make_error(Error::Kind::bad_input, "--variant " + name,
                        "no such variant in " + manifest + "; " + allowed_variants(variants, name));
    }
  }
  PENUMBRA_TRY_ASSIGN(const std::vector<Target> targets,
                      parse_names<Target>(selection.targets, parse_target, "--target", "target",
                                          allowed_targets()));
  PENUMBRA_TRY_ASSIGN(
      const std::vector<Form> forms,
      parse_names<Form>(selection.forms, parse_form, "--form", "form", allowed_forms()));
  std::vector<Variant> selected;
  for (Variant& variant : variants) {
    if (!names.empty() && std::ranges::find(names, variant.name) == names.end()) continue;
    keep_wanted(variant.targets, targets);
    keep_wanted(variant.forms, forms);
    if (!variant.targets.empty() && !variant.forms.empty()) selected.push_back(std::move(variant));
  }
  if (selected.empty()) {
    std::string where = names.empty() ? "" : "--variant " + join(names);
    const auto add = [&](std::string_view flag, const std::vector<std::string>& values) {
      if (!values.empty())
        where += (where.empty() ? "" : " ") + std::string(flag) + " " + join(values);
    };
    add("--target", selection.targets);
    add("--form", selection.forms);
    return make_error(Error::Kind::bad_input, where,
                      "no variant of " + manifest + " is built for the selected targets and forms");
  }
  return selected;
}

}  // namespace penumbra::cli
