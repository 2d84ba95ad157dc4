// A tool that reads a built library's index.json (`penumbra build`'s
// output, its path the argument) and lists each variant's targets: it links
// Penumbra::library alone, no shader compiler.
#include <cstdio>
#include <string>

#include "penumbra/library/library.hpp"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: index_reader LIBRARY\n");
    return 2;
  }
  const auto library = penumbra::load_library(argv[1]);
  if (!library) {
    std::fprintf(stderr, "index_reader: %s\n", library.error().to_string().c_str());
    return 1;
  }
  for (const penumbra::LibraryVariant& entry : library->variants) {
    std::string targets;
    for (const penumbra::Target target : entry.variant.targets) {
      targets += std::string(targets.empty() ? "" : " ") + std::string(to_string(target));
    }
    std::printf("index_reader: %s: %s\n", entry.variant.name.c_str(), targets.c_str());
  }
  return library->variants.empty() ? 1 : 0;
}
