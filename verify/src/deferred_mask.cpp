// The deferred pass checked as an engine runs it (docs/deferred-mask.md):
// the camera's depth of the report's stage, written as the target's API
// stores it, and the receivers the pass rebuilds from it, rebuilt here in
// double precision from the same stored depths.
#include <algorithm>
#include <cmath>
#include <span>
#include <tuple>
#include <utility>
#include <vector>

#include "backend.hpp"
#include "camera_stage.hpp"
#include "penumbra/model/map_encoding.hpp"
#include "penumbra/model/target_traits.hpp"

namespace penumbra {
namespace {

// The inverse of `m` by Gauss-Jordan elimination with partial pivoting; a
// camera's view-projection is well conditioned.
Matrix4 inverse(Matrix4 m) {
  Matrix4 out{};
  for (int i = 0; i < 4; ++i) out[i][i] = 1.0;
  for (int c = 0; c < 4; ++c) {
    int pivot = c;
    for (int r = c + 1; r < 4; ++r) {
      if (std::abs(m[r][c]) > std::abs(m[pivot][c])) pivot = r;
    }
    std::swap(m[c], m[pivot]);
    std::swap(out[c], out[pivot]);
    const double scale = 1.0 / m[c][c];
    for (int k = 0; k < 4; ++k) {
      m[c][k] *= scale;
      out[c][k] *= scale;
    }
    for (int r = 0; r < 4; ++r) {
      if (r == c || m[r][c] == 0.0) continue;
      const double factor = m[r][c];
      for (int k = 0; k < 4; ++k) {
        m[r][k] -= factor * m[c][k];
        out[r][k] -= factor * out[c][k];
      }
    }
  }
  return out;
}

// How a float32 shader may round the rebuilding: each product and sum on
// its own, or fused (multiply-adds, divisions as reciprocal products), as
// GPU compilers emit it.
enum class Rounding { separate, fused };

// `m` times `v` in `Real`, column by column as a shader multiplies.
template <typename Real>
std::array<Real, 4> times_in(const Matrix4& m, const std::array<Real, 4>& v,
                             Rounding rounding = Rounding::separate) {
  std::array<Real, 4> out{};
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) {
      out[r] = rounding == Rounding::fused ? std::fma(Real(m[r][c]), v[c], out[r])
                                           : out[r] + Real(m[r][c]) * v[c];
    }
  }
  return out;
}

// a / b as `rounding` computes it.
template <typename Real>
Real quotient(Real a, Real b, Rounding rounding) {
  return rounding == Rounding::fused ? a * (Real(1) / b) : a / b;
}

// Column `c` of `m`, as ShadowParams' members hold matrices.
std::array<float, 4> column(const Matrix4& m, int c) {
  return {float(m[0][c]), float(m[1][c]), float(m[2][c]), float(m[3][c])};
}

// How the engine stores its camera's depth: clip z / w = a depth + b, and
// the depth it clears to (no surface).
struct DepthConvention {
  double a = 1.0;
  double b = 0.0;
  float clear = 1.0f;
};

// `target`'s API's convention: z / w in [0, 1] on Direct3D, [-1, 1] on the
// GL targets (camera_clip()'s), reversed (near at 1, cleared to 0) when
// `reversed`, as an engine with a reversed-Z shadow map reverses its camera.
DepthConvention depth_convention(Target target, bool reversed) {
  DepthConvention out;
  if (!traits(target).is_hlsl) out = {2.0, -1.0, 1.0f};
  // depth' = 1 - depth: z / w = a (1 - depth') + b.
  if (reversed) out = {-out.a, out.a + out.b, 0.0f};
  return out;
}

// The camera's depth buffer as stored: the ray cast's surface per pixel,
// the clear where it hits none.
FloatImage camera_depth(const reference::StageView& view, const Matrix4& camera,
                        const DepthConvention& convention, int width, int height) {
  FloatImage out(width, height, 1);
  for (std::size_t k = 0; k < out.data.size(); ++k) {
    if (view.surfaces[k] == reference::Surface::none) {
      out.data[k] = convention.clear;
      continue;
    }
    const auto& p = view.points[k];
    const std::array<double, 4> clip = times_in<double>(camera, {p[0], p[1], p[2], 1.0});
    out.data[k] = float((clip[2] / clip[3] - convention.b) / convention.a);
  }
  return out;
}

