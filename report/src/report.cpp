// The report streams: each run's pictures are written as soon as it is done
// and only its figures are kept (plus, per technique, the crop of its best
// picture for the contact sheet), so memory does not grow with the library.
#include "penumbra/report/report.hpp"

#include <tbb/info.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <map>
#include <mutex>
#include <optional>
#include <tuple>

#include "cost_chart.hpp"
#include "gpu_costs.hpp"
#include "html_page.hpp"
#include "penumbra/compiler/build.hpp"
#include "penumbra/reference/stage.hpp"
#include "penumbra/report/figures.hpp"
#include "penumbra/support/atomic_file.hpp"
#include "pixel_font.hpp"
#include "png_file.hpp"
#include "shading.hpp"

namespace penumbra {
namespace {

namespace fs = std::filesystem;
using report::Crop;
using report::Picture;

// The slab's shadow over the low block and the ground, and the pole's foot
// with its shadow's wide end.
constexpr Crop kContactCrop{130, 106, 110, 94};
constexpr int kContactScale = 2;

struct ContactPanel {
  nlohmann::json row;  // the run's row, for the page's caption
  Picture crop;
  // Which run stands for its technique: SPIR-V on Vulkan before any other
  // (hlsl_dx9 caps some loops), then the lowest exact_penumbra_mae, then the
  // earliest run (so that the choice does not depend on the threads' order).
  std::tuple<bool, double, std::size_t> rank;
};

class ReportWriter {
 public:
  ReportWriter(const Library& library, fs::path dir, fs::path final_dir)
      : library_(library), dir_(std::move(dir)), final_dir_(std::move(final_dir)) {
    stage_ = reference::report_stage();
    view_ = reference::view(stage_, stage_.scene.receivers_width, stage_.scene.receivers_height);
    exact_ = reference::exact_visibility_image(stage_.scene, view_);
  }

  PictureScene scene() const { return {stage_.scene, view_.receivers}; }

  // Called from several threads at once: each run's files are its own, and
  // what is shared is taken under the mutex.
  Status add(PictureRun&& run) {
    nlohmann::json row = {{"variant", run.variant},
                          {"technique", to_string(run.technique)},
                          {"target", to_string(run.target)},
                          {"path", run.backend},
                          {"device", run.device},
                          {"front_end", run.execution.front_end},
                          {"shims", run.execution.shims},
                          {"files", files(run.variant, run.target)}};
    if (!run.not_executed.empty() || !run.error.empty()) {
      row["status"] = run.error.empty() ? "not executed" : "failed";
      row["reason"] = run.error.empty() ? run.not_executed : run.error;
      const std::lock_guard lock(mutex_);
      rows_.emplace(run.order, std::move(row));
      return {};
    }
    const std::string base =
        "images/" + run.variant + "/" + std::string(to_string(run.target)) + "-" + run.backend;
    std::error_code ec;
    fs::create_directories(dir_ / ("images/" + run.variant), ec);
    if (ec) return make_error(Error::Kind::io, (dir_ / "images").string(), ec.message());
    const Picture picture = report::shade(view_, run.visibility);
    PENUMBRA_TRY(report::write_png(dir_ / (base + ".png"), picture));
    PENUMBRA_TRY(report::write_png(dir_ / (base + "-exact-error.png"),
                                   report::heatmap(view_, run.visibility, exact_)));
    PENUMBRA_TRY(report::write_png(dir_ / (base + "-reference-error.png"),
                                   report::heatmap(view_, run.visibility, run.reference)));
    const report::Figures figures = report::measure(view_, exact_, run.visibility, run.reference,
                                                    run.reference_ambiguous, run.texel_reads);
    row["status"] = "ok";
    row["figures"] = report::to_json(figures);
    row["run_ms"] = run.run_seconds * 1e3;
    row["image"] = base + ".png";
    row["exact_error_image"] = base + "-exact-error.png";
    row["reference_error_image"] = base + "-reference-error.png";
    const std::lock_guard lock(mutex_);
    keep_for_contact_sheet(run, figures, picture, row);
    rows_.emplace(run.order, std::move(row));
    return {};
  }

  // The cost chart's GPU times, measured after the pictures.
  void time_costs(Engine& engine, const ReportOptions& options,
                  const DiagnosticConsumer& diagnostics) {
    gpu_ = options.gpu_cost;
    timed_ = report::time_variants(library_, engine, scene(), view_, exact_, options.pictures, gpu_,
                                   diagnostics);
  }

