// Every manifest error names the file and the JSON path, and says what is allowed.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "penumbra/compiler/manifest.hpp"

namespace penumbra {
namespace {

// The error of parsing and expanding `json` as "perms.json".
Error manifest_error(std::string_view json) {
  Result<Manifest> manifest = parse_manifest(json, "perms.json");
  if (!manifest) return manifest.error();
  Result<std::vector<Variant>> variants = expand(*manifest);
  if (!variants) return variants.error();
  ADD_FAILURE() << "expected an error for " << json;
  return {};
}

// A manifest whose only set is `set`.
std::string with_set(std::string_view set) {
  return R"({"schema": 1, "disks": {"poisson": {}}, "sets": [{"technique": "hard"}, )" +
         std::string(set) + "]}";
}

void expect_bad_input(const Error& error, std::string_view text) {
  EXPECT_EQ(error.kind, Error::Kind::bad_input);
  EXPECT_EQ(error.to_string(), text);
}

TEST(ManifestErrors, MalformedJsonGivesLineAndColumn) {
  expect_bad_input(manifest_error("{\"schema\": 1,\n  \"sets\": [}"),
                   "perms.json: malformed JSON: parse error at line 2, column 12: syntax error "
                   "while parsing value - unexpected '}'; expected '[', '{', or a literal");
}

TEST(ManifestErrors, DocumentMustBeAnObject) {
  expect_bad_input(manifest_error("[1]"), "perms.json: expected an object, got an array");
}

TEST(ManifestErrors, SchemaIsRequiredAndMustBeOne) {
  expect_bad_input(manifest_error(R"({"sets": []})"),
                   "perms.json: missing key 'schema'; allowed value 1");
  expect_bad_input(manifest_error(R"({"schema": 2, "sets": []})"),
                   "perms.json: /schema: schema 2 is not supported; allowed value 1");
}

TEST(ManifestErrors, UnknownTopLevelKey) {
  expect_bad_input(manifest_error(R"({"schema": 1, "set": []})"),
                   "perms.json: /set: unknown key 'set'; allowed keys: schema, disks, targets, "
                   "forms, sets, exclude, max_variants");
}

TEST(ManifestErrors, FormsNameKnownForms) {
  expect_bad_input(
      manifest_error(
          R"({"schema": 1, "forms": ["query", "shadow"], "sets": [{"technique": "hard"}]})"),
      "perms.json: /forms/1: unknown form 'shadow'; allowed forms: query, deferred, function");
  expect_bad_input(manifest_error(R"({"schema": 1, "forms": [], "sets": [{"technique": "hard"}]})"),
                   "perms.json: /forms: expected at least one value, got an empty list");
  EXPECT_THAT(manifest_error(with_set(R"({"technique": "hard", "forms": 3})")).to_string(),
              ::testing::HasSubstr("perms.json: /sets/1/forms: expected a string, got "));
  // Exclusions remove variants and targets, not forms.
  EXPECT_THAT(
      manifest_error(
          R"({"schema": 1, "sets": [{"technique": "hard"}], "exclude": [{"forms": "query"}]})")
          .to_string(),
      ::testing::HasSubstr("/exclude/0/forms: unknown key 'forms'"));
}

// A technique with none of the forms asked would leave a variant with
// nothing but its depth pass.
TEST(ManifestErrors, ATechniqueNeedsOneOfTheFormsAsked) {
  expect_bad_input(
      manifest_error(
          with_set(R"({"technique": "screen_blur", "blur_radius": 2, "forms": ["function"]})")),
      "perms.json: /sets/1/forms: technique screen_blur has none of the forms asked; its forms: "
      "query");
  expect_bad_input(
      manifest_error(R"({"schema": 1, "forms": "deferred",
                         "sets": [{"technique": ["hard", "screen_blur"], "blur_radius": 2}]})"),
      "perms.json: /sets/0: technique screen_blur has none of the forms asked; its forms: query "
      "(this set takes the top-level forms; give it a 'forms' list)");
}

TEST(ManifestErrors, UnknownKeyInASet) {
  expect_bad_input(
      manifest_error(with_set(R"({"technique": "pcf_grid", "kernels": [3]})")),
      "perms.json: /sets/1/kernels: unknown key 'kernels'; allowed keys: technique, "
      "blocker_samples, pcf_samples, kernel, disk, traversal, max_nodes, "
      "blur_radius, depth_aware, light_bits, rotation, receiver_plane, map_encoding, map_layout, "
      "target, forms");
}

TEST(ManifestErrors, UnknownTechnique) {
  expect_bad_input(manifest_error(with_set(R"({"technique": ["pcss", "vsm"]})")),
                   "perms.json: /sets/1/technique/1: unknown technique 'vsm'; allowed "
                   "techniques: hard, pcf_grid, pcf_poisson, pcss, minmax_pcf, backprojection, "
                   "pcss_minmax, screen_blur, bitmask_backprojection");
}

TEST(ManifestErrors, UnknownTarget) {
  expect_bad_input(
      manifest_error(
          R"({"schema": 1, "targets": ["spirv", "dx12"], "sets": [{"technique": "hard"}]})"),
      "perms.json: /targets/1: unknown target 'dx12'; allowed targets: spirv, glsl450, glsl330, "
      "essl300, hlsl_dx11, hlsl_dx10, hlsl_dx9");
  expect_bad_input(manifest_error(with_set(R"({"technique": "hard", "target": "metal"})")),
                   "perms.json: /sets/1/target: unknown target 'metal'; allowed targets: spirv, "
                   "glsl450, glsl330, essl300, hlsl_dx11, hlsl_dx10, hlsl_dx9");
}

TEST(ManifestErrors, SampleCountOutOfRange) {
  expect_bad_input(
      manifest_error(
          with_set(R"({"technique": "pcf_poisson", "pcf_samples": [16, 0], "disk": "poisson"})")),
      "perms.json: /sets/1/pcf_samples/1: sample count 0 is out of range; allowed "
      "1..128");
  expect_bad_input(
      manifest_error(with_set(
          R"({"technique": "pcss", "blocker_samples": 129, "pcf_samples": 16, "disk": "poisson"})")),
      "perms.json: /sets/1/blocker_samples: sample count 129 is out of range; allowed 1..128");
}

TEST(ManifestErrors, SampleCountMustBeAnInteger) {
  expect_bad_input(manifest_error(with_set(
                       R"({"technique": "pcf_poisson", "pcf_samples": 16.5, "disk": "poisson"})")),
                   "perms.json: /sets/1/pcf_samples: expected an integer, got 16.5");
}

TEST(ManifestErrors, EvenKernelForPcfGrid) {
  expect_bad_input(manifest_error(with_set(R"({"technique": "pcf_grid", "kernel": [3, 4]})")),
                   "perms.json: /sets/1/kernel/1: kernel 4 is not allowed for pcf_grid; allowed "
                   "odd sizes 1..127 (minmax_pcf takes any size 1..128)");
  // 128 is a size minmax_pcf takes, but not pcf_grid, even in a set shared with it.
  expect_bad_input(
      manifest_error(with_set(R"({"technique": ["minmax_pcf", "pcf_grid"], "kernel": 128})")),
      "perms.json: /sets/1/kernel: kernel 128 is not allowed for pcf_grid; allowed odd sizes "
      "1..127 (minmax_pcf takes any size 1..128)");
}

TEST(ManifestErrors, KernelOutOfRange) {
  const std::string allowed = " is out of range; allowed 1..128 (pcf_grid: odd sizes 1..127)";
  expect_bad_input(manifest_error(with_set(R"({"technique": "minmax_pcf", "kernel": [8, 0]})")),
                   "perms.json: /sets/1/kernel/1: kernel 0" + allowed);
  expect_bad_input(manifest_error(with_set(R"({"technique": "minmax_pcf", "kernel": 129})")),
                   "perms.json: /sets/1/kernel: kernel 129" + allowed);
  expect_bad_input(manifest_error(with_set(R"({"technique": "pcf_grid", "kernel": 129})")),
                   "perms.json: /sets/1/kernel: kernel 129" + allowed);
}

TEST(ManifestErrors, UnknownTraversal) {
  expect_bad_input(
      manifest_error(with_set(R"({"technique": "minmax_pcf", "kernel": 8, "traversal": "foo"})")),
      "perms.json: /sets/1/traversal: unknown traversal 'foo'; allowed traversals: brute_force "
      "(leave the key out for the min-max traversal)");
  expect_bad_input(manifest_error(with_set(R"({"technique": "backprojection",
                                              "traversal": ["brute_force", 1]})")),
                   "perms.json: /sets/1/traversal/1: expected a string, got 1");
}

TEST(ManifestErrors, MaxNodesOutOfRange) {
  const std::string allowed = " is out of range; allowed 1..1048576";
  expect_bad_input(
      manifest_error(with_set(R"({"technique": "backprojection", "max_nodes": [64, 0]})")),
      "perms.json: /sets/1/max_nodes/1: max_nodes 0" + allowed);
  expect_bad_input(
      manifest_error(with_set(R"({"technique": "backprojection", "max_nodes": 1048577})")),
      "perms.json: /sets/1/max_nodes: max_nodes 1048577" + allowed);
}

TEST(ManifestErrors, LightBitsAreASquareGrid) {
  expect_bad_input(
      manifest_error(with_set(
          R"({"technique": "bitmask_backprojection", "light_bits": [64, 100], "target": "spirv"})")),
      "perms.json: /sets/1/light_bits/1: light_bits 100 is not allowed; allowed 16, 64, 256, 1024 "
      "(a square grid of light samples)");
  expect_bad_input(
      manifest_error(with_set(R"({"technique": "bitmask_backprojection", "target": "spirv"})")),
      "perms.json: /sets/1: technique bitmask_backprojection needs key 'light_bits'; "
      "bitmask_backprojection uses traversal (optional), max_nodes (optional), light_bits, "
      "map_encoding (optional)");
}

// Shader Model 3 has no integer bit operations: the set is refused where the
// target comes from, never silently narrowed.
TEST(ManifestErrors, BitmaskIsRefusedForDirect3D9) {
  const std::string refused =
      "technique bitmask_backprojection cannot be emitted for hlsl_dx9 (Shader Model 3 has no "
      "integer bit operations); allowed targets: spirv, glsl450, glsl330, essl300, hlsl_dx11, "
      "hlsl_dx10";
  expect_bad_input(manifest_error(with_set(R"({"technique": "bitmask_backprojection",
                                              "light_bits": 64,
                                              "target": ["spirv", "hlsl_dx9"]})")),
                   "perms.json: /sets/1/target: " + refused);
  expect_bad_input(
      manifest_error(with_set(R"({"technique": "bitmask_backprojection", "light_bits": 64})")),
      "perms.json: /sets/1: " + refused +
          " (this set takes the top-level targets; give it a 'target' list)");
}

// minmax_pcf promises the exact count, which hlsl_dx9's cap on the walk's
// steps breaks from K = 9 (K = 15 with brute force): refused like the bitmask.
TEST(ManifestErrors, MinmaxPcfIsRefusedWhereItCannotCountExactly) {
  const std::string why =
      "minmax_pcf_k16 cannot count exactly on hlsl_dx9: its walk may take 599 steps, and "
      "hlsl_dx9 stops every walk after 224 (ps_3_0 guarantees only 65,535 executed "
      "instructions); the largest kernel that fits is 8; ";
  expect_bad_input(manifest_error(with_set(R"({"technique": "minmax_pcf", "kernel": [8, 16],
                                              "target": ["spirv", "hlsl_dx9"]})")),
                   "perms.json: /sets/1/target: " + why +
                       "leave hlsl_dx9 out of this set's 'target' list, or use a smaller "
                       "kernel (docs/targets.md)");
  expect_bad_input(manifest_error(with_set(R"({"technique": "minmax_pcf", "kernel": 16})")),
                   "perms.json: /sets/1: " + why +
                       "this set takes the top-level targets: give it a 'target' list without "
                       "hlsl_dx9, or use a smaller kernel (docs/targets.md)");
  expect_bad_input(
      manifest_error(with_set(R"({"technique": "minmax_pcf", "kernel": 15,
                                 "traversal": "brute_force", "target": "hlsl_dx9"})")),
      "perms.json: /sets/1/target: minmax_pcf_k15_brute_force cannot count exactly on hlsl_dx9: "
      "its walk may take 225 steps (a texel each), and hlsl_dx9 stops every walk after 224 "
      "(ps_3_0 guarantees only 65,535 executed instructions); the largest kernel that fits is "
      "14 with traversal brute_force; leave hlsl_dx9 out of this set's 'target' list, or use a "
      "smaller kernel (docs/targets.md)");
  // What fits is built for every target; the rest for the others.
  const std::string fits = R"({"schema": 1, "sets": [
    {"technique": "minmax_pcf", "kernel": [8, 14], "traversal": "brute_force"},
    {"technique": "minmax_pcf", "kernel": 8},
    {"technique": "minmax_pcf", "kernel": 64, "target": ["spirv", "hlsl_dx11"]}]})";
  Result<Manifest> manifest = parse_manifest(fits, "perms.json");
  ASSERT_TRUE(manifest.ok()) << manifest.error().to_string();
  EXPECT_TRUE(expand(*manifest).ok());
}

