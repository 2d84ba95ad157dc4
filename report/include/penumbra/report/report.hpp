// `penumbra report`: every variant of a built library pictured on the
// report's stage (reference/stage.hpp) through the runtime, measured against
// the CPU reference and the exact area-light truth, and written as PNGs,
// report.json and a static HTML page (docs/verification.md, "Report").
#pragma once

#include <filesystem>
#include <map>
#include <string>

#include "penumbra/library/library.hpp"
#include "penumbra/verify/gpu_cost.hpp"
#include "penumbra/verify/pictures.hpp"

namespace penumbra {

struct ReportOptions {
  PictureOptions pictures;  // which variants, targets and paths run
  // Where the report's links to the library's files point from: the folder
  // the report will finally be in (it may be written elsewhere first).
  std::filesystem::path final_dir;
  // How the cost chart's spirv variants are timed: fewer runs than the GPU
  // benchmark's 21, as the report times every variant (on lavapipe some
  // query passes take seconds).
  GpuCostOptions gpu_cost{.runs = 5};
};

// Writes the report of `library` into `dir` (an existing empty folder):
// index.html, report.json, truth.png, contact_sheet.png, cost_chart.png and
// images/.
// Errors: those of render_pictures and of writing the files.
Status write_report(const Library& library, Engine& engine, const std::filesystem::path& dir,
                    const ReportOptions& options, const DiagnosticConsumer& diagnostics);

// A report's files (path relative to its folder -> bytes) less what is
// timed: each row's run_ms (wall time), gpu_cost (timestamps) and the cost
// chart drawn from it (cost_chart.png, its SVG in index.html). Two reports
// of one library on one device are then equal whatever the thread count.
std::map<std::string, std::string> untimed_report_files(std::map<std::string, std::string> files);

// Whether `dir` may be replaced by a report: missing, empty, or a report
// that write_report() wrote (report.json whose "generator" is penumbra);
// bad_input naming the folder and what is allowed otherwise.
Status check_report_directory(const std::filesystem::path& dir);

}  // namespace penumbra
