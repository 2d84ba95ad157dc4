// D3dDevice: the pass driver's Device (penumbra/runtime/device.hpp) on a
// D3dEngine's host. Every call writes into one job list; read_all() sends
// what was written since the last read and waits for the host's answer, so
// a chain of passes is one round trip. Textures are the job's and released
// after it, except the maps the depth pass drew, which the caller keeps.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "job.hpp"
#include "pass_binding.hpp"
#include "penumbra/d3d/engine.hpp"
#include "penumbra/runtime/device.hpp"

namespace penumbra::d3d {

class D3dDevice final : public runtime::Device {
 public:
  explicit D3dDevice(D3dEngine& engine) : job_(engine) {}

  // `pass` as the driver's Program; its reflection must outlive the device.
  runtime::Program load(const D3dPass& pass);
  // A map the depth pass drew (in this job or an earlier one).
  runtime::Texture adopt(const D3dMap& map);
  // What the device knows of a map it drew: its id, formats and size (its
  // texels once read).
  D3dMap map(runtime::Texture texture) const;

  Result<runtime::Texture> upload(TextureId as, const FloatImage& image) override;
  Result<runtime::Drawn> draw(const runtime::Draw& draw) override;
  Result<runtime::Texture> gather_mip(runtime::Texture map,
                                      std::span<const runtime::Texture> levels) override;
  Result<std::vector<FloatImage>> read_all(std::span<const runtime::Texture> textures) override;
  // The job's textures live until the device ends: release() frees nothing sooner.
  void release(runtime::Texture texture) override;

 private:
  // A host texture: its id, the view it is read through (an engine's D24
  // or D16 map) and what it holds.
  struct Held {
    int id = 0;
    std::string format;
    std::string view_format;
    int channels = 0;
    int levels = 1;
    int layers = 0;  // a 2D array's (an engine's array of maps), else 0
  };

  runtime::Texture hold(Held held, int width, int height);
  Result<Held> find(runtime::Texture texture, std::string_view where) const;
  Result<PassTextures> textures(const runtime::Draw& draw) const;
  Result<runtime::Drawn> draw_map(const runtime::Draw& draw, const D3dPass& pass,
                                  const std::string& where);
  DrawGeometry full_screen_triangle();

  Job job_;
  std::vector<D3dPass> programs_;  // Program::id - 1
  std::map<int, Held> textures_;
  std::optional<DrawGeometry> triangle_;  // the job's full-screen triangle
  int next_id_ = 1;
};

}  // namespace penumbra::d3d
