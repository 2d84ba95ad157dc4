#include <unistd.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <filesystem>
#include <iostream>
#include <optional>
#include <string>
#include <system_error>
#include <utility>

#include "commands.hpp"
#include "exit_codes.hpp"
#include "penumbra/reference/techniques.hpp"
#include "penumbra/support/pfm.hpp"
#include "penumbra/verify/eval.hpp"
#include "validators.hpp"

namespace penumbra::cli {
namespace {

namespace fs = std::filesystem;

struct EvalArgs {
  std::string library;
  std::string variant;
  std::string target = "spirv";
  std::string shadow_map;
  std::string receivers;
  std::string no_receiver;          // optional Pf mask of pixels with no receiver
  bool map_stored = false;          // --shadow-map holds an engine's stored values
  std::optional<double> far_plane;  // the engine's far plane, with map_stored
  std::string map_tile;             // "x,y,width,height": the light's tile of an atlas
  std::string map_layer;            // "layer,count": the light's layer of an array
  std::string output;
  std::string texel_reads;  // optional Pf of the query's per-pixel texel reads
  std::string ambiguous;    // optional Pf of the reference's ambiguity mask
  std::string device;
  bool reference = false;
  LightParams light;
  std::optional<double> filter_radius;  // none: the default, 2 texels
};

// `path` absolute, through its links, `.` and `..`, whether or not it exists:
// weakly_canonical leaves a relative path whose first part is missing
// relative, so that `v.pfm` and `./v.pfm` would differ.
fs::path resolved(const fs::path& path, std::error_code& error) {
  const fs::path absolute = fs::absolute(path, error);
  return error ? fs::path() : fs::weakly_canonical(absolute, error);
}

// Whether `a` and `b` name the same file, however spelled (neither need exist).
bool same_file(const fs::path& a, const fs::path& b) {
  std::error_code a_error, b_error;
  const fs::path a_path = resolved(a, a_error);
  const fs::path b_path = resolved(b, b_error);
  return !a_error && !b_error && a_path == b_path;
}

// Whether writing `output` would overwrite the existing file `input`: the
// same file however spelled, a hard link included.
bool overwrites(const fs::path& output, const fs::path& input) {
  std::error_code ec;
  return fs::equivalent(output, input, ec) || same_file(output, input);
}

// Whether `path` is `dir` or below it, through any spelling or link.
bool inside(const fs::path& path, const fs::path& dir) {
  std::error_code path_error, dir_error;
  const fs::path full = resolved(path, path_error);
  const fs::path root = fs::canonical(dir, dir_error);
  if (path_error || dir_error) return false;
  const fs::path relative = full.lexically_relative(root);
  return !relative.empty() && *relative.begin() != "..";
}

// eval reads every input before it writes: an output onto one would destroy it.
Status check_outputs_spare_inputs(const EvalArgs& args) {
  const std::pair<const char*, const std::string*> inputs[] = {
      {"--shadow-map", &args.shadow_map},
      {"--receivers", &args.receivers},
      {"--no-receiver", &args.no_receiver}};
  const std::pair<const char*, const std::string*> outputs[] = {
      {"-o", &args.output}, {"--texel-reads", &args.texel_reads}, {"--ambiguous", &args.ambiguous}};
  for (const auto& [flag, output] : outputs) {
    if (output->empty()) continue;
    const std::string where = std::string(flag) + " " + *output;
    for (const auto& [input_flag, input] : inputs) {
      if (input->empty()) continue;
      if (overwrites(*output, *input)) {
        return make_error(Error::Kind::bad_input, where,
                          "is the same file as " + std::string(input_flag) + " " + *input +
                              "; allowed: a file that is none of eval's inputs");
      }
    }
    if (inside(*output, args.library)) {
      return make_error(Error::Kind::bad_input, where,
                        "is inside the library " + args.library + "; allowed: a file outside it");
    }
  }
  return {};
}

// --map-tile's "x,y,width,height": four integers (their range is the
// inputs' check's, check_eval_inputs()).
// `text`, N integers separated by commas, given as `option`; errors say
// what `expected`.
template <std::size_t N>
Result<std::array<int, N>> parse_integers(const std::string& text, const char* option,
                                          const char* expected) {
  std::array<int, N> values{};
  std::size_t at = 0;
  for (std::size_t k = 0; k < N; ++k) {
    const std::size_t end = k + 1 < N ? text.find(',', at) : text.size();
    const std::string part = end == std::string::npos ? "" : text.substr(at, end - at);
    const auto [last, error] = std::from_chars(part.data(), part.data() + part.size(), values[k]);
    if (part.empty() || error != std::errc() || last != part.data() + part.size()) {
      return make_error(Error::Kind::bad_input, std::string(option) + " " + text,
                        std::string("expected ") + expected);
    }
    at = end + 1;
  }
  return values;
}

// What eval writes: the visibility (-o) and the file beside it, the texel
// reads (--texel-reads) or the ambiguity mask (--ambiguous).
struct EvalOutput {
  FloatImage visibility;
  FloatImage companion;
};

// The option and file written beside -o, if any. Never both: the texel reads
// need the device, the mask --reference (run_eval refuses the other).
std::pair<const char*, const std::string*> companion(const EvalArgs& args) {
  if (!args.ambiguous.empty()) return {"--ambiguous", &args.ambiguous};
  return {"--texel-reads", &args.texel_reads};
}

Result<EvalOutput> run_eval(const EvalArgs& args) {
  PENUMBRA_TRY(check_outputs_spare_inputs(args));
  if (args.reference && !args.texel_reads.empty()) {
    return make_error(Error::Kind::bad_input, "--texel-reads",
                      "texel reads are counted by the shaders on the device; they are not "
                      "available with --reference");
  }
  if (!args.reference && !args.ambiguous.empty()) {
    return make_error(Error::Kind::bad_input, "--ambiguous " + args.ambiguous,
                      "the ambiguity mask is the CPU reference's; allowed only with --reference");
  }
  if (args.map_stored != args.far_plane.has_value()) {
    return make_error(Error::Kind::bad_input, args.map_stored ? "--map-stored" : "--far",
                      "--map-stored needs --far and --far needs --map-stored (a stored map is "
                      "decoded with the engine's --near and --far); allowed: both or neither");
  }
  if (const auto [flag, path] = companion(args); !path->empty() && same_file(args.output, *path)) {
    return make_error(Error::Kind::bad_input, std::string(flag) + " " + *path,
                      "is the same file as -o " + args.output + "; allowed: a file of its own");
  }
  auto library = load_library(args.library);
  if (!library) return library.error();
  const LibraryVariant* variant = library->find(args.variant);
  if (!variant) {
    return make_error(Error::Kind::bad_input, args.variant,
                      "no such variant in " + args.library + " (see `penumbra list`)");
  }
  auto target = parse_target(args.target);
  if (!target) {
    return make_error(Error::Kind::bad_input, "--target " + args.target,
                      "unknown target; allowed: " + allowed_targets());
  }
  EvalInputs inputs;
  auto map = read_pfm(args.shadow_map);
  if (!map) return map.error();
  auto receivers = read_pfm(args.receivers);
  if (!receivers) return receivers.error();
  inputs.shadow_map = std::move(*map);
  inputs.receivers = std::move(*receivers);
  if (!args.no_receiver.empty()) {
    auto mask = read_pfm(args.no_receiver);
    if (!mask) return mask.error();
    inputs.no_receiver = std::move(*mask);
  }
  inputs.stored_far = args.far_plane;
  if (!args.map_tile.empty()) {
    PENUMBRA_TRY_ASSIGN(inputs.map_tile,
                        parse_integers<4>(args.map_tile, "--map-tile",
                                          "x,y,width,height: four integers in texels of "
                                          "--shadow-map"));
  }
  if (!args.map_layer.empty()) {
    PENUMBRA_TRY_ASSIGN(inputs.map_layer,
                        parse_integers<2>(args.map_layer, "--map-layer",
                                          "layer,count: two integers, the light's layer and "
                                          "the layers stacked in --shadow-map"));
  }
  inputs.light = args.light;
  inputs.light.filter_radius_uv = args.filter_radius;

  if (args.reference) {
    auto image = eval_reference(*variant, *target, inputs);
    if (!image) return image.error();
    return EvalOutput{std::move(image->visibility), std::move(image->ambiguous)};
  }
  auto engine = Engine::create(EngineOptions{.device = args.device}, stderr_diagnostics(false));
  if (!engine) return engine.error();
  auto output = eval_on_device(*library, *variant, *target, inputs, **engine);
  if (!output) return output.error();
  return EvalOutput{std::move(output->visibility), std::move(output->texel_reads)};
}

// `path`'s temporary for write_outputs, beside it so a rename moves it in.
fs::path staged(const fs::path& path) {
  return path.parent_path() /
         ("." + path.filename().string() + ".eval-" + std::to_string(::getpid()));
}

Error io_error(const fs::path& path, std::string message) {
  return make_error(Error::Kind::io, path.string(), std::move(message));
}

// Writes the visibility and, with --texel-reads or --ambiguous, its companion
// as a pair: each into a temporary beside its path, renamed into place once
// both are written, so that a failure leaves neither file.
Status write_outputs(const EvalArgs& args, const EvalOutput& output) {
  const fs::path other = *companion(args).second;
  if (other.empty()) return write_pfm(args.output, output.visibility);
  const fs::path visibility = args.output;
  const fs::path visibility_temp = staged(visibility);
  const fs::path other_temp = staged(other);
  std::error_code ignored;
  if (Status written = write_pfm(visibility_temp, output.visibility); !written) {
    return io_error(visibility, written.error().message);
  }
  if (Status written = write_pfm(other_temp, output.companion); !written) {
    fs::remove(visibility_temp, ignored);
    return io_error(other, written.error().message);
  }
  std::error_code renamed;
  fs::rename(other_temp, other, renamed);
  if (renamed) {
    fs::remove(visibility_temp, ignored);
    fs::remove(other_temp, ignored);
    return io_error(other, "cannot replace file: " + renamed.message());
  }
  fs::rename(visibility_temp, visibility, renamed);
  if (renamed) {
    fs::remove(visibility_temp, ignored);
    fs::remove(other, ignored);
    return io_error(visibility, "cannot replace file: " + renamed.message());
  }
  return {};
}

// `eval --help`'s list of the --ambiguous codes, from the reference's own.
std::string ambiguity_codes() {
  std::string text =
      "--ambiguous writes per pixel 0 where the reference decides it, else the sum of the codes "
      "of its reasons (docs/verification.md, \"The ambiguity rule\"):";
  constexpr std::size_t kWidth = 4;  // the codes right-aligned
  for (const reference::AmbiguityReason& r : reference::kAmbiguityReasons) {
    const std::string code = std::to_string(int(r.reason));
    text +=
        "\n  " + std::string(kWidth - std::min(kWidth, code.size()), ' ') + code + "  " + r.summary;
  }
  return text;
}

}  // namespace

void add_eval_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<EvalArgs>();
  CLI::App* cmd = app.add_subcommand("eval", "Run one variant over a shadow map and receivers");
  cmd->add_option("library", args->library, "Built library directory (penumbra build -o)")
      ->required();
  cmd->add_option("variant", args->variant, "Variant name")->required();
  cmd->add_option("--target", args->target, "Target whose shaders run");
  cmd->add_option("--shadow-map", args->shadow_map,
                  "Pf image of linear light-view z (with --map-stored: of stored depth)")
      ->required();
  cmd->add_option("--receivers", args->receivers, "PF image of (u, v, z_r)")->required();
  cmd->add_flag("--map-stored", args->map_stored,
                "--shadow-map holds the map as the engine stored it: depth-buffer values, 0 to "
                "1, in the variant's map encoding (linear: z / far), with --near and --far");
  cmd->add_option("--far", args->far_plane,
                  "The far plane of the engine's light projection (with --map-stored)");
  cmd->add_option("--map-tile", args->map_tile,
                  "x,y,width,height: the light's tile in texels of --shadow-map, an atlas of "
                  "several lights' maps (variants with map_layout atlas)");
  cmd->add_option("--map-layer", args->map_layer,
                  "layer,count: the light's layer of an array of count layers stacked in "
                  "--shadow-map, layer 0's rows first (variants with map_layout array)");
  cmd->add_option("--no-receiver", args->no_receiver,
                  "Pf image of the receivers' size: a pixel not 0 has no receiver; it is lit, "
                  "and --ambiguous marks it");
  cmd->add_option("-o,--out", args->output, "Visibility image to write (Pf)")->required();
  cmd->add_option("--texel-reads", args->texel_reads,
                  "Also write the shadow-map and min-max texels each pixel read (Pf; device only)");
  cmd->add_option("--ambiguous", args->ambiguous,
                  "With --reference, also write the pixels the error model excludes and why (Pf; "
                  "codes below)");
  // Their ranges are checked with the inputs (check_eval_inputs), NaN included.
  // The defaults shown are index.json's `defaults`.
  cmd->add_option("--light-size", args->light.light_world_size,
                  "Light half-width L (0: a point); orthographic variants: the tangent of the "
                  "directional light's angular half-width")
      ->capture_default_str();
  cmd->add_option("--frustum-width", args->light.frustum_width,
                  "Frustum width Fw at the near plane; orthographic variants: the box's width")
      ->capture_default_str();
  cmd->add_option("--near", args->light.near_plane, "Near plane n")->capture_default_str();
  cmd->add_option("--bias", args->light.bias, "Depth bias subtracted from z_r")
      ->capture_default_str();
  cmd->add_option("--filter-radius", args->filter_radius, "pcf_poisson radius in uv (default 2/W)");
  cmd->add_option("--device", args->device, "Vulkan device: index or name substring");
  cmd->add_flag(
      "--reference", args->reference,
      "Run the CPU reference of the target's shader (its step cap) instead of the device");
  cmd->footer(ambiguity_codes());
  cmd->callback([args, &exit_code] {
    auto output = run_eval(*args);
    if (!output) {
      exit_code = report(output.error());
      return;
    }
    if (Status written = write_outputs(*args, *output); !written) {
      exit_code = report(written.error());
      return;
    }
    std::cout << "wrote " << args->output << "\n";
    if (const std::string& other = *companion(*args).second; !other.empty()) {
      std::cout << "wrote " << other << "\n";
    }
  });
}

}  // namespace penumbra::cli