TEST(ManifestErrors, RotationIsIgnWhereSamplesAreBaked) {
  expect_bad_input(manifest_error(with_set(R"({"technique": "pcss", "blocker_samples": 16,
                                              "pcf_samples": 16, "disk": "poisson",
                                              "rotation": ["ign", "random"]})")),
                   "perms.json: /sets/1/rotation/1: unknown rotation 'random'; allowed rotations: "
                   "ign (leave the key out for the same samples at every pixel)");
  expect_bad_input(manifest_error(with_set(R"({"technique": "pcf_grid", "kernel": 3,
                                              "rotation": "ign"})")),
                   "perms.json: /sets/1/rotation: key 'rotation' is used by none of this set's "
                   "techniques"
                   "; techniques that use it: pcf_poisson, pcss, pcss_minmax");
}

TEST(ManifestErrors, TraversalAndMaxNodesOnlyWhereUsed) {
  expect_bad_input(
      manifest_error(
          with_set(R"({"technique": "pcf_grid", "kernel": 3, "traversal": "brute_force"})")),
      "perms.json: /sets/1/traversal: key 'traversal' is used by none of this set's techniques"
      "; techniques that use it: minmax_pcf, backprojection, "
      "bitmask_backprojection");
  expect_bad_input(
      manifest_error(with_set(R"({"technique": "minmax_pcf", "kernel": 8, "max_nodes": 64})")),
      "perms.json: /sets/1/max_nodes: key 'max_nodes' is used by none of this set's techniques"
      "; techniques that use it: backprojection, bitmask_backprojection");
  expect_bad_input(
      manifest_error(with_set(R"({"technique": "minmax_pcf", "traversal": "brute_force"})")),
      "perms.json: /sets/1: technique minmax_pcf needs key 'kernel'; minmax_pcf uses "
      "kernel, traversal (optional), map_encoding (optional)");
}

