#include <unistd.h>

#include <filesystem>
#include <iostream>
#include <optional>
#include <string>
#include <system_error>
#include <utility>

#include "commands.hpp"
#include "exit_codes.hpp"
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
  std::string output;
  std::string texel_reads;  // optional Pf of the query's per-pixel texel reads
  std::string device;
  bool reference = false;
  reference::LightParams light;
  std::optional<double> filter_radius;  // none: the default, 2 texels
};

// Whether `a` and `b` name the same file, however spelled (neither need exist).
bool same_file(const fs::path& a, const fs::path& b) {
  std::error_code a_error, b_error;
  const fs::path a_path = fs::weakly_canonical(a, a_error);
  const fs::path b_path = fs::weakly_canonical(b, b_error);
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
  const fs::path resolved = fs::weakly_canonical(path, path_error);
  const fs::path root = fs::canonical(dir, dir_error);
  if (path_error || dir_error) return false;
  const fs::path relative = resolved.lexically_relative(root);
  return !relative.empty() && *relative.begin() != "..";
}

// eval reads every input before it writes: an output onto one would destroy it.
Status check_outputs_spare_inputs(const EvalArgs& args) {
  const std::pair<const char*, const std::string*> inputs[] = {{"--shadow-map", &args.shadow_map},
                                                               {"--receivers", &args.receivers}};
  const std::pair<const char*, const std::string*> outputs[] = {
      {"-o", &args.output}, {"--texel-reads", &args.texel_reads}};
  for (const auto& [flag, output] : outputs) {
    if (output->empty()) continue;
    const std::string where = std::string(flag) + " " + *output;
    for (const auto& [input_flag, input] : inputs) {
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

Result<QueryOutput> run_eval(const EvalArgs& args) {
  PENUMBRA_TRY(check_outputs_spare_inputs(args));
  if (args.reference && !args.texel_reads.empty()) {
    return make_error(Error::Kind::bad_input, "--texel-reads",
                      "texel reads are counted by the shaders on the device; they are not "
                      "available with --reference");
  }
  if (!args.texel_reads.empty() && same_file(args.output, args.texel_reads)) {
    return make_error(
        Error::Kind::bad_input, "--texel-reads " + args.texel_reads,
        "is the same file as -o " + args.output + "; the texel reads need a file of their own");
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
  inputs.light = args.light;
  inputs.light.filter_radius_uv = args.filter_radius;

  if (args.reference) {
    auto visibility = eval_reference(*variant, inputs);
    if (!visibility) return visibility.error();
    return QueryOutput{std::move(*visibility), {}, std::nullopt};
  }
  auto engine = Engine::create(EngineOptions{.device = args.device}, stderr_diagnostics(false));
  if (!engine) return engine.error();
  return eval_on_device(*library, *variant, *target, inputs, **engine);
}

// `path`'s temporary for write_outputs, beside it so a rename moves it in.
fs::path staged(const fs::path& path) {
  return path.parent_path() /
         ("." + path.filename().string() + ".eval-" + std::to_string(::getpid()));
}

Error io_error(const fs::path& path, std::string message) {
  return make_error(Error::Kind::io, path.string(), std::move(message));
}

// Writes the visibility and, with --texel-reads, the texel reads as a pair:
// each into a temporary beside its path, renamed into place once both are
// written, so that a failure leaves neither file.
Status write_outputs(const EvalArgs& args, const QueryOutput& output) {
  if (args.texel_reads.empty()) return write_pfm(args.output, output.visibility);
  const fs::path visibility = args.output;
  const fs::path reads = args.texel_reads;
  const fs::path visibility_temp = staged(visibility);
  const fs::path reads_temp = staged(reads);
  std::error_code ignored;
  if (Status written = write_pfm(visibility_temp, output.visibility); !written) {
    return io_error(visibility, written.error().message);
  }
  if (Status written = write_pfm(reads_temp, output.texel_reads); !written) {
    fs::remove(visibility_temp, ignored);
    return io_error(reads, written.error().message);
  }
  std::error_code renamed;
  fs::rename(reads_temp, reads, renamed);
  if (renamed) {
    fs::remove(visibility_temp, ignored);
    fs::remove(reads_temp, ignored);
    return io_error(reads, "cannot replace file: " + renamed.message());
  }
  fs::rename(visibility_temp, visibility, renamed);
  if (renamed) {
    fs::remove(visibility_temp, ignored);
    fs::remove(reads, ignored);
    return io_error(visibility, "cannot replace file: " + renamed.message());
  }
  return {};
}

}  // namespace

void add_eval_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<EvalArgs>();
  CLI::App* cmd = app.add_subcommand("eval", "Run one variant over a shadow map and receivers");
  cmd->add_option("library", args->library, "Built library directory (penumbra build -o)")
      ->required();
  cmd->add_option("variant", args->variant, "Variant name")->required();
  cmd->add_option("--target", args->target, "Target whose shaders run");
  cmd->add_option("--shadow-map", args->shadow_map, "Pf image of linear light-view z")->required();
  cmd->add_option("--receivers", args->receivers, "PF image of (u, v, z_r)")->required();
  cmd->add_option("-o,--out", args->output, "Visibility image to write (Pf)")->required();
  cmd->add_option("--texel-reads", args->texel_reads,
                  "Also write the shadow-map and min-max texels each pixel read (Pf; device only)");
  // Their ranges are checked with the inputs (check_eval_inputs), NaN included.
  cmd->add_option("--light-size", args->light.light_world_size, "Light half-width L (0: a point)");
  cmd->add_option("--frustum-width", args->light.frustum_width,
                  "Frustum width Fw at the near plane");
  cmd->add_option("--near", args->light.near_plane, "Near plane n");
  cmd->add_option("--bias", args->light.bias, "Depth bias subtracted from z_r");
  cmd->add_option("--filter-radius", args->filter_radius, "pcf_poisson radius in uv (default 2/W)");
  cmd->add_option("--device", args->device, "Vulkan device: index or name substring");
  cmd->add_flag("--reference", args->reference, "Run the CPU reference instead of the device");
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
    if (!args->texel_reads.empty()) std::cout << "wrote " << args->texel_reads << "\n";
  });
}

}  // namespace penumbra::cli
