// three.js r187 (npm, pinned by examples/threejs/package-lock.json) drawing
// the report's stage with its own SpotLight or DirectionalLight, shadow map
// (24-bit depth) and camera, the light's shadow term replaced by a variant's
// essl300 function form through examples/threejs/penumbra-three.js, in
// headless Chromium. Each picture must agree with the CPU reference
// evaluated on three's own map at the receivers three's shaders derived;
// the figures against the exact truth of each light, beside three's own
// PCF, are printed for docs/accuracy.md.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <iomanip>
#include <iostream>
#include <nlohmann/json.hpp>

#include "chromium_page.hpp"
#include "default_library.hpp"
#include "penumbra/compiler/manifest.hpp"
#include "penumbra/model/shadow_params.hpp"
#include "penumbra/reference/exact_visibility.hpp"
#include "penumbra/support/file.hpp"
#include "penumbra/verify/stage_picture.hpp"

namespace penumbra::testing {
namespace {

namespace fs = std::filesystem;

// examples/threejs/manifest.json's variants: each function-form technique
// in three's spot-light map, forward and reversed-Z, and in its
// directional-light map, and pcss rotated per pixel (the function's pixel
// argument from gl_FragCoord).
const std::vector<Variant>& example_variants() {
  static const std::vector<Variant> variants = [] {
    auto loaded = load_variants(PENUMBRA_SOURCE_DIR "/examples/threejs/manifest.json");
    if (!loaded) {
      std::fprintf(stderr, "cannot load the example's manifest: %s\n",
                   loaded.error().to_string().c_str());
      std::abort();  // while tests register: an empty list would drop them unseen
    }
    return std::move(*loaded);
  }();
  return variants;
}

const Variant& example_variant(const std::string& name) {
  return *std::find_if(example_variants().begin(), example_variants().end(),
                       [&](const Variant& v) { return v.name == name; });
}

std::vector<std::string> example_names() {
  std::vector<std::string> out;
  for (const Variant& variant : example_variants()) out.push_back(variant.name);
  return out;
}

// The ratios of the accuracy figures are to these variants', per light.
constexpr const char* kPcss = "pcss_b16_p16_poisson_perspective";
constexpr const char* kPcssDirectional = "pcss_b16_p16_poisson_orthographic";
// three's PCF (Vogel disk of 5 hardware comparisons) at these radii, in
// texels: its default, 1, and wider ones.
const std::vector<int> kThreeRadii = {1, 2, 4, 8};
// three's own bias, in stored depth: the stage's 0.05 world units at the
// box tops' depths (12 to 16), where its map holds what they receive from.
constexpr double kThreeBias = -0.002;

// examples/threejs/stage.json, which the example draws: it must be the
// report's stage, which the reference ray-casts.
Result<nlohmann::json> stage_json(const reference::Stage& stage) {
  const fs::path path = fs::path(PENUMBRA_SOURCE_DIR) / "examples" / "threejs" / "stage.json";
  PENUMBRA_TRY_ASSIGN(const std::string text, read_file(path));
  nlohmann::json json = nlohmann::json::parse(text, nullptr, false);
  const reference::Scene& scene = stage.scene;
  nlohmann::json boxes = nlohmann::json::array();
  for (const reference::Box& b : scene.boxes) boxes.push_back({b.x0, b.y0, b.x1, b.y1, b.z0, b.z1});
  const LightParams directional =
      reference::for_map_encoding(scene, MapEncoding::orthographic).light;
  const nlohmann::json expected = {
      {"width", scene.receivers_width},
      {"height", scene.receivers_height},
      {"map_size", scene.map_width},
      {"boxes", boxes},
      {"ground", {{"half_width", stage.ground_half_width}, {"z", scene.plane_z0}}},
      {"camera",
       {{"eye", stage.camera.eye},
        {"target", stage.camera.target},
        {"fov", stage.camera.vertical_fov_degrees}}},
      {"light",
       {{"near", scene.light.near_plane},
        {"far", 1.0 / depth_scale_for(scene.far_z)},
        {"frustum_width", scene.light.frustum_width},
        {"light_world_size", scene.light.light_world_size},
        {"bias", scene.light.bias}}},
      {"directional",
       {{"frustum_width", directional.frustum_width},
        {"light_world_size", directional.light_world_size}}}};
  if (json != expected) {
    return make_error(Error::Kind::bad_input, path.string(),
                      "is not reference::report_stage(), which is " + expected.dump());
  }
  return json;
}

Result<std::vector<float>> decode_floats(const std::string& base64, std::size_t count,
                                         const std::string& what) {
  static const std::string kAlphabet =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string bytes;
  unsigned bits = 0;
  int held = 0;
  for (char c : base64) {
    if (c == '=') break;
    const auto value = kAlphabet.find(c);
    if (value == std::string::npos) continue;
    bits = (bits << 6) | unsigned(value);
    held += 6;
    if (held >= 8) {
      held -= 8;
      bytes += char((bits >> held) & 0xff);
    }
  }
  if (bytes.size() != count * sizeof(float)) {
    return make_error(Error::Kind::internal, what,
                      "holds " + std::to_string(bytes.size()) + " bytes, not " +
                          std::to_string(count * sizeof(float)));
  }
  std::vector<float> out(count);
  std::memcpy(out.data(), bytes.data(), bytes.size());
  return out;
}

// A read-back picture: 4 channels, row 0 first, as the reference's ray cast
// has it (conformance.html turns three's camera to match).
Result<FloatImage> picture(const nlohmann::json& base64, int width, int height,
                           const std::string& what) {
  FloatImage out(width, height, 4);
  PENUMBRA_TRY_ASSIGN(
      out.data, decode_floats(base64.get<std::string>(), std::size_t(width) * height * 4, what));
  return out;
}

// The light three's shadow camera gave the function (its ShadowParams),
// directional for an orthographic map.
LightParams light_of(const nlohmann::json& parameters, MapEncoding encoding) {
  LightParams light;
  if (is_orthographic(encoding)) light.projection = LightProjection::orthographic;
  light.light_world_size = parameters.at("light")[0].get<double>();
  light.frustum_width = parameters.at("light")[1].get<double>();
  light.near_plane = parameters.at("light")[2].get<double>();
  light.filter_radius_uv = parameters.at("sampling")[0].get<double>();
  light.bias = parameters.at("sampling")[1].get<double>();
  return light;
}

struct BrowserRun {
  std::unique_ptr<TemporaryLibrary> built;
  nlohmann::json browser;
  std::string error;
};

Status build_and_run(BrowserRun& run) {
  PENUMBRA_TRY_ASSIGN(run.built, TemporaryLibrary::build(example_variants()));
  const Library& library = run.built->library();
  PENUMBRA_TRY_ASSIGN(const std::string index, read_file(library.root / "index.json"));
  PENUMBRA_TRY_ASSIGN(nlohmann::json stage, stage_json(reference::report_stage()));
  nlohmann::json input = {{"stage", std::move(stage)},
                          {"index", nlohmann::json::parse(index)},
                          {"variants", nlohmann::json::array()},
                          {"three_pcf_radii", kThreeRadii},
                          {"three_pcf_bias", kThreeBias}};
  for (const LibraryVariant& variant : library.variants) {
    PENUMBRA_TRY_ASSIGN(const std::string source,
                        read_file(library.root / variant.function.at(Target::essl300).file));
    input["variants"].push_back({{"name", variant.variant.name}, {"source", source}});
  }
  const fs::path site = PENUMBRA_THREEJS_SITE;
  for (const char* file : {"penumbra-three.js", "stage.js"}) {
    PENUMBRA_TRY_ASSIGN(const std::string text,
                        read_file(fs::path(PENUMBRA_SOURCE_DIR) / "examples" / "threejs" / file));
    PENUMBRA_TRY(write_file(site / file, text));
  }
  const fs::path template_path =
      fs::path(PENUMBRA_SOURCE_DIR) / "examples" / "threejs" / "conformance.html";
  PENUMBRA_TRY_ASSIGN(std::string page, read_file(template_path));
  const std::string placeholder = "PENUMBRA_INPUT_JSON";
  page.replace(page.find(placeholder), placeholder.size(), script_safe(input.dump()));
  const fs::path page_path = site / ("conformance-" + std::to_string(::getpid()) + ".html");
  PENUMBRA_TRY(write_file(page_path, page));
  PENUMBRA_TRY_ASSIGN(const std::string text, run_chromium_page(page_path, CHROMIUM_EXECUTABLE));
  run.browser = nlohmann::json::parse(text, nullptr, false);
  if (run.browser.is_discarded() || run.browser.contains("failure")) {
    return make_error(Error::Kind::device, page_path.string(), "the page failed: " + text);
  }
  std::error_code ignored;
  fs::remove(page_path, ignored);  // kept when the run fails
  return {};
}

const BrowserRun& shared() {
  static BrowserRun* const instance = [] {
    static BrowserRun run;
    if (auto status = build_and_run(run); !status) run.error = status.error().to_string();
    return &run;
  }();
  return *instance;
}

// The stage as three drew it, and what each picture is measured over.
struct Stage {
  reference::Stage stage = reference::report_stage();
  reference::StageView view;
  int width = 0, height = 0;
};

// The stage under the light that draws a map in `encoding`: the spot
// light's, or the directional one (reference::for_map_encoding()).
Stage three_stage(MapEncoding encoding) {
  Stage out;
  out.stage.scene = reference::for_map_encoding(out.stage.scene, encoding);
  out.width = out.stage.scene.receivers_width;
  out.height = out.stage.scene.receivers_height;
  out.view = reference::view(out.stage, out.width, out.height);
  return out;
}

// three's map for `encoding`, as the function forms sampled it.
Result<EngineMap> three_map(const nlohmann::json& browser, const reference::Scene& scene,
                            MapEncoding encoding) {
  const std::string key(to_string(encoding));
  PENUMBRA_TRY_ASSIGN(const std::vector<float> texels,
                      decode_floats(browser.at("maps").at(key).get<std::string>(),
                                    std::size_t(scene.map_width) * scene.map_height, key));
  EngineMap map;
  map.stored = FloatImage(scene.map_width, scene.map_height, 1);
  map.stored.data = texels;  // row 0 first in memory: v = 0.5 / height
  map.encoded = reference::encoded_depth(encoding, scene.light, depth_scale_for(scene.far_z));
  return map;
}

class ThreeJs : public ::testing::TestWithParam<std::string> {};

TEST_P(ThreeJs, FunctionFormInThreesMaterialsMatchesTheReferenceOnThreesMap) {
  const BrowserRun& run = shared();
  ASSERT_TRUE(run.error.empty()) << run.error;
  EXPECT_EQ(run.browser.at("three"), "187");
  EXPECT_EQ(run.browser.at("errors"), nlohmann::json::array({0, 0, 0})) << "WebGL errors";
  const Variant& variant = example_variant(GetParam());
  const MapEncoding encoding = map_encoding(variant.keys);
  const Stage stage = three_stage(encoding);
  auto map = three_map(run.browser, stage.stage.scene, encoding);
  ASSERT_TRUE(map) << map.error().to_string();
  auto gpu =
      picture(run.browser.at("pictures").at(GetParam()), stage.width, stage.height, GetParam());
  ASSERT_TRUE(gpu) << gpu.error().to_string();
  const LightParams light = light_of(run.browser.at("parameters").at(GetParam()), encoding);
  const LightParams& expected = stage.stage.scene.light;
  EXPECT_NEAR(light.frustum_width, expected.frustum_width, 1e-6);
  EXPECT_NEAR(light.near_plane, expected.near_plane, 1e-9);
  EXPECT_NEAR(light.light_world_size, expected.light_world_size, 1e-12);

  const FloatImage receivers = receivers_from_clip(*gpu, 3, 0.5, is_orthographic(encoding));
  // SwiftShader's texel coordinates carry 8 fractional bits, as lavapipe's.
  const reference::SamplingPrecision precision{8};
  auto check = check_stage_picture(variant, stage.stage, stage.view, *map, light, receivers, *gpu,
                                   2, precision, reference::shader_limits(Target::essl300));
  ASSERT_TRUE(check) << check.error().to_string();
  const reference::Comparison& c = check->comparison;
  EXPECT_TRUE(check->pass) << "max error " << c.max_abs_error << " (tolerance " << c.tolerance
                           << "), " << c.over_tolerance << " pixels over, " << c.ambiguous << " of "
                           << c.pixels << " ambiguous; camera agreement "
                           << check->camera_agreement;
  EXPECT_GT(check->surface_pixels, std::size_t(stage.width * stage.height / 4));
  EXPECT_GT(c.compared, c.pixels * 49 / 50);
  std::cout << std::defaultfloat << GetParam() << ": " << c.compared << " of " << c.pixels
            << " pixels, max error " << c.max_abs_error << ", camera agreement "
            << check->camera_agreement << "\n";
}

INSTANTIATE_TEST_SUITE_P(Example, ThreeJs, ::testing::ValuesIn(example_names()),
                         [](const auto& param_info) { return test_name(param_info.param); });

// Mean |visibility - exact| over the penumbra of the face-on pixels inside
// a face (exact strictly between 0 and 1), at the receivers three derived.
double penumbra_mae(const Stage& stage, const FloatImage& receivers, const FloatImage& exact,
                    const FloatImage& visibility, int channel) {
  double sum = 0.0;
  std::size_t count = 0;
  for (std::size_t k : face_pixels(stage.stage, stage.view, receivers)) {
    const double truth = exact.data[k];
    if (!reference::receives_light(stage.view.surfaces[k]) || !(truth > 0.0 && truth < 1.0))
      continue;
    sum += std::abs(visibility.data[4 * k + std::size_t(channel)] - truth);
    ++count;
  }
  return count ? sum / double(count) : 0.0;
}

// The figures docs/accuracy.md quotes for the light that draws maps in
// `encoding`, each also as a ratio to `pcss`'s; at every radius three's PCF
// on the same map must stay further from the truth than pcss.
void accuracy_against_the_truth(const BrowserRun& run, MapEncoding encoding, const char* pcss) {
  const Stage stage = three_stage(encoding);
  auto pcss_picture = picture(run.browser.at("pictures").at(pcss), stage.width, stage.height, pcss);
  ASSERT_TRUE(pcss_picture) << pcss_picture.error().to_string();
  const bool directional = is_orthographic(encoding);
  const FloatImage receivers = receivers_from_clip(*pcss_picture, 3, 0.5, directional);
  const FloatImage exact = reference::exact_visibility_image(stage.stage.scene, receivers);
  const double pcss_mae = penumbra_mae(stage, receivers, exact, *pcss_picture, 2);
  std::cout << std::fixed << std::setprecision(4) << "penumbra MAE against the exact "
            << (directional ? "directional light" : "area light") << " ("
            << run.browser.value("renderer", "") << "):\n";
  for (const std::string& name : example_names()) {
    if (map_encoding(example_variant(name).keys) != encoding) continue;
    auto gpu = picture(run.browser.at("pictures").at(name), stage.width, stage.height, name);
    ASSERT_TRUE(gpu) << gpu.error().to_string();
    const double mae = penumbra_mae(stage, receivers, exact, *gpu, 2);
    std::cout << "  penumbra " << name << ": " << mae << " (" << mae / pcss_mae << ")\n";
  }
  double best_three = 1.0;
  const nlohmann::json& pcf = run.browser.at("pcf").at(std::string(to_string(encoding)));
  for (int radius : kThreeRadii) {
    const std::string key = std::to_string(radius);
    auto three = picture(pcf.at(key), stage.width, stage.height, key);
    ASSERT_TRUE(three) << three.error().to_string();
    const double mae = penumbra_mae(stage, receivers, exact, *three, 0);
    std::cout << "  three PCFShadowMap radius " << radius << ": " << mae << " (" << mae / pcss_mae
              << ")\n";
    best_three = std::min(best_three, mae);
  }
  EXPECT_GT(pcss_mae, 0.0);
  EXPECT_LT(pcss_mae, best_three);
}

TEST(ThreeJsAccuracy, AgainstTheExactAreaLightBesideThreesPcf) {
  const BrowserRun& run = shared();
  ASSERT_TRUE(run.error.empty()) << run.error;
  accuracy_against_the_truth(run, MapEncoding::perspective, kPcss);
}

TEST(ThreeJsAccuracy, AgainstTheExactDirectionalLightBesideThreesPcf) {
  const BrowserRun& run = shared();
  ASSERT_TRUE(run.error.empty()) << run.error;
  accuracy_against_the_truth(run, MapEncoding::orthographic, kPcssDirectional);
}

}  // namespace
}  // namespace penumbra::testing