TEST(ManifestErrors, Whitepaper16HasOnly16Points) {
  expect_bad_input(
      manifest_error(with_set(
          R"({"technique": "pcss", "blocker_samples": 16, "pcf_samples": [16, 25], "disk": "whitepaper16"})")),
      "perms.json: /sets/1: variant pcss_b16_p25_whitepaper16: pcf_samples 25 is out of range "
      "for whitepaper16; allowed 1..16 (declare a generated disk under /disks for more samples)");
}

TEST(ManifestErrors, UndeclaredDisk) {
  expect_bad_input(manifest_error(with_set(
                       R"({"technique": "pcf_poisson", "pcf_samples": 16, "disk": "vogel"})")),
                   "perms.json: /sets/1/disk: unknown disk 'vogel'; allowed disks: poisson, "
                   "whitepaper16 (declare generated disks under /disks)");
}

TEST(ManifestErrors, DiskDeclarations) {
  expect_bad_input(manifest_error(R"({"schema": 1, "disks": {"p": {"method": "lloyd"}}})"),
                   "perms.json: /disks/p/method: unknown disk method 'lloyd'; allowed methods: "
                   "best_candidate, sample_elimination, square_stratified, square_r2");
  expect_bad_input(manifest_error(R"({"schema": 1, "disks": {"p": {"seed": -1}}})"),
                   "perms.json: /disks/p/seed: expected an integer in 0..18446744073709551615, "
                   "got -1");
  expect_bad_input(manifest_error(R"({"schema": 1, "disks": {"p": {"count": 16}}})"),
                   "perms.json: /disks/p/count: unknown key 'count'; allowed keys: method, seed");
  expect_bad_input(manifest_error(R"({"schema": 1, "disks": {"whitepaper16": {}}})"),
                   "perms.json: /disks/whitepaper16: 'whitepaper16' is built in; give generated "
                   "disks another name");
  expect_bad_input(manifest_error(R"({"schema": 1, "disks": {"My/Disk": {}}})"),
                   "perms.json: /disks/My~1Disk: disk name 'My/Disk' is not allowed; use "
                   "lowercase letters, digits and '_', starting with a letter");
}

