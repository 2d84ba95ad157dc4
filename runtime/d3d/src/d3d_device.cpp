#include "d3d_device.hpp"

#include <utility>

#include "penumbra/model/map_encoding.hpp"
#include "penumbra/support/full_screen_triangle.hpp"
#include "penumbra/support/image_checks.hpp"
#include "penumbra/support/minmax_levels.hpp"

namespace penumbra::d3d {
namespace {

// A target of the runtime, for the reflection's format names.
Target api_target(D3dRuntime runtime) {
  switch (runtime) {
    case D3dRuntime::d3d9:
      return Target::hlsl_dx9;
    case D3dRuntime::d3d10:
      return Target::hlsl_dx10;
    case D3dRuntime::d3d11:
      break;
  }
  return Target::hlsl_dx11;
}

// The render target a pass draws into: its format and floats per texel.
struct TargetFormat {
  std::string format;
  int channels = 0;
};

Result<TargetFormat> target_format(D3dRuntime runtime, const D3dPass& pass,
                                   const std::string& where) {
  if (pass.reflection.render_targets.empty()) {
    return make_error(Error::Kind::bad_input, where, "its reflection lists no render target");
  }
  const std::string& format = pass.reflection.render_targets.front().format;
  const auto parsed = parse_api_format(api_target(runtime), format);
  if (!parsed) {
    return make_error(Error::Kind::bad_input, where,
                      "render target format '" + format + "' is not one of " +
                          allowed_api_formats(api_target(runtime)));
  }
  return TargetFormat{format, static_cast<int>(texel_components(*parsed))};
}

// `triangles` (x, y, z per vertex) as a vertex buffer of the job's.
DrawGeometry triangle_list(Job& job, std::span<const std::array<float, 3>> triangles) {
  std::vector<float> vertices;
  for (const auto& v : triangles) vertices.insert(vertices.end(), v.begin(), v.end());
  return {job.vertices(vertices), static_cast<unsigned>(triangles.size())};
}

// The map's typeless texture and the view it is read through: written
// through its depth view, read through R32_FLOAT views (docs/engines/d3d10.md),
// or an engine's D24 or D16 map's unorm views ("Using your own shadow map").
std::pair<std::string, std::string> map_formats(D3dRuntime runtime, DepthFormat format) {
  switch (format) {
    case DepthFormat::d24_unorm:
      return {"DXGI_FORMAT_R24G8_TYPELESS", "DXGI_FORMAT_R24_UNORM_X8_TYPELESS"};
    case DepthFormat::d16_unorm:
      return {"DXGI_FORMAT_R16_TYPELESS", "DXGI_FORMAT_R16_UNORM"};
    case DepthFormat::d32_float:
      break;
  }
  return {std::string(api_format(api_target(runtime), TextureFormat::d32_float)), ""};
}

}  // namespace

runtime::Program D3dDevice::load(const D3dPass& pass) {
  programs_.push_back(pass);
  return runtime::Program{static_cast<int>(programs_.size())};
}

runtime::Texture D3dDevice::hold(Held held, int width, int height) {
  const int id = next_id_++;
  textures_.emplace(id, std::move(held));
  return runtime::Texture{id, width, height};
}

Result<D3dDevice::Held> D3dDevice::find(runtime::Texture texture, std::string_view where) const {
  const auto found = textures_.find(texture.id);
  if (found == textures_.end()) {
    return make_error(Error::Kind::internal, std::string(where),
                      "texture " + std::to_string(texture.id) + " is not on this device");
  }
  return found->second;
}

runtime::Texture D3dDevice::adopt(const D3dMap& map) {
  return hold({map.id, map.format, map.view_format, 1, 1}, map.width, map.height);
}

D3dMap D3dDevice::map(runtime::Texture texture) const {
  const Held& held = textures_.at(texture.id);
  D3dMap out;
  out.id = held.id;
  out.width = texture.width;
  out.height = texture.height;
  out.format = held.format;
  out.view_format = held.view_format;
  return out;
}

DrawGeometry D3dDevice::full_screen_triangle() {
  if (!triangle_) {
    triangle_ = DrawGeometry{
        job_.vertices(std::vector<float>(kFullScreenTriangle.begin(), kFullScreenTriangle.end())),
        3};
  }
  return *triangle_;
}

Result<runtime::Texture> D3dDevice::upload(TextureId as, const FloatImage& image) {
  const Target target = api_target(job_.runtime());
  Held held;
  std::vector<float> texels;
  switch (as) {
    case TextureId::receivers:
    case TextureId::scene_colour:
      held.format = api_format(target, TextureFormat::rgba32_float);
      held.channels = 4;
      texels = receivers_to_rgba(image);
      break;
    case TextureId::camera_depth:
      // What a Direct3D 10/11 engine's typeless depth buffer's shader view
      // reads, and what a Direct3D 9 engine draws its depth into.
      PENUMBRA_TRY(check_normalized_depth(image));
      held.format = api_format(target, TextureFormat::r32_float);
      held.channels = 1;
      texels = image.data;
      break;
    case TextureId::shadow_depth:
      // A map as the depth pass would have drawn it in D32 (Direct3D 9's
      // R32F), kept on the host like one: an engine's atlas, say, or its
      // array of maps (Direct3D 10 and 11).
      PENUMBRA_TRY(check_normalized_depth(image));
      held.channels = 1;
      texels = image.data;
      if (job_.runtime() == D3dRuntime::d3d9) {
        if (image.layers > 0) {
          return make_error(Error::Kind::bad_input, "shadow map",
                            "Direct3D 9 has no texture arrays; an array of " +
                                std::to_string(image.layers) + " layers cannot be uploaded");
        }
        held.format = api_format(target, TextureFormat::r32_float);
        held.id = job_.texture(held.format, image.width, image.height, 1, "input");
      } else {
        std::tie(held.format, held.view_format) =
            map_formats(job_.runtime(), DepthFormat::d32_float);
        held.layers = image.layers;
        held.id =
            job_.texture(held.format, image.width, image.layer_height(), 1, "depth", image.layers);
      }
      job_.keep(held.id);
      job_.upload(held.id, 0, texels);
      return hold(std::move(held), image.width, image.layer_height());
    default:
      return make_error(Error::Kind::bad_input, std::string(describe(as).name),
                        "the Direct3D runtime uploads maps, receivers, a scene colour and a "
                        "camera's depth, and no other texture");
  }
  held.id = job_.texture(held.format, image.width, image.height, 1, "input");
  job_.upload(held.id, 0, texels);
  return hold(std::move(held), image.width, image.height);
}

Result<PassTextures> D3dDevice::textures(const runtime::Draw& draw) const {
  PassTextures out;
  for (const runtime::Offer& offer : draw.inputs) {
    PENUMBRA_TRY_ASSIGN(const Held held, find(offer.texture, draw.where));
    out[offer.as] = {held.id, held.view_format};
  }
  return out;
}

Result<runtime::Drawn> D3dDevice::draw(const runtime::Draw& draw) {
  const D3dPass& pass = programs_.at(static_cast<std::size_t>(draw.program.id - 1));
  const std::string where = "the " + draw.where;
  if (draw.pass == PassKind::depth) return draw_map(draw, pass, where);
  PENUMBRA_TRY_ASSIGN(const PassTextures bound, textures(draw));
  PENUMBRA_TRY_ASSIGN(const TargetFormat format, target_format(job_.runtime(), pass, where));
  const int output = job_.texture(format.format, draw.width, draw.height, 1, "target");
  DrawTarget target{output, 0, std::nullopt, draw.width, draw.height, std::nullopt, std::nullopt};
  DrawGeometry geometry;
  if (draw.triangles.empty()) {
    geometry = full_screen_triangle();
  } else {
    // An engine's own geometry, with its camera's own depth buffer: the
    // nearest surface wins, as in an engine.
    const std::string depth_format =
        job_.runtime() == D3dRuntime::d3d9
            ? pass.reflection.depth_target
            : std::string(api_format(api_target(job_.runtime()), TextureFormat::d32_float));
    target.depth = job_.texture(depth_format, draw.width, draw.height, 1, "depth");
    target.clear_colour = std::array<float, 4>{1.0f, 1.0f, 1.0f, 1.0f};
    target.clear_depth = 1.0f;
    geometry = triangle_list(job_, draw.triangles);
  }
  PENUMBRA_TRY(draw_pass(job_, pass, where, bound, draw.params, target, geometry));
  return runtime::Drawn{
      hold({output, format.format, "", format.channels, 1}, draw.width, draw.height), std::nullopt};
}

Result<runtime::Drawn> D3dDevice::draw_map(const runtime::Draw& draw, const D3dPass& pass,
                                           const std::string& where) {
  // A reversed-Z map is cleared to 0, its far plane, and keeps the greater depth.
  const bool reversed = pass.reflection.map_encoding == MapEncoding::perspective_reversed;
  const float far = reversed ? 0.0f : 1.0f;
  DrawTarget target{std::nullopt, 0,   std::nullopt, draw.width, draw.height,
                    std::nullopt, far, reversed};
  Held held;
  held.channels = 1;
  if (job_.runtime() == D3dRuntime::d3d9) {
    // The whitepaper's map: an R32F colour target, and a depth buffer that
    // only depth-tests (docs/engines/d3d9.md).
    PENUMBRA_TRY_ASSIGN(const TargetFormat colour, target_format(job_.runtime(), pass, where));
    held.format = colour.format;
    held.id = job_.texture(held.format, draw.width, draw.height, 1, "target");
    target.colour = held.id;
    target.clear_colour = std::array<float, 4>{far, far, far, far};
    target.depth = job_.texture(pass.reflection.depth_target, draw.width, draw.height, 1, "depth");
  } else {
    std::tie(held.format, held.view_format) = map_formats(job_.runtime(), draw.depth_format);
    held.id = job_.texture(held.format, draw.width, draw.height, 1, "depth");
    target.depth = held.id;
  }
  // The caller keeps the map (D3dEngine::release frees it).
  job_.keep(held.id);
  PENUMBRA_TRY(
      draw_pass(job_, pass, where, {}, draw.params, target, triangle_list(job_, draw.triangles)));
  return runtime::Drawn{hold(std::move(held), draw.width, draw.height), std::nullopt};
}

Result<runtime::Texture> D3dDevice::gather_mip(runtime::Texture map,
                                               std::span<const runtime::Texture> levels) {
  PENUMBRA_TRY_ASSIGN(const Held first, find(levels.front(), "the min-max mip"));
  const int side = minmax_chain_side(map.width, map.height);
  const int count = static_cast<int>(levels.size());
  const int chain = job_.texture(first.format, side, side, count, "target");
  for (int l = 0; l < count; ++l) {
    PENUMBRA_TRY_ASSIGN(const Held level,
                        find(levels[static_cast<std::size_t>(l)], "the min-max mip"));
    job_.copy(level.id, 0, chain, l);
  }
  return hold({chain, first.format, "", first.channels, count}, levels.front().width,
              levels.front().height);
}

Result<std::vector<FloatImage>> D3dDevice::read_all(std::span<const runtime::Texture> textures) {
  std::vector<std::size_t> reads;
  for (runtime::Texture texture : textures) {
    PENUMBRA_TRY_ASSIGN(const Held held, find(texture, "readback"));
    reads.push_back(
        job_.read(held.id, 0, texture.width, texture.height, held.channels, held.layers));
  }
  PENUMBRA_TRY(job_.run());
  std::vector<FloatImage> images;
  for (std::size_t read : reads) images.push_back(job_.take(read));
  return images;
}

void D3dDevice::release(runtime::Texture /*texture*/) {}

}  // namespace penumbra::d3d
