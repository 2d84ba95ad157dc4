#include "guide_check.hpp"

#include <nlohmann/json.hpp>
#include <regex>
#include <set>

namespace penumbra::testing {
namespace {

// The columns a marked table may have: index.json's field names, plus `kind`.
const std::set<std::string> kColumns = {
    "kind",   "name",        "type",      "register",   "set",       "binding",    "location",
    "index",  "offset",      "size",      "registers",  "parameter", "semantic",   "components",
    "format", "view_format", "mipmapped", "comparison", "filter",    "mip_filter", "address"};

std::string scalar(const nlohmann::json& value) {
  if (value.is_string()) return value.get<std::string>();
  return value.dump();  // numbers and booleans as index.json writes them
}

// The JSON object's scalar fields, plus its kind.
ReflectionRow row_of(const nlohmann::json& object, std::string kind) {
  ReflectionRow row{{"kind", std::move(kind)}};
  for (const auto& [key, value] : object.items()) {
    if (!value.is_object() && !value.is_array()) row[key] = scalar(value);
  }
  return row;
}

std::string trim(std::string_view text) {
  const auto begin = text.find_first_not_of(" \t\r");
  if (begin == std::string_view::npos) return "";
  const auto end = text.find_last_not_of(" \t\r");
  return std::string(text.substr(begin, end - begin + 1));
}

// A cell's value: without backticks; "-" is no value.
std::string cell_value(std::string_view cell) {
  std::string out;
  for (char c : cell) {
    if (c != '`') out += c;
  }
  out = trim(out);
  return out == "-" ? "" : out;
}

bool is_word_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
}

// `name` in `line` as a whole word (names may contain '.').
bool names(std::string_view line, const std::string& name) {
  for (auto at = line.find(name); at != std::string_view::npos; at = line.find(name, at + 1)) {
    const bool starts = at == 0 || !is_word_char(line[at - 1]);
    const auto end = at + name.size();
    if (starts && (end == line.size() || !is_word_char(line[end]))) return true;
  }
  return false;
}

// The numbers a row's resource is bound at, written as check_code finds them.
std::set<std::string> numbers_of(const ReflectionRow& row) {
  std::set<std::string> out;
  auto field = [&](const char* key) {
    auto it = row.find(key);
    return it == row.end() ? std::string() : it->second;
  };
  if (!field("register").empty()) out.insert(field("register"));
  if (!field("semantic").empty()) out.insert(field("semantic"));
  if (!field("binding").empty()) out.insert("binding " + field("binding"));
  if (!field("location").empty()) out.insert("location " + field("location"));
  if (!field("index").empty()) out.insert("location " + field("index"));
  return out;
}

struct NumberForm {
  std::regex pattern;  // group 1: the number or token
  std::string prefix;  // put before group 1
  bool needs_name;     // a line with this form must name a resource
};

const std::vector<NumberForm>& number_forms() {
  static const std::vector<NumberForm> forms = {
      {std::regex(R"(\b([bcst]\d+)\b)"), "", false},
      {std::regex(R"(\b(TEXCOORD\d+)\b)"), "", false},
      {std::regex(R"(\b(?:binding|dstBinding)\s*=\s*(\d+))"), "binding ", true},
      {std::regex(R"(\blocation\s*=\s*(\d+))"), "location ", true},
      {std::regex(R"(\bSet(?:Vertex|Pixel)ShaderConstantF\(\s*(\d+))"), "c", true},
      {std::regex(R"(\b(?:SetTexture|SetSamplerState)\(\s*(\d+))"), "s", true},
      {std::regex(R"(\b[VP]SSetConstantBuffers\(\s*(\d+))"), "b", true},
      {std::regex(R"(\bPSSetShaderResources\(\s*(\d+))"), "t", true},
      {std::regex(R"(\bPSSetSamplers\(\s*(\d+))"), "s", true},
      {std::regex(R"(\b(?:glBindTextureUnit|glBindSampler)\(\s*(\d+))"), "binding ", true},
      {std::regex(R"(\bglBindBufferBase\(\s*GL_UNIFORM_BUFFER\s*,\s*(\d+))"), "binding ", true},
  };
  return forms;
}

}  // namespace