// map_encoding names an encoding, for the techniques that take one (all but
// screen_blur); linear is the key left out.
TEST(ManifestErrors, MapEncodingIsAnEncodingOfATechniqueThatTakesOne) {
  expect_bad_input(manifest_error(with_set(R"({"technique": "hard",
                                              "map_encoding": ["perspective", "reversed"]})")),
                   "perms.json: /sets/1/map_encoding/1: unknown map_encoding 'reversed'; allowed "
                   "map encodings: linear, perspective, perspective_reversed, orthographic "
                   "(docs/techniques.md, \"Map encodings\")");
  expect_bad_input(manifest_error(with_set(R"({"technique": "screen_blur", "blur_radius": 4,
                                              "map_encoding": "perspective"})")),
                   "perms.json: /sets/1/map_encoding: key 'map_encoding' is used by none of this "
                   "set's techniques"
                   "; techniques that use it: hard, pcf_grid, pcf_poisson, pcss, "
                   "minmax_pcf, backprojection, pcss_minmax, bitmask_backprojection");
  const std::string both = R"({"schema": 1, "sets": [
    {"technique": "hard", "map_encoding": ["linear", "perspective_reversed"]}],
    "exclude": [{"map_encoding": "linear", "target": "spirv"}]})";
  Result<Manifest> manifest = parse_manifest(both, "perms.json");
  ASSERT_TRUE(manifest.ok()) << manifest.error().to_string();
  Result<std::vector<Variant>> variants = expand(*manifest);
  ASSERT_TRUE(variants.ok()) << variants.error().to_string();
  ASSERT_EQ(variants->size(), 2u);
  EXPECT_EQ((*variants)[0].name, "hard");
  EXPECT_FALSE((*variants)[0].keys.map_encoding);
  EXPECT_EQ(std::ranges::find((*variants)[0].targets, Target::spirv), (*variants)[0].targets.end());
  EXPECT_EQ((*variants)[1].name, "hard_perspective_reversed");
  EXPECT_EQ((*variants)[1].keys.map_encoding, "perspective_reversed");
  EXPECT_NE(std::ranges::find((*variants)[1].targets, Target::spirv), (*variants)[1].targets.end());
}

