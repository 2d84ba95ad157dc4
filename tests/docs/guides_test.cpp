// The engine guides (docs/engines/) against the reflection of the library
// they describe: every marked bindings table equals the generated
// reflection of its variant, pass, target and stage, and every register or
// binding number their code gives a resource of those tables is the
// reflection's. The conventions are guide_check.hpp's.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
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

namespace penumbra::testing {
namespace {

const std::filesystem::path kSourceDir = PENUMBRA_SOURCE_DIR;
const std::vector<std::string> kGuides = {"d3d9", "d3d10", "d3d11", "opengl", "webgl2", "vulkan"};

std::string read_guide(const std::string& guide) {
  std::ifstream in(kSourceDir / "docs" / "engines" / (guide + ".md"));
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// The variants the guides name, built from permutations/default.json once
// for all tests; an empty library, with a test failure, when that fails.
const Library& guide_library() {
  static const std::unique_ptr<TemporaryLibrary> built = []() -> std::unique_ptr<TemporaryLibrary> {
    std::set<std::string> named;
    for (const std::string& guide : kGuides) {
      for (const GuideTable& table : parse_guide(read_guide(guide)).tables) {
        named.insert(table.variant);
      }
    }
    std::vector<Variant> used;
    for (const Variant& variant : default_variants()) {
      if (named.contains(variant.name)) used.push_back(variant);
    }
    auto library = TemporaryLibrary::build(std::move(used), {}, {.jobs = 2});
    if (!library) {
      ADD_FAILURE() << library.error().to_string();
      return nullptr;
    }
    return std::move(*library);
  }();
  static const Library none;
  return built ? built->library() : none;
}

// The reflection a table names, or a message saying what is not there.
Result<PassReflection> reflection_for(const GuideTable& table) {
  const std::string where = "table at line " + std::to_string(table.line);
  const LibraryVariant* variant = guide_library().find(table.variant);
  if (!variant) {
    return make_error(Error::Kind::bad_input, where,
                      "no variant '" + table.variant + "' in permutations/default.json");
  }
  const auto pass = parse_pass(table.pass);
  const auto target = parse_target(table.target);
  // "function": the variant's function form (docs/function-form.md).
  if (table.pass == "function" && target) {
    const auto form = variant->function.find(*target);
    if (form == variant->function.end()) {
      return make_error(Error::Kind::bad_input, where,
                        table.variant + " has no function form for " + table.target);
    }
    return form->second.reflection;
  }
  if (!pass || !target) {
    return make_error(Error::Kind::bad_input, where,
                      "unknown pass '" + table.pass + "' or target '" + table.target + "'");
  }
  auto by_pass = variant->reflection.find(*pass);
  if (by_pass == variant->reflection.end() || !by_pass->second.contains(*target)) {
    return make_error(Error::Kind::bad_input, where,
                      table.variant + " has no " + table.pass + " pass for " + table.target);
  }
  return by_pass->second.at(*target);
}

// Every difference between a guide's text and the reflection.
std::vector<std::string> guide_errors(const std::string& markdown) {
  const Guide guide = parse_guide(markdown);
  std::vector<std::string> errors = guide.errors;
  if (guide.tables.empty()) errors.push_back("no <!-- reflection ... --> table");
  std::vector<ReflectionRow> rows;
  for (const GuideTable& table : guide.tables) {
    auto pass = reflection_for(table);
    if (!pass) {
      errors.push_back(pass.error().to_string());
      continue;
    }
    for (std::string& error : compare_table(table, *pass)) errors.push_back(std::move(error));
    for (auto& [name, row] : reflection_rows(*pass, table.stage)) rows.push_back(row);
  }
  for (std::string& error : check_code(guide.code, rows)) errors.push_back(std::move(error));
  return errors;
}

std::string joined(const std::vector<std::string>& errors) {
  std::string out;
  for (const std::string& error : errors) out += "  " + error + "\n";
  return out;
}

class EngineGuide : public ::testing::TestWithParam<std::string> {};

TEST_P(EngineGuide, MatchesTheReflection) {
  const std::string text = read_guide(GetParam());
  ASSERT_FALSE(text.empty()) << "docs/engines/" << GetParam() << ".md is missing or empty";
  const auto errors = guide_errors(text);
  EXPECT_TRUE(errors.empty()) << "docs/engines/" << GetParam() << ".md:\n" << joined(errors);
}

// `text` with the first digit of the first match of `pattern` at or after
// `from` changed; empty when nothing matches.
std::string with_wrong_digit(const std::string& text, std::size_t from, const std::regex& pattern) {
  if (from == std::string::npos) return "";
  std::smatch m;
  const std::string tail = text.substr(from);
  if (!std::regex_search(tail, m, pattern)) return "";
  const std::size_t digit =
      from + static_cast<std::size_t>(m.position(0)) + m[0].str().find_first_of("0123456789");
  std::string wrong = text;
  wrong[digit] = wrong[digit] == '9' ? '8' : '9';
  return wrong;
}

// Where 1-based line `line` of `text` starts.
std::size_t line_start(const std::string& text, std::size_t line) {
  std::size_t at = 0;
  for (std::size_t i = 1; i < line && at != std::string::npos; ++i) {
    at = text.find('\n', at);
    if (at != std::string::npos) ++at;
  }
  return at;
}

// The check can fail: one wrong number in a table, and one in the code, is
// reported.
TEST_P(EngineGuide, ReportsAWrongNumber) {
  const std::string text = read_guide(GetParam());
  // A table's first number cell (a register, binding, offset, ...).
  static const std::regex table_number(R"(\| `?[bcst]?\d+`? \|)");
  const std::string wrong_table =
      with_wrong_digit(text, text.find("<!-- reflection"), table_number);
  ASSERT_FALSE(wrong_table.empty()) << "no number in a table";
  EXPECT_FALSE(guide_errors(wrong_table).empty());
  // The code's first register declaration, binding, location or binding call.
  static const std::regex code_number(
      R"(register\([bcst]\d+\)|(binding|location) = \d+|ShaderConstantF\(\d+|)"
      R"(SetTexture\(\d+|[VP]SSet\w+\(\d+|glBind(TextureUnit|Sampler)\(\d+)");
  std::string wrong_code;
  for (const CodeLine& line : parse_guide(text).code) {
    if (!std::regex_search(line.text, code_number)) continue;
    wrong_code = with_wrong_digit(text, line_start(text, line.line), code_number);
    break;
  }
  ASSERT_FALSE(wrong_code.empty()) << "no register, binding or location number in the code";
  EXPECT_FALSE(guide_errors(wrong_code).empty());
}

INSTANTIATE_TEST_SUITE_P(Guides, EngineGuide, ::testing::ValuesIn(kGuides),
                         [](const ::testing::TestParamInfo<std::string>& guide) {
                           return guide.param;
                         });

}  // namespace
}  // namespace penumbra::testing