  Status finish(const Engine& engine) {
    const Picture truth = report::shade(view_, exact_);
    PENUMBRA_TRY(report::write_png(dir_ / "truth.png", truth));
    std::vector<Picture> crops{
        report::labelled(report::crop_scaled(truth, kContactCrop, kContactScale), "exact")};
    nlohmann::json panels = nlohmann::json::array({{{"label", "exact area light"}}});
    for (const auto& [technique, panel] : best_) {
      crops.push_back(report::labelled(panel.crop, panel.row["variant"].get<std::string>()));
      panels.push_back({{"label", to_string(technique)},
                        {"variant", panel.row["variant"]},
                        {"target", panel.row["target"]},
                        {"path", panel.row["path"]},
                        {"exact_penumbra_mae", std::get<1>(panel.rank)}});
    }
    PENUMBRA_TRY(report::write_png(dir_ / "contact_sheet.png", report::side_by_side(crops, 4)));
    std::vector<report::CostPoint> points;
    for (const report::TimedVariant& t : timed_) points.push_back(t.point);
    PENUMBRA_TRY(report::write_png(dir_ / "cost_chart.png", report::cost_chart_picture(points)));
    const report::Region measured = report::region(view_, exact_);
    nlohmann::json json = {
        {"generator", "penumbra " + std::string(penumbra_version())},
        {"library", fs::relative(fs::absolute(library_.root), fs::absolute(final_dir_)).string()},
        {"device", engine.device_info().name},
        {"stage",
         {{"width", view_.receivers.width},
          {"height", view_.receivers.height},
          {"map_width", stage_.scene.map_width},
          {"map_height", stage_.scene.map_height},
          {"light_half_width", stage_.scene.light.light_world_size},
          {"measured_pixels", measured.measured},
          {"penumbra_pixels", measured.penumbra}}},
        {"heatmap_full_scale", report::kHeatmapFullScale},
        {"truth_image", "truth.png"},
        {"contact_sheet",
         {{"image", "contact_sheet.png"},
          {"crop", {kContactCrop.x, kContactCrop.y, kContactCrop.width, kContactCrop.height}},
          {"panels", panels}}},
        {"gpu_cost", report::to_json(timed_, gpu_)},
        {"rows", rows()}};
    PENUMBRA_TRY(write_file_atomic(dir_ / "report.json", json.dump(2) + "\n"));
    return write_file_atomic(dir_ / "index.html",
                             report::html_page(json, report::cost_chart_svg(points)));
  }

 private:
  // The library's files of `variant` for `target`, as links from the report.
  nlohmann::json files(const std::string& variant, Target target) const {
    nlohmann::json links = nlohmann::json::array();
    const LibraryVariant* entry = library_.find(variant);
    if (!entry) return links;
    const fs::path from = fs::absolute(final_dir_);
    const auto link = [&](const std::string& relative) {
      links.push_back(
          {{"name", fs::path(relative).filename().string()},
           {"href", fs::relative(fs::absolute(library_.root / relative), from).generic_string()}});
    };
    for (const auto& [pass, targets] : entry->passes) {
      const auto it = targets.find(target);
      if (it == targets.end()) continue;
      const PassFiles& f = it->second;
      link(f.vert);
      link(f.frag);
      if (f.vert_bytecode) link(f.vert_bytecode->path);
      if (f.frag_bytecode) link(f.frag_bytecode->path);
    }
    return links;
  }

  // The rows in run order.
  nlohmann::json rows() const {
    nlohmann::json rows = nlohmann::json::array();
    for (const auto& [order, row] : rows_) rows.push_back(row);
    return rows;
  }

  void keep_for_contact_sheet(const PictureRun& run, const report::Figures& figures,
                              const Picture& picture, const nlohmann::json& row) {
    const std::tuple<bool, double, std::size_t> rank{
        run.target != Target::spirv || run.backend != "vulkan", figures.exact_penumbra_mae,
        run.order};
    auto it = best_.find(run.technique);
    if (it != best_.end() && it->second.rank <= rank) return;
    best_[run.technique] = {row, report::crop_scaled(picture, kContactCrop, kContactScale), rank};
  }

  const Library& library_;
  fs::path dir_;
  fs::path final_dir_;
  reference::Stage stage_;
  reference::StageView view_;
  FloatImage exact_;
  std::mutex mutex_;                            // guards rows_ and best_
  std::map<std::size_t, nlohmann::json> rows_;  // by PictureRun::order
  std::map<Technique, ContactPanel> best_;      // per technique, the run its panel shows
  GpuCostOptions gpu_;
  std::vector<report::TimedVariant> timed_;  // the cost chart's variants
};

}  // namespace

Status check_report_directory(const fs::path& dir) {
  return check_replaceable_directory(dir, {"report", "report.json", "penumbra report"});
}

Status write_report(const Library& library, Engine& engine, const fs::path& dir,
                    const ReportOptions& options, const DiagnosticConsumer& diagnostics) {
  // The exact truth, computed as the writer is made, on no more threads than
  // the pictures.
  const int cores = tbb::info::default_concurrency();
  tbb::task_arena arena(options.pictures.jobs > 0 ? std::min(options.pictures.jobs, cores) : cores);
  std::optional<ReportWriter> writer;
  arena.execute(
      [&] { writer.emplace(library, dir, options.final_dir.empty() ? dir : options.final_dir); });
  const PictureScene scene = writer->scene();
  PENUMBRA_TRY(render_pictures(
      library, engine, scene, options.pictures,
      [&](PictureRun&& run) { return writer->add(std::move(run)); }, diagnostics));
  // After the pictures, one variant at a time: no CPU work beside the timings.
  writer->time_costs(engine, options, diagnostics);
  return writer->finish(engine);
}

}  // namespace penumbra