// map_layout names a layout, for the techniques that read the map alone;
// single is the key left out.
TEST(ManifestErrors, MapLayoutIsALayoutOfATechniqueThatTakesOne) {
  expect_bad_input(manifest_error(with_set(R"({"technique": "hard",
                                              "map_layout": ["atlas", "cube"]})")),
                   "perms.json: /sets/1/map_layout/1: unknown map_layout 'cube'; allowed map "
                   "layouts: single, atlas, array (docs/techniques.md, \"Map layouts\")");
  expect_bad_input(manifest_error(with_set(R"({"technique": "minmax_pcf", "kernel": 3,
                                              "map_layout": "atlas"})")),
                   "perms.json: /sets/1/map_layout: key 'map_layout' is used by none of this "
                   "set's techniques"
                   " (minmax_pcf reads a min-max mip built over a whole texture: its "
                   "nodes would mix an atlas's tiles, and it has no levels per array "
                   "layer); techniques that use it: hard, pcf_grid, pcf_poisson, pcss");
  const std::string both = R"({"schema": 1, "sets": [
    {"technique": "pcf_grid", "kernel": 3, "map_encoding": ["linear", "perspective"],
     "map_layout": ["single", "atlas"]}],
    "exclude": [{"map_layout": "atlas", "map_encoding": "perspective"}]})";
  Result<Manifest> manifest = parse_manifest(both, "perms.json");
  ASSERT_TRUE(manifest.ok()) << manifest.error().to_string();
  Result<std::vector<Variant>> variants = expand(*manifest);
  ASSERT_TRUE(variants.ok()) << variants.error().to_string();
  std::vector<std::string> names;
  for (const Variant& v : *variants) names.push_back(v.name);
  EXPECT_EQ(names, (std::vector<std::string>{"pcf_grid_k3", "pcf_grid_k3_atlas",
                                             "pcf_grid_k3_perspective"}));
  EXPECT_FALSE((*variants)[0].keys.map_layout);
  EXPECT_EQ((*variants)[1].keys.map_layout, "atlas");
}

