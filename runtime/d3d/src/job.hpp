// One job list for the Direct3D host: the commands of one engine call
// (main.cpp's protocol), sent in one or more runs, the data files they read, and the targets to
// read back once the host answers. The textures and buffers it creates are the job's own and
// released with it, unless kept.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "penumbra/d3d/engine.hpp"
#include "penumbra/model/shader_contract.hpp"

namespace penumbra::d3d {

class Job {
 public:
  explicit Job(D3dEngine& engine);
  Job(const Job&) = delete;
  Job& operator=(const Job&) = delete;
  ~Job();

  D3dRuntime runtime() const { return engine_.runtime(); }

  // A texture (main.cpp's `texture` command); `usage` target, depth or input;
  // `layers` 0 for a 2D texture, else a 2D array of that many layers.
  int texture(std::string_view format, int width, int height, int levels, std::string_view usage,
              int layers = 0);
  // Leaves texture `id` on the host after the job (a map the engine keeps).
  void keep(int id);
  void upload(int id, int level, const std::vector<float>& texels);
  int vertices(const std::vector<float>& floats);
  // The bytecode's shader, loaded once per engine. Errors: a file that cannot be read.
  Result<int> shader(const std::filesystem::path& bytecode, std::string_view stage);
  // A constant texture (D3D9's disks), created once per engine from its texels.
  int constant_texture(std::string_view format, const TextureContents& contents);
  // Command lines as they are (a draw block).
  void append(const std::string& lines);
  void copy(int source, int source_level, int destination, int destination_level);
  // Reads level `level` back after run(): take(returned index); an array's
  // `layers` stacked (FloatImage::layers).
  std::size_t read(int id, int level, int width, int height, int channels, int layers = 0);

  // Sends the commands written since the last run and waits for the host's
  // answer; the host's error names the failing command.
  Status run();
  FloatImage take(std::size_t read);

 private:
  friend class penumbra::D3dEngine;  // sends the commands
  struct Read {
    std::filesystem::path file;
    FloatImage image;
  };

  std::filesystem::path data_file();

  D3dEngine& engine_;
  int number_;
  std::filesystem::path folder_;
  std::string commands_;
  std::vector<int> own_;  // released with the job
  std::vector<Read> reads_;
  std::size_t answered_ = 0;  // reads_ before it were read by an earlier run
  int files_ = 0;
};

}  // namespace penumbra::d3d
