// docs/shader-interface.md's tables of the ShadowParams members each pass
// reads, against the default library's glsl450 text. A member is read where
// the text names it through the block's instance (`params.light.zw`); a
// name without a swizzle reads all four components. Every target's text is
// cross-compiled from the same module, so they read the same members.
//
// The tables sit between `<!-- params-reads TABLE -->` and
// `<!-- end params-reads -->`: TABLE `techniques` has a row per technique
// (and one per technique's atlas variants, "pcss, map_layout atlas") and a
// column per form (query, deferred, function), TABLE `passes` a row
// per shared pass (reads). A cell lists `member.components` in block order,
// `-` for none, or `no such form`; a technique's cell is the union over its
// variants. Cells compare as guide_check's split_row() reads them: without
// backticks, `-` empty.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <memory>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "default_library.hpp"
#include "guide_check.hpp"
#include "penumbra/library/library.hpp"
#include "penumbra/model/map_layout.hpp"
#include "penumbra/support/file.hpp"

namespace penumbra::testing {
namespace {

namespace fs = std::filesystem;

// Table name -> row -> column -> cell.
using Tables = std::map<std::string, std::map<std::string, std::map<std::string, std::string>>>;
// Member -> the components read.
using Reads = std::map<std::string, std::set<char>>;

const fs::path kDoc = fs::path(PENUMBRA_SOURCE_DIR) / "docs" / "shader-interface.md";

// The members `text` reads through its ShadowParams block (none without one).
void add_reads(const std::string& text, Reads& reads) {
  static const std::regex block(R"(uniform\s+\w*ShadowParams\s*\{[^}]*\}\s*(\w+)\s*;)");
  std::smatch declared;
  if (!std::regex_search(text, declared, block)) return;
  const std::regex use("\\b" + declared[1].str() + R"(\.(\w+)(\.([xyzw]{1,4})\b)?)");
  const std::string after = declared.suffix();
  for (auto it = std::sregex_iterator(after.begin(), after.end(), use);
       it != std::sregex_iterator(); ++it) {
    const std::string components = (*it)[3].matched ? (*it)[3].str() : "xyzw";
    reads[(*it)[1].str()].insert(components.begin(), components.end());
  }
}

// `reads` as a cell: `member.components` in block order, empty for none.
// The deferred pass's matrices, columns _0 to _3 each read whole, are one
// `camera_inverse_*` or `light_view_proj_*`.
std::string cell(const Reads& reads) {
  static const std::vector<std::string> kOrder = {
      "shadow_map_size",    "light",       "sampling",         "screen_size",
      "source_size",        "minmax_info", "camera_inverse_0", "light_view_proj_0",
      "camera_depth_range", "map_tile",    "map_layer"};
  const auto whole = [&](const std::string& member) {
    const auto found = reads.find(member);
    return found != reads.end() && found->second.size() == 4;
  };
  std::vector<std::pair<std::string, std::string>> shown;  // member, as shown
  for (const auto& [member, components] : reads) {
    const std::string base = member.substr(0, member.size() - 1);
    const bool column = member.size() > 2 && member[member.size() - 2] == '_';
    if (column && whole(base + "0") && whole(base + "1") && whole(base + "2") &&
        whole(base + "3")) {
      if (member.ends_with("_0")) shown.emplace_back(member, base + "*");
      continue;
    }
    std::string swizzle;
    for (char c : std::string("xyzw")) {
      if (components.contains(c)) swizzle += c;
    }
    shown.emplace_back(member, member + "." + swizzle);
  }
  const auto rank = [&](const auto& entry) {
    return std::ranges::find(kOrder, entry.first) - kOrder.begin();
  };
  std::ranges::stable_sort(shown, {}, rank);
  std::string out;
  for (const auto& [member, text] : shown) out += (out.empty() ? "" : ", ") + text;
  return out;
}

// What the library's glsl450 files read, as the tables should list it.
Tables library_reads(const Library& library) {
  std::map<std::string, std::map<std::string, Reads>> techniques, passes;
  const auto add_file = [&](const std::string& relative, Reads& reads) {
    if (!relative.empty()) add_reads(read_file(library.root / relative).value(), reads);
  };
  for (const LibraryVariant& variant : library.variants) {
    // An atlas or array variant reads its light from elsewhere: a row of
    // its own.
    const MapLayout layout = map_layout(variant.variant.keys);
    const std::string technique =
        std::string(to_string(variant.variant.technique)) +
        (layout == MapLayout::single ? "" : ", map_layout " + std::string(to_string(layout)));
    for (const auto& [pass, targets] : variant.passes) {
      const auto files = targets.find(Target::glsl450);
      if (files == targets.end()) continue;
      const bool own = pass == PassKind::query || pass == PassKind::deferred;
      Reads& reads = own ? techniques[technique][std::string(to_string(pass))]
                         : passes[std::string(to_string(pass))]["reads"];
      add_file(files->second.vert, reads);
      add_file(files->second.frag, reads);
    }
    if (const auto form = variant.function.find(Target::glsl450); form != variant.function.end()) {
      add_file(form->second.file, techniques[technique]["function"]);
    }
  }
  Tables out;
  for (const auto& [technique, forms] : techniques) {
    for (const std::string form : {"query", "deferred", "function"}) {
      const auto reads = forms.find(form);
      out["techniques"][technique][form] =
          reads == forms.end() ? "no such form" : cell(reads->second);
    }
  }
  for (const auto& [pass, column] : passes) out["passes"][pass]["reads"] = cell(column.at("reads"));
  return out;
}

// The marked tables of `markdown`, their cells as split_row() reads them.
Tables doc_tables(const std::string& markdown) {
  static const std::regex open(R"(<!-- params-reads (\w+) -->)");
  Tables out;
  std::stringstream lines(markdown);
  std::string table;
  std::vector<std::string> header;
  for (std::string line; std::getline(lines, line);) {
    std::smatch marker;
    if (std::regex_match(line, marker, open)) {
      table = marker[1];
      header.clear();
    } else if (line == "<!-- end params-reads -->") {
      table.clear();
    } else if (!table.empty() && line.starts_with('|') && !line.starts_with("|---")) {
      std::vector<std::string> row = split_row(line);
      if (header.empty()) {
        header = row;
        continue;
      }
      for (std::size_t c = 1; c < row.size() && c < header.size(); ++c) {
        out[table][row[0]][header[c]] = row[c];
      }
    }
  }
  return out;
}

// A cell as the doc writes it: each member in backticks, `-` for none.
std::string markdown_cell(const std::string& cell) {
  if (cell.empty()) return "-";
  if (cell == "no such form") return cell;
  std::string out;
  std::stringstream members(cell);
  for (std::string member; std::getline(members >> std::ws, member, ',');) {
    out += (out.empty() ? "`" : ", `") + member + "`";
  }
  return out;
}

// Every difference between `doc` and `want`, one line each, and the tables
// as they should read.
std::vector<std::string> differences(const Tables& doc, const Tables& want) {
  std::vector<std::string> out;
  for (const auto& [table, rows] : want) {
    for (const auto& [row, columns] : rows) {
      for (const auto& [column, value] : columns) {
        const auto t = doc.find(table);
        const bool has =
            t != doc.end() && t->second.contains(row) && t->second.at(row).contains(column);
        if (has && t->second.at(row).at(column) == value) continue;
        const std::string got = has ? markdown_cell(t->second.at(row).at(column)) : "(missing)";
        out.push_back(table + " " + row + " " + column + ": the doc has " + got +
                      ", the library reads " + markdown_cell(value));
      }
    }
  }
  for (const auto& [table, rows] : doc) {
    for (const auto& [row, columns] : rows) {
      if (!want.contains(table) || !want.at(table).contains(row)) {
        out.push_back(table + " " + row + ": no such " +
                      (table == "passes" ? "shared pass" : "technique") + " in the library");
      }
    }
  }
  return out;
}

// The tables as Markdown rows, to paste into the doc when it is out of date.
std::string markdown_rows(const Tables& want) {
  const std::map<std::string, std::vector<std::string>> columns = {
      {"techniques", {"query", "deferred", "function"}}, {"passes", {"reads"}}};
  std::string out;
  for (const auto& [table, rows] : want) {
    out += "params-reads " + table + ":\n";
    for (const auto& [row, cells] : rows) {
      out += "| `" + row + "` |";
      for (const std::string& column : columns.at(table)) {
        out += " " + markdown_cell(cells.at(column)) + " |";
      }
      out += "\n";
    }
  }
  return out;
}

const Library& default_library() {
  static const std::unique_ptr<TemporaryLibrary> built = [] {
    auto library = TemporaryLibrary::build(default_variants(), {Target::glsl450}, {.jobs = 2});
    EXPECT_TRUE(library.ok()) << library.error().to_string();
    return library.ok() ? std::move(*library) : nullptr;
  }();
  static const Library none;
  return built ? built->library() : none;
}

TEST(ParamsReads, TheDocsTablesAreWhatTheShadersRead) {
  const Tables want = library_reads(default_library());
  ASSERT_TRUE(want.contains("techniques") && want.contains("passes"));
  std::string listed;
  for (const std::string& d : differences(doc_tables(read_file(kDoc).value()), want))
    listed += d + "\n";
  EXPECT_TRUE(listed.empty()) << listed << "\nThe tables' rows:\n" << markdown_rows(want);
}

// The check fails where a cell is wrong or a row is missing.
TEST(ParamsReads, ReportsAWrongCell) {
  const Tables want = library_reads(default_library());
  Tables doc = doc_tables(read_file(kDoc).value());
  ASSERT_TRUE(doc.contains("techniques") && doc["techniques"].contains("pcss"));
  doc["techniques"]["pcss"]["query"] = "light.xyzw";
  doc["passes"].erase("depth");
  const std::vector<std::string> found = differences(doc, want);
  const auto mentions = [&](const std::string& part) {
    return std::ranges::any_of(
        found, [&](const std::string& d) { return d.find(part) != std::string::npos; });
  };
  EXPECT_TRUE(mentions("techniques pcss query: the doc has `light.xyzw`"));
  EXPECT_TRUE(mentions("passes depth reads: the doc has (missing)"));
}

}  // namespace
}  // namespace penumbra::testing