// Direct3D 9 has no texture arrays: a set that asks for the array layout
// there is refused, naming where its targets came from.
TEST(ManifestErrors, ArrayLayoutIsRefusedOnDirect3D9) {
  expect_bad_input(manifest_error(with_set(R"({"technique": "hard", "map_layout": "array",
                                              "target": ["spirv", "hlsl_dx9"]})")),
                   "perms.json: /sets/1/target: map_layout array cannot be read on hlsl_dx9 "
                   "(Direct3D 9 has no texture arrays; map_layout atlas can); leave hlsl_dx9 "
                   "out of this set's 'target' list");
  expect_bad_input(manifest_error(R"({"schema": 1, "targets": ["glsl330", "hlsl_dx9"],
                                      "sets": [{"technique": "hard", "map_layout": "array"}]})"),
                   "perms.json: /sets/0: map_layout array cannot be read on hlsl_dx9 "
                   "(Direct3D 9 has no texture arrays; map_layout atlas can); this set takes "
                   "the top-level targets: give it a 'target' list without hlsl_dx9");
}

TEST(ManifestErrors, TechniqueMissingAKeyItNeeds) {
  expect_bad_input(
      manifest_error(with_set(R"({"technique": "pcss", "pcf_samples": 16, "disk": "poisson"})")),
      "perms.json: /sets/1: technique pcss needs key 'blocker_samples'; pcss uses "
      "blocker_samples, pcf_samples, disk, rotation (optional), receiver_plane (optional), "
      "map_encoding (optional), map_layout (optional)");
  expect_bad_input(manifest_error(with_set(R"({"kernel": 3})")),
                   "perms.json: /sets/1: missing key 'technique'; allowed techniques: hard, "
                   "pcf_grid, pcf_poisson, pcss, minmax_pcf, backprojection, pcss_minmax, "
                   "screen_blur, bitmask_backprojection");
}

TEST(ManifestErrors, KeyNoTechniqueUses) {
  expect_bad_input(manifest_error(with_set(R"({"technique": ["hard", "pcf_grid"], "kernel": 3,
                                              "pcf_samples": 16})")),
                   "perms.json: /sets/1/pcf_samples: key 'pcf_samples' is used by none of this "
                   "set's techniques"
                   "; techniques that use it: pcf_poisson, pcss, pcss_minmax");
}

TEST(ManifestErrors, SetsAndExclusions) {
  expect_bad_input(manifest_error(R"({"schema": 1})"),
                   "perms.json: missing key 'sets'; a manifest needs at least one set");
  expect_bad_input(manifest_error(R"({"schema": 1, "sets": []})"),
                   "perms.json: /sets: expected at least one set, got an empty list");
  expect_bad_input(manifest_error(with_set(R"({"technique": []})")),
                   "perms.json: /sets/1/technique: expected at least one value, got an empty list");
  expect_bad_input(
      manifest_error(R"({"schema": 1, "sets": [{"technique": "hard"}], "exclude": [{}]})"),
      "perms.json: /exclude/0: an exclusion needs at least one key; allowed keys: technique, "
      "blocker_samples, pcf_samples, kernel, disk, traversal, max_nodes, blur_radius, "
      "depth_aware, light_bits, rotation, receiver_plane, map_encoding, map_layout, target");
  expect_bad_input(
      manifest_error(
          R"({"schema": 1, "sets": [{"technique": "hard"}], "exclude": [{"kernel": 0}]})"),
      "perms.json: /exclude/0/kernel: kernel 0 is out of range; allowed 1..128 (pcf_grid: odd "
      "sizes 1..127)");
  expect_bad_input(
      manifest_error(
          R"({"schema": 1, "sets": [{"technique": "hard"}], "exclude": [{"max_nodes": 0}]})"),
      "perms.json: /exclude/0/max_nodes: max_nodes 0 is out of range; allowed 1..1048576");
}

