#include <iostream>

#include "commands.hpp"
#include "exit_codes.hpp"
#include "penumbra/runtime/eval.hpp"
#include "penumbra/support/pfm.hpp"

namespace penumbra::cli {
namespace {

struct EvalArgs {
  std::string library;
  std::string variant;
  std::string target = "spirv";
  std::string shadow_map;
  std::string receivers;
  std::string output;
  std::string device;
  bool reference = false;
  reference::LightParams light;
  double filter_radius = 0.0;  // 0: the default, 2 texels
};

Result<FloatImage> run_eval(const EvalArgs& args) {
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
  if (args.filter_radius > 0.0) inputs.light.filter_radius_uv = args.filter_radius;

  if (args.reference) return eval_reference(*variant, inputs);
  auto engine = Engine::create(EngineOptions{.device = args.device}, stderr_diagnostics(false));
  if (!engine) return engine.error();
  return eval_on_device(*library, *variant, *target, inputs, **engine);
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
  cmd->add_option("--light-size", args->light.light_world_size, "Light half-width L")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--frustum-width", args->light.frustum_width,
                  "Frustum width Fw at the near plane")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--near", args->light.near_plane, "Near plane n")->check(CLI::PositiveNumber);
  cmd->add_option("--bias", args->light.bias, "Depth bias subtracted from z_r");
  cmd->add_option("--filter-radius", args->filter_radius, "pcf_poisson radius in uv (default 2/W)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--device", args->device, "Vulkan device: index or name substring");
  cmd->add_flag("--reference", args->reference, "Run the CPU reference instead of the device");
  cmd->callback([args, &exit_code] {
    auto image = run_eval(*args);
    if (!image) {
      exit_code = report(image.error());
      return;
    }
    if (Status written = write_pfm(args->output, *image); !written) {
      exit_code = report(written.error());
      return;
    }
    std::cout << "wrote " << args->output << "\n";
  });
}

}  // namespace penumbra::cli