std::vector<std::string> split_row(std::string_view line) {
  std::string text = trim(line);
  if (!text.empty() && text.front() == '|') text.erase(0, 1);
  if (!text.empty() && text.back() == '|') text.pop_back();
  std::vector<std::string> cells;
  std::size_t start = 0;
  while (true) {
    const auto bar = text.find('|', start);
    cells.push_back(cell_value(std::string_view(text).substr(start, bar - start)));
    if (bar == std::string::npos) break;
    start = bar + 1;
  }
  return cells;
}

std::map<std::string, ReflectionRow> reflection_rows(const PassReflection& pass,
                                                     std::string_view stage) {
  const nlohmann::json j = pass;
  std::vector<ReflectionRow> rows;
  const nlohmann::json& bindings = j.at(std::string(stage));
  for (const auto& block : bindings.value("blocks", nlohmann::json::array())) {
    rows.push_back(row_of(block, "block"));
    for (const auto& member : block.at("members")) rows.push_back(row_of(member, "member"));
  }
  for (const auto& uniform : bindings.value("uniforms", nlohmann::json::array())) {
    rows.push_back(row_of(uniform, "uniform"));
  }
  for (const auto& texture : bindings.value("textures", nlohmann::json::array())) {
    const nlohmann::json& sampler = texture.at("sampler");
    ReflectionRow row = row_of(texture, "texture");
    for (const char* key : {"comparison", "filter", "mip_filter", "address"}) {
      row[key] = scalar(sampler.at(key));
    }
    rows.push_back(std::move(row));
    if (sampler.contains("name")) rows.push_back(row_of(sampler, "sampler"));
  }
  if (stage == "vert") {
    for (const auto& input : j.at("vertex_inputs")) rows.push_back(row_of(input, "vertex_input"));
  } else {
    for (const auto& target : j.at("render_targets")) {
      rows.push_back(row_of(target, "render_target"));
    }
    if (j.contains("depth_target")) {
      rows.push_back({{"kind", "depth_target"},
                      {"name", "depth_target"},
                      {"format", j.at("depth_target").get<std::string>()}});
    }
    for (const auto& extension : j.value("extensions", nlohmann::json::array())) {
      rows.push_back({{"kind", "extension"}, {"name", extension.get<std::string>()}});
    }
  }
  std::map<std::string, ReflectionRow> out;
  for (ReflectionRow& row : rows) {
    const std::string name = row.at("name");
    out.emplace(name, std::move(row));
  }
  return out;
}

Guide parse_guide(std::string_view markdown) {
  static const std::regex open(
      R"(^\s*<!--\s*reflection\s+(\S+)\s+(\S+)\s+(\S+)\s+(\S+)\s*-->\s*$)");
  static const std::regex close(R"(^\s*<!--\s*end reflection\s*-->\s*$)");
  Guide guide;
  GuideTable* table = nullptr;
  bool in_code = false;
  std::size_t number = 0;
  std::size_t start = 0;
  while (start <= markdown.size()) {
    auto end = markdown.find('\n', start);
    if (end == std::string_view::npos) end = markdown.size();
    const std::string line(markdown.substr(start, end - start));
    start = end + 1;
    ++number;
    const std::string where = "line " + std::to_string(number) + ": ";
    if (trim(line).rfind("```", 0) == 0) {
      in_code = !in_code;
      continue;
    }
    if (in_code) {
      guide.code.push_back({number, line});
      continue;
    }
    std::smatch m;
    if (std::regex_match(line, m, open)) {
      if (table) guide.errors.push_back(where + "reflection table opened inside another");
      guide.tables.push_back({number, m[1], m[2], m[3], m[4], {}, {}});
      table = &guide.tables.back();
    } else if (std::regex_match(line, close)) {
      if (!table) guide.errors.push_back(where + "<!-- end reflection --> without a table");
      table = nullptr;
    } else if (table && trim(line).rfind('|', 0) == 0) {
      std::vector<std::string> cells = split_row(line);
      if (table->header.empty()) {
        table->header = std::move(cells);
      } else if (cells.front().find_first_not_of("-: ") == std::string::npos) {
        continue;  // the |---|---| separator
      } else if (cells.size() != table->header.size()) {
        guide.errors.push_back(where + "row has " + std::to_string(cells.size()) +
                               " cells, the header " + std::to_string(table->header.size()));
      } else {
        table->rows.push_back(std::move(cells));
      }
    }
  }
  if (table) {
    guide.errors.push_back("line " + std::to_string(table->line) +
                           ": reflection table without <!-- end reflection -->");
  }
  if (in_code) guide.errors.push_back("a ``` fence is never closed");
  return guide;
}