TEST(ManifestErrors, BlurRadiusOutOfRange) {
  const std::string allowed = " is out of range; allowed 1..32";
  expect_bad_input(
      manifest_error(with_set(R"({"technique": "screen_blur", "blur_radius": [4, 0]})")),
      "perms.json: /sets/1/blur_radius/1: blur_radius 0" + allowed);
  expect_bad_input(manifest_error(with_set(R"({"technique": "screen_blur", "blur_radius": 33})")),
                   "perms.json: /sets/1/blur_radius: blur_radius 33" + allowed);
  expect_bad_input(manifest_error(with_set(R"({"technique": "screen_blur", "blur_radius": 2.5})")),
                   "perms.json: /sets/1/blur_radius: expected an integer, got 2.5");
  expect_bad_input(
      manifest_error(
          R"({"schema": 1, "sets": [{"technique": "hard"}], "exclude": [{"blur_radius": 33}]})"),
      "perms.json: /exclude/0/blur_radius: blur_radius 33" + allowed);
}

TEST(ManifestErrors, DepthAwareMustBeABool) {
  expect_bad_input(manifest_error(with_set(
                       R"({"technique": "screen_blur", "blur_radius": 4, "depth_aware": "yes"})")),
                   "perms.json: /sets/1/depth_aware: expected true or false, got \"yes\"");
  expect_bad_input(
      manifest_error(
          with_set(R"({"technique": "screen_blur", "blur_radius": 4, "depth_aware": [true, 1]})")),
      "perms.json: /sets/1/depth_aware/1: expected true or false, got 1");
}

TEST(ManifestErrors, BlurKeysOnlyForScreenBlur) {
  expect_bad_input(
      manifest_error(with_set(R"({"technique": "pcf_grid", "kernel": 3, "blur_radius": 4})")),
      "perms.json: /sets/1/blur_radius: key 'blur_radius' is used by none of this set's "
      "techniques"
      "; techniques that use it: screen_blur");
  expect_bad_input(manifest_error(with_set(R"({"technique": "hard", "depth_aware": true})")),
                   "perms.json: /sets/1/depth_aware: key 'depth_aware' is used by none of this "
                   "set's techniques"
                   "; techniques that use it: screen_blur");
  expect_bad_input(manifest_error(with_set(R"({"technique": "screen_blur", "depth_aware": true})")),
                   "perms.json: /sets/1: technique screen_blur needs key 'blur_radius'; "
                   "screen_blur uses blur_radius, depth_aware (optional)");
}

TEST(ManifestErrors, MissingFile) {
  const std::string path = PENUMBRA_BINARY_DIR "/no-such-dir/manifest.json";
  Result<Manifest> manifest = load_manifest(path);
  ASSERT_FALSE(manifest.ok());
  EXPECT_EQ(manifest.error().kind, Error::Kind::io);
  EXPECT_EQ(manifest.error().to_string(), path + ": cannot read the manifest: no such file");
}

TEST(ManifestErrors, DirectoryIsNotAManifest) {
  Result<Manifest> manifest = load_manifest(PENUMBRA_SOURCE_DIR "/permutations");
  ASSERT_FALSE(manifest.ok());
  EXPECT_EQ(manifest.error().kind, Error::Kind::io);
  EXPECT_EQ(manifest.error().to_string(),
            PENUMBRA_SOURCE_DIR "/permutations: cannot read the manifest: it is a directory");
}

}  // namespace
}  // namespace penumbra