// (u, v, z_r) per pixel as the deferred pass rebuilds it from `depth`
// (shaderlib/passes/deferred.frag), in `Real`: double for the receivers
// themselves, float for a float32 shader's rounding of them; `nudge` moves
// each pixel's screen_uv, as its interpolation may.
template <typename Real>
FloatImage rebuilt_receivers(const FloatImage& depth, const Matrix4& camera_inverse,
                             const Matrix4& light, const LightClipDepth& light_depth,
                             const DepthConvention& convention, double v_sign,
                             Rounding rounding = Rounding::separate,
                             std::array<double, 2> nudge = {0.0, 0.0}) {
  FloatImage out(depth.width, depth.height, 3);
  const Real half(0.5), one(1.0), two(2.0), sign = static_cast<Real>(v_sign);
  for (int j = 0; j < depth.height; ++j) {
    for (int i = 0; i < depth.width; ++i) {
      const Real d = depth.at(i, j);
      if (depth.at(i, j) == convention.clear) {
        out.at(i, j, 0) = out.at(i, j, 1) = 0.5f;
        out.at(i, j, 2) = 0.0f;
        continue;
      }
      const Real s = (Real(i) + half) / Real(depth.width) + Real(nudge[0]);
      const Real t = (Real(j) + half) / Real(depth.height) + Real(nudge[1]);
      const std::array<Real, 4> clip{two * s - one, (t - half) / sign,
                                     d * Real(convention.a) + Real(convention.b), one};
      std::array<Real, 4> world = times_in(camera_inverse, clip, rounding);
      const Real w = world[3];
      for (Real& c : world) c = quotient(c, w, rounding);
      const std::array<Real, 4> lit = times_in(light, world, rounding);
      out.at(i, j, 0) = float(half + half * quotient(lit[0], lit[3], rounding));
      out.at(i, j, 1) = float(half + sign * quotient(lit[1], lit[3], rounding));
      out.at(i, j, 2) = float(light_depth.linear_z(lit[2], lit[3]));
    }
  }
  return out;
}

// A first-order bound on how far any float32 evaluation of the rebuilding
// may put each receiver channel, whatever order or fusing a compiler
// chooses: each four-term product of a matrix row (the matrix rounded to
// float) within 5u of its terms' magnitudes, each quotient within 5u (2.5
// ulp), u = 2^-24, and every input's error carried through.
FloatImage rebuild_error_bound(const FloatImage& depth, const Matrix4& camera_inverse,
                               const Matrix4& light, const LightClipDepth& light_depth,
                               const DepthConvention& convention, double v_sign) {
  constexpr double u = 0x1p-24;
  using Vector = std::array<double, 4>;
  // m v and its error, with `error` v's.
  auto times = [&](const Matrix4& m, const Vector& v, const Vector& error) {
    std::pair<Vector, Vector> out{};
    for (int r = 0; r < 4; ++r) {
      for (int c = 0; c < 4; ++c) {
        out.first[r] += m[r][c] * v[c];
        out.second[r] += 5.0 * u * std::abs(m[r][c] * v[c]) + std::abs(m[r][c]) * error[c];
      }
    }
    return out;
  };
  // a / b and its error.
  auto ratio = [&](double a, double ea, double b, double eb) {
    const double q = a / b;
    return std::pair{q, (ea + std::abs(q) * eb) / std::abs(b) + 5.0 * u * std::abs(q)};
  };
  FloatImage out(depth.width, depth.height, 3);
  for (int j = 0; j < depth.height; ++j) {
    for (int i = 0; i < depth.width; ++i) {
      const double d = depth.at(i, j);
      if (depth.at(i, j) == convention.clear) continue;
      const double s = (i + 0.5) / depth.width, t = (j + 0.5) / depth.height;
      const Vector clip{2.0 * s - 1.0, (t - 0.5) / v_sign, d * convention.a + convention.b, 1.0};
      const Vector clip_error{u * std::abs(clip[0]), u * std::abs(clip[1]),
                              2.0 * u * (std::abs(d * convention.a) + std::abs(convention.b)), 0.0};
      const auto [world, world_error] = times(camera_inverse, clip, clip_error);
      Vector point{}, point_error{};
      for (int c = 0; c < 4; ++c) {
        std::tie(point[c], point_error[c]) =
            ratio(world[c], world_error[c], world[3], world_error[3]);
      }
      const auto [lit, lit_error] = times(light, point, point_error);
      const auto [x, ex] = ratio(lit[0], lit_error[0], lit[3], lit_error[3]);
      const auto [y, ey] = ratio(lit[1], lit_error[1], lit[3], lit_error[3]);
      out.at(i, j, 0) = float(0.5 * ex + u * (0.5 + 0.5 * std::abs(x)));
      out.at(i, j, 1) = float(std::abs(v_sign) * ey + u * (0.5 + std::abs(v_sign * y)));
      if (!light_depth.orthographic) {
        out.at(i, j, 2) = float(lit_error[3]);
      } else {
        const auto [z, ez] = ratio(lit[2], lit_error[2], lit[3], lit_error[3]);
        const double spread = std::abs(light_depth.far_plane - light_depth.near_plane);
        const double scale = light_depth.zero_to_one ? 1.0 : 0.5;
        out.at(i, j, 2) =
            float(scale * spread * ez +
                  4.0 * u * (std::abs(light_depth.near_plane) + std::abs(light_depth.far_plane)));
      }
    }
  }
  return out;
}

}  // namespace