std::vector<std::string> compare_table(const GuideTable& table, const PassReflection& pass) {
  const std::string where = "table at line " + std::to_string(table.line) + " (" + table.variant +
                            " " + table.pass + " " + table.target + " " + table.stage + "): ";
  if (table.stage != "vert" && table.stage != "frag") {
    return {where + "stage must be vert or frag"};
  }
  if (table.header.empty() || table.header.front() != "name") {
    return {where + "the first column must be `name`"};
  }
  std::vector<std::string> errors;
  for (const std::string& column : table.header) {
    if (!kColumns.contains(column)) {
      errors.push_back(where + "unknown column '" + column + "' (use index.json's field names)");
    }
  }
  if (!errors.empty()) return errors;
  const auto expected = reflection_rows(pass, table.stage);
  std::set<std::string> listed;
  for (const auto& cells : table.rows) {
    const std::string& name = cells.front();
    if (!listed.insert(name).second) errors.push_back(where + "'" + name + "' listed twice");
    auto it = expected.find(name);
    if (it == expected.end()) {
      errors.push_back(where + "'" + name + "' is not in the reflection");
      continue;
    }
    for (std::size_t i = 1; i < cells.size(); ++i) {
      auto field = it->second.find(table.header[i]);
      const std::string want = field == it->second.end() ? "" : field->second;
      if (cells[i] != want) {
        errors.push_back(where + "'" + name + "' " + table.header[i] + " is '" + cells[i] +
                         "', the reflection has '" + want + "'");
      }
    }
  }
  for (const auto& [name, row] : expected) {
    if (!listed.contains(name)) {
      errors.push_back(where + "the reflection's " + row.at("kind") + " '" + name + "' is missing");
    }
  }
  return errors;
}

std::vector<std::string> check_code(const std::vector<CodeLine>& code,
                                    const std::vector<ReflectionRow>& rows) {
  std::map<std::string, std::set<std::string>> numbers;
  for (const ReflectionRow& row : rows) {
    numbers[row.at("name")].merge(numbers_of(row));
  }
  std::vector<std::string> errors;
  for (const CodeLine& line : code) {
    std::set<std::string> allowed;
    std::vector<std::string> named;
    for (const auto& [name, bound] : numbers) {
      if (!names(line.text, name)) continue;
      named.push_back(name);
      allowed.insert(bound.begin(), bound.end());
    }
    for (const NumberForm& form : number_forms()) {
      for (auto it = std::sregex_iterator(line.text.begin(), line.text.end(), form.pattern);
           it != std::sregex_iterator(); ++it) {
        const std::string found = form.prefix + (*it)[1].str();
        const std::string where = "code line " + std::to_string(line.line) + ": ";
        if (named.empty()) {
          if (form.needs_name) {
            errors.push_back(where + "'" + (*it)[0].str() +
                             "' names no resource of a reflection table: " + line.text);
          }
        } else if (!allowed.contains(found)) {
          std::string bound;
          for (const std::string& n : allowed) bound += (bound.empty() ? "" : ", ") + n;
          errors.push_back(where + "'" + found + "' for " + named.front() +
                           ", the reflection has {" + bound + "}: " + line.text);
        }
      }
    }
  }
  return errors;
}

}  // namespace penumbra::testing
