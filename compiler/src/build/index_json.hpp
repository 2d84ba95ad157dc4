// OUT/index.json (docs/shader-interface.md): written from one resolved
// record per variant, by a build (from its jobs) or by a merge (from parts'
// index.json), through the same IndexWriter, so both give the same bytes.
#pragma once

#include <map>
#include <nlohmann/json.hpp>
#include <span>
#include <string>
#include <vector>

#include "penumbra/compiler/stage.hpp"

namespace penumbra {

nlohmann::json variant_keys_json(const VariantKeys& keys);

// A variant's record with nothing shared: `disks`, `passes` and `reflection`
// hold their records themselves instead of positions in index.json's
// top-level tables (a constant texture's `contents` is its texels, from a
// build, or the disk it holds, from an index.json).
using ResolvedVariant = nlohmann::json;

// The finished jobs of a build, found by what they are.
class JobTable {
 public:
  explicit JobTable(const std::vector<ShaderJob>& jobs);
  // The job that made `stage` of `pass` for `target`: the variant's own, or
  // the shared one when the pass is shared.
  const ShaderJob* find(const Variant& variant, Target target, PassKind pass,
                        ShaderStage stage) const;
  // The job that made `variant`'s function form for `target`, if any.
  const ShaderJob* function(const Variant& variant, Target target) const;

 private:
  using Key = std::tuple<const Variant*, Target, PassKind, ShaderStage, MapEncoding, ShaderForm>;
  std::map<Key, const ShaderJob*> jobs_;
};

ResolvedVariant resolve_variant(const Variant& variant, const JobTable& jobs);

// The resolved record of index.json's variant `i` (a parsed index of
// kIndexSchema, as load_library checks it).
ResolvedVariant resolve_variant(const nlohmann::json& index, std::size_t i);

// Builds index.json from resolved variants, in library order: each
// distinct shared record once, in the order variants first use it.
class IndexWriter {
 public:
  IndexWriter();
  ~IndexWriter();
  void add(const ResolvedVariant& variant);
  // index.json's text: each top-level member on a line of its own, and each
  // record of a top-level array (a variant, a reflection record, a disk) on
  // one line (one variant a line: grep finds it). Indenting every nested
  // member, as dump(2) does, made over half of the file whitespace.
  std::string finish();

 private:
  struct Tables;
  // Replaces a reflection record with its position in `reflections`, its
  // constant textures' contents with the variant's disk they hold
  // ({"disk": "pcf"}), so that records differing only in disks are one.
  void share_record(nlohmann::json& record);

  std::unique_ptr<Tables> tables_;
  std::vector<std::string> variants_;  // each record's text
};

}  // namespace penumbra
