#include <algorithm>
#include <regex>
#include <sstream>

#include "penumbra/compiler/targets.hpp"
#include "penumbra/support/file.hpp"
#include "stages/stages.hpp"
#include "targets/sm3_slots.hpp"
#include "vkd3d/run_vkd3d.hpp"

namespace penumbra {
namespace {

// One line of vkd3d-compiler's report on the file: "FILE:LINE:COL: E5000: text".
struct CompilerMessage {
  bool error = false;  // E####; else a warning (W####)
  int line = 0;
  std::string text;  // "LINE:COL: E5000: text", the file left out
};

// The messages about `source`; every other line (vkd3d's "Failed to compile
// shader" summary) goes to `other`.
std::vector<CompilerMessage> parse_messages(const std::string& output, const std::string& source,
                                            std::string& other) {
  static const std::regex kMessage(R"(^(\d+):(\d+): ([EW])\d+: .*$)");
  std::vector<CompilerMessage> out;
  std::istringstream lines(output);
  std::string line;
  while (std::getline(lines, line)) {
    std::smatch match;
    const std::string prefix = source + ":";
    const std::string rest = line.starts_with(prefix) ? line.substr(prefix.size()) : "";
    if (std::regex_match(rest, match, kMessage)) {
      out.push_back({match[3] == "E", std::stoi(match[1]), rest});
    } else if (!line.empty()) {
      other = line;
    }
  }
  return out;
}

// `number`'s line of `path`, trimmed, or empty.
std::string source_line(const std::filesystem::path& path, int number) {
  const Result<std::string> text = read_file(path);
  if (!text) return "";
  std::istringstream lines(*text);
  std::string line;
  for (int i = 1; std::getline(lines, line); ++i) {
    if (i == number) {
      const std::size_t first = line.find_first_not_of(" \t");
      return first == std::string::npos ? "" : line.substr(first);
    }
  }
  return "";
}

// "60 s" or "250 ms".
std::string duration_text(std::chrono::milliseconds limit) {
  if (limit.count() % 1000 == 0) return std::to_string(limit.count() / 1000) + " s";
  return std::to_string(limit.count()) + " ms";
}

}  // namespace

BytecodeStage::BytecodeStage(std::filesystem::path root, HlslCompilerOptions options)
    : root_(std::move(root)), options_(std::move(options)) {}

Status BytecodeStage::process(ShaderJob& job) const {
  const std::optional<BytecodeFormat> format = bytecode_format(job.target, job.stage);
  // The function form is not a whole shader: its tests compile it in one.
  if (!format || job.form == ShaderForm::function) return {};
  std::filesystem::path relative = job.output_path;
  relative.replace_extension(format->extension);
  const std::string source = (root_ / job.output_path).string();
  const std::filesystem::path output = root_ / relative;
  const std::string tool = "vkd3d-compiler " + format->profile + ": ";

  auto run = run_vkd3d(options_.compiler,
                       {"-x", "hlsl", "-p", format->profile, "-b", std::string(format->vkd3d_type),
                        "-e", "main", "-o", output.string(), source},
                       options_.timeout);
  if (!run) return run.error();
  // The message names the file as the library will: relative to its root.
  auto located = [&](const CompilerMessage& m) {
    const std::string line = source_line(source, m.line);
    return tool + job.output_path + ":" + m.text + (line.empty() ? "" : " [" + line + "]");
  };
  std::string other;
  const std::vector<CompilerMessage> messages = parse_messages(run->output, source, other);
  const auto first_error = std::ranges::find_if(messages, &CompilerMessage::error);
  for (const CompilerMessage& m : messages) {
    if (!m.error) job.diagnostics.push_back({Severity::warning, job.describe(), located(m)});
  }

  std::string failure;
  if (run->timed_out) {
    failure = tool + job.output_path + ": no bytecode after " + duration_text(options_.timeout) +
              " (the time limit, --hlsl-timeout)";
  } else if (first_error != messages.end()) {
    const auto errors = std::ranges::count_if(messages, &CompilerMessage::error);
    failure = located(*first_error) +
              (errors > 1 ? " (and " + std::to_string(errors - 1) + " more errors)" : "");
  } else if (run->exit_code != 0) {
    failure = tool + job.output_path + ": exit status " + std::to_string(run->exit_code) +
              (other.empty() ? "" : ": " + other);
  }
  std::error_code ec;
  if (!failure.empty()) {
    std::filesystem::remove(output, ec);  // vkd3d leaves an empty file behind
    return make_error(Error::Kind::compile, job.describe(), failure);
  }
  const std::uintmax_t size = std::filesystem::file_size(output, ec);
  if (ec || size == 0) {
    return make_error(Error::Kind::compile, job.describe(),
                      tool + "succeeded but wrote no bytecode to " + relative.string());
  }
  job.bytecode = BytecodeFile{relative.string(), format->profile, size};
  if (format->vkd3d_type == "d3dbc") return count_slots(job, output);
  return {};
}

// The slots are counted on the bytecode as shipped, disassembled by the same
// compiler: our own model of a Direct3D 9 compiler under-counted by 2-10x.
Status BytecodeStage::count_slots(ShaderJob& job, const std::filesystem::path& bytecode) const {
  const std::string tool = "vkd3d-compiler -b d3d-asm: ";
  auto run = run_vkd3d(options_.compiler, {"-x", "d3dbc", "-b", "d3d-asm", bytecode.string()},
                       options_.timeout);
  if (!run) return run.error();
  if (run->timed_out || run->exit_code != 0) {
    return make_error(Error::Kind::compile, job.describe(),
                      tool + "cannot disassemble " + job.bytecode->path + ": " + run->output);
  }
  const int slots = count_sm3_slots(run->output);
  job.bytecode->instruction_slots = slots;
  if (slots > kSm3MinimumSlots) {
    job.diagnostics.push_back(
        {Severity::warning, job.describe(),
         job.bytecode->profile + " bytecode of " + std::to_string(slots) +
             " instruction slots (vkd3d-compiler's count), over the " +
             std::to_string(kSm3MinimumSlots) + " every " + job.bytecode->profile +
             " device runs: it needs a device whose caps allow more (docs/targets.md)"});
  }
  return {};
}

}  // namespace penumbra