Result<EngineFormCheck> check_deferred_mask(Engine& engine, Backend& backend, CameraStages& stages,
                                            PictureReferences& references, const Library& library,
                                            const LibraryVariant& entry, Target target,
                                            std::optional<int> cascade) {
  const auto pass = entry.reflection.find(PassKind::deferred);
  if (pass == entry.reflection.end() || !pass->second.contains(target)) {
    return make_error(
        Error::Kind::bad_input, entry.variant.name,
        "the library has no deferred pass for target " + std::string(to_string(target)));
  }
  PENUMBRA_TRY_ASSIGN(const CameraStage* stage, stages.get(library, entry, target, cascade));
  const CameraStage& camera = *stage;
  EngineFormCheck check = started_check(entry, target, backend, cascade);
  const Matrix4 camera_matrix = camera_clip(camera.stage, camera.width, camera.height, target);
  const Matrix4 camera_inverse = inverse(camera_matrix);
  const LightClipDepth light_depth =
      light_clip_depth(camera.stage.scene.light, camera.fixture.far_plane(), target);
  const Matrix4 light = light_clip(camera.stage.scene.light, light_depth, target);
  const DepthConvention convention = depth_convention(
      target, map_encoding(entry.variant.keys) == MapEncoding::perspective_reversed);
  DeferredDraw draw;
  draw.library = &library;
  draw.entry = &entry;
  draw.target = target;
  draw.camera_depth =
      camera_depth(camera.view, camera_matrix, convention, camera.width, camera.height);
  draw.params = camera.fixture.params;
  for (int c = 0; c < 4; ++c) {
    draw.params["camera_inverse_" + std::to_string(c)] = column(camera_inverse, c);
    draw.params["light_view_proj_" + std::to_string(c)] = column(light, c);
  }
  draw.params["camera_depth_range"] = {float(convention.a), float(convention.b), convention.clear,
                                       0.0f};
  PENUMBRA_TRY_ASSIGN(const SceneOutput drawn,
                      backend.run_deferred(draw, camera.fixture, check.execution));

  const double v_sign = traits(target).is_hlsl ? -0.5 : 0.5;
  const FloatImage receivers = rebuilt_receivers<double>(draw.camera_depth, camera_inverse, light,
                                                         light_depth, convention, v_sign);
  // The receivers as the pass may have rebuilt them in float32.
  const auto rounded = [&] {
    std::vector<FloatImage> out;
    for (Rounding rounding : {Rounding::separate, Rounding::fused}) {
      out.push_back(rebuilt_receivers<float>(draw.camera_depth, camera_inverse, light, light_depth,
                                             convention, v_sign, rounding));
    }
    // screen_uv within 2 ulps of the pixel's centre, along each axis.
    constexpr double kNudge = 0x1p-22;
    std::vector<FloatImage> nudged;
    for (const std::array<double, 2> nudge : {std::array{kNudge, 0.0}, std::array{0.0, kNudge}}) {
      nudged.push_back(rebuilt_receivers<double>(draw.camera_depth, camera_inverse, light,
                                                 light_depth, convention, v_sign,
                                                 Rounding::separate, nudge));
    }
    const FloatImage error_bound = rebuild_error_bound(draw.camera_depth, camera_inverse, light,
                                                       light_depth, convention, v_sign);
    for (FloatImage& bound : receiver_bounds(entry.variant, receivers, out, nudged, error_bound)) {
      out.push_back(std::move(bound));
    }
    return out;
  };
  PENUMBRA_TRY(judge_picture(check, engine, entry, camera, drawn.own_stored_depth, receivers,
                             drawn.visibility, 0, rounded, &references));
  return check;
}

Result<EngineFormCheck> check_deferred_mask(Engine& engine, const Library& library,
                                            const LibraryVariant& entry, Target target,
                                            DepthFormat map_format) {
  const std::unique_ptr<Backend> vulkan = vulkan_backend(engine);
  CameraStages stages(engine, map_format);
  PictureReferences references;
  return check_deferred_mask(engine, *vulkan, stages, references, library, entry, target, {});
}

}  // namespace penumbra
