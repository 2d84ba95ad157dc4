#include "chromium_page.hpp"

#include <cstdlib>
#include <map>

#include "penumbra/support/file.hpp"

namespace penumbra::testing {
namespace {

namespace fs = std::filesystem;

// Headless WebGL 2 as root on a machine with no GPU: ANGLE on SwiftShader
// (Chromium refuses it unless told it is meant), no sandbox (root), nothing
// that reaches the network, and module scripts from file:// pages.
constexpr const char* kFlags =
    " --headless --no-sandbox --disable-gpu-sandbox --use-gl=angle --use-angle=swiftshader"
    " --enable-unsafe-swiftshader --ignore-gpu-blocklist --disable-background-networking"
    " --disable-component-update --disable-sync --no-first-run --allow-file-access-from-files"
    " --dump-dom";

std::string shell_quoted(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

// The text of <pre id="result"> in the dumped DOM, unescaped as the DOM
// serializer escapes text.
Result<std::string> result_text(const std::string& dom, const std::string& where) {
  const std::string open = "<pre id=\"result\">";
  const auto begin = dom.find(open);
  const auto end = begin == std::string::npos ? begin : dom.find("</pre>", begin);
  if (end == std::string::npos) {
    return make_error(Error::Kind::internal, where,
                      "the dumped DOM has no <pre id=\"result\">: " + dom.substr(0, 2000));
  }
  const std::string text = dom.substr(begin + open.size(), end - begin - open.size());
  static const std::map<std::string, std::string> kEntities = {
      {"&amp;", "&"}, {"&lt;", "<"}, {"&gt;", ">"}, {"&quot;", "\""}, {"&nbsp;", "\u00a0"}};
  std::string out;
  for (std::size_t i = 0; i < text.size();) {
    bool replaced = false;
    for (const auto& [entity, character] : kEntities) {
      if (text.compare(i, entity.size(), entity) == 0) {
        out += character;
        i += entity.size();
        replaced = true;
        break;
      }
    }
    if (!replaced) out += text[i++];
  }
  if (out.empty()) return make_error(Error::Kind::internal, where, "the page wrote no result");
  return out;
}

}  // namespace

Result<std::string> run_chromium_page(const fs::path& page, const std::string& chromium) {
  const fs::path dir = page.parent_path();
  const std::string stem = page.stem().string();
  const fs::path profile = dir / (stem + "-profile");
  const fs::path dom_path = dir / (stem + "-dom.html");
  const fs::path log_path = dir / (stem + "-chromium.log");
  const std::string command = "timeout 300 " + shell_quoted(chromium) + kFlags +
                              " --user-data-dir=" + shell_quoted(profile.string()) + " " +
                              shell_quoted("file://" + fs::absolute(page).string()) + " > " +
                              shell_quoted(dom_path.string()) + " 2> " +
                              shell_quoted(log_path.string());
  const int status = std::system(command.c_str());
  const std::string where = page.string();
  if (status != 0) {
    auto log = read_file(log_path);
    return make_error(Error::Kind::device, where,
                      "chromium exited with status " + std::to_string(status) + ": " +
                          (log ? log->substr(0, 4000) : std::string("(no log)")));
  }
  PENUMBRA_TRY_ASSIGN(const std::string dom, read_file(dom_path));
  PENUMBRA_TRY_ASSIGN(std::string text, result_text(dom, where));
  std::error_code ignored;  // kept when the run fails, for the page's log
  fs::remove_all(profile, ignored);
  fs::remove(dom_path, ignored);
  fs::remove(log_path, ignored);
  return text;
}

std::string script_safe(const std::string& text) {
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    out += text[i];
    if (text[i] == '<' && i + 1 < text.size() && text[i + 1] == '/') out += '\\';
  }
  return out;
}

}  // namespace penumbra::testing
