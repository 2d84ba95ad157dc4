#include <iostream>

#include "commands.hpp"
#include "exit_codes.hpp"
#include "penumbra/compiler/manifest.hpp"

namespace penumbra::cli {

void add_list_command(CLI::App& app, int& exit_code) {
  auto manifest_path = std::make_shared<std::string>();
  CLI::App* cmd = app.add_subcommand("list", "Print the variants of a manifest, one per line");
  cmd->add_option("manifest", *manifest_path, "Permutation manifest (JSON)")->required();
  cmd->callback([manifest_path, &exit_code] {
    auto variants = load_variants(*manifest_path);
    if (!variants) {
      exit_code = report(variants.error());
      return;
    }
    for (const Variant& variant : *variants) std::cout << variant.name << "\n";
  });
}

}  // namespace penumbra::cli
