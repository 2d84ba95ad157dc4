#include "penumbra/shaders/library.hpp"

#include <algorithm>
#include <cstring>
#include <mutex>
#include <string>
#include <tuple>

#include "penumbra/model/shader_contract.hpp"

namespace penumbra::shaders {
namespace {

auto order_key(std::string_view variant, Target target, PassKind pass) {
  return std::make_tuple(variant, static_cast<int>(target), static_cast<int>(pass));
}

auto order_key(const Program& p) {
  return order_key(p.variant, p.target, p.pass);
}

auto order_key(const EmbeddedProgram& e) {
  return order_key(e.variant, e.target, e.pass);
}

auto function_key(std::string_view variant, Target target) {
  return std::make_tuple(variant, static_cast<int>(target));
}

// "variant hard was built without the query form (its forms: function)", or
// empty when `forms` holds `form`.
std::string without(std::string_view variant, Form form, const std::vector<Form>& forms) {
  if (std::ranges::find(forms, form) != forms.end()) return {};
  return "variant " + std::string(variant) + " was " + built_without(form, forms);
}

}  // namespace

// Built on first use: an engine that looks up a few programs of a large
// library pays for the parts holding them, not for the whole blob.
struct Library::Built {
  std::once_flag once;
  std::string blob;                               // the part's pieces joined
  std::vector<std::vector<std::uint32_t>> words;  // SPIR-V, copied out aligned
  std::vector<Program> programs;                  // in the part's table order
  std::vector<Function> functions;                // in the part's table order

  void build(const EmbeddedPart& part);
};

void Library::Built::build(const EmbeddedPart& part) {
  for (std::string_view piece : part.blob) blob.append(piece);
  auto text = [&](BlobRange r) { return std::string_view(blob).substr(r.offset, r.size); };
  auto bytes = [&](BlobRange r) {
    return std::span<const std::uint8_t>(
        reinterpret_cast<const std::uint8_t*>(blob.data()) + r.offset, r.size);
  };
  // The blob's chars carry no alignment, and SPIR-V is read as words.
  auto spirv = [&](BlobRange r) -> std::span<const std::uint32_t> {
    std::vector<std::uint32_t>& out = words.emplace_back(r.size / 4);
    std::memcpy(out.data(), blob.data() + r.offset, out.size() * 4);
    return out;
  };
  std::size_t spirv_stages = 0;
  for (const EmbeddedProgram& e : part.programs) spirv_stages += e.target == Target::spirv ? 2 : 0;
  words.reserve(spirv_stages);  // spans into `words` stay valid
  programs.reserve(part.programs.size());
  for (const EmbeddedProgram& e : part.programs) {
    Program& p = programs.emplace_back();
    p.variant = e.variant;
    p.target = e.target;
    p.pass = e.pass;
    p.reflection = text(e.reflection);
    for (auto [stage, code, bytecode, profile] :
         {std::tuple{&p.vertex, e.vertex, e.vertex_bytecode, e.vertex_profile},
          std::tuple{&p.fragment, e.fragment, e.fragment_bytecode, e.fragment_profile}}) {
      if (e.target == Target::spirv) {
        stage->spirv = spirv(code);
      } else {
        stage->text = text(code);
      }
      stage->bytecode = bytes(bytecode);
      stage->profile = profile;
    }
  }
  functions.reserve(part.functions.size());
  for (const EmbeddedFunction& e : part.functions) {
    functions.push_back({e.variant, e.target, text(e.text), text(e.reflection)});
  }
}

Library::Library(std::span<const EmbeddedPart> parts)
    : parts_(parts), built_(std::make_unique<Built[]>(parts.size())) {}

Library::~Library() = default;

const Library::Built& Library::built(std::size_t part) const {
  Built& built = built_[part];
  std::call_once(built.once, [&] { built.build(parts_[part]); });
  return built;
}

const Program* Library::find(std::string_view variant, Target target, PassKind pass) const {
  const auto key = order_key(variant, target, pass);
  for (std::size_t part = 0; part < parts_.size(); ++part) {
    const std::span<const EmbeddedProgram> table = parts_[part].programs;
    const auto it = std::ranges::lower_bound(table, key, {},
                                             [](const EmbeddedProgram& e) { return order_key(e); });
    if (it != table.end() && order_key(*it) == key) {
      return &built(part).programs[static_cast<std::size_t>(it - table.begin())];
    }
  }
  return nullptr;
}

const Program* Library::find(Technique technique, const VariantKeys& keys, Target target,
                             PassKind pass) const {
  return find(variant_name(technique, keys), target, pass);
}

const Function* Library::find_function(std::string_view variant, Target target) const {
  const auto key = function_key(variant, target);
  for (std::size_t part = 0; part < parts_.size(); ++part) {
    const std::span<const EmbeddedFunction> table = parts_[part].functions;
    const auto it = std::ranges::lower_bound(table, key, {}, [](const EmbeddedFunction& e) {
      return function_key(e.variant, e.target);
    });
    if (it != table.end() && function_key(it->variant, it->target) == key) {
      return &built(part).functions[static_cast<std::size_t>(it - table.begin())];
    }
  }
  return nullptr;
}

const Function* Library::find_function(Technique technique, const VariantKeys& keys,
                                       Target target) const {
  return find_function(variant_name(technique, keys), target);
}

std::vector<Form> Library::forms(std::string_view variant) const {
  for (const EmbeddedPart& part : parts_) {
    const auto it = std::ranges::lower_bound(part.variants, variant, {},
                                             [](const EmbeddedVariant& v) { return v.name; });
    if (it == part.variants.end() || it->name != variant) continue;
    std::vector<Form> out;
    for (Form form : kAllForms) {
      if (it->forms >> static_cast<unsigned>(form) & 1u) out.push_back(form);
    }
    return out;
  }
  return {};
}

std::string Library::why_not_found(std::string_view variant, Target target, PassKind pass) const {
  if (find(variant, target, pass)) return {};
  const std::vector<Form> built = forms(variant);
  if (built.empty()) return "no variant " + std::string(variant) + " in the library";
  // Every form reads the depth pass and the min-max chain; the others belong to one.
  for (Form form : kAllForms) {
    if (form_reads_pass(form, pass) &&
        std::ranges::none_of(built, [&](Form f) { return form_reads_pass(f, pass); })) {
      return without(variant, form, built);
    }
  }
  return "variant " + std::string(variant) + " has no " + std::string(to_string(pass)) +
         " pass for target " + std::string(to_string(target));
}

std::string Library::why_no_function(std::string_view variant, Target target) const {
  if (find_function(variant, target)) return {};
  const std::vector<Form> built = forms(variant);
  if (built.empty()) return "no variant " + std::string(variant) + " in the library";
  if (std::string why = without(variant, Form::function, built); !why.empty()) return why;
  return "variant " + std::string(variant) + " has no function form for target " +
         std::string(to_string(target));
}

std::size_t Library::size() const {
  std::size_t size = 0;
  for (const EmbeddedPart& part : parts_) size += part.programs.size();
  return size;
}

std::vector<const Program*> Library::programs() const {
  std::vector<const Program*> all;
  all.reserve(size());
  for (std::size_t part = 0; part < parts_.size(); ++part) {
    for (const Program& p : built(part).programs) all.push_back(&p);
  }
  std::ranges::sort(all, {}, [](const Program* p) { return order_key(*p); });
  return all;
}

std::vector<const Function*> Library::functions() const {
  std::vector<const Function*> all;
  for (std::size_t part = 0; part < parts_.size(); ++part) {
    for (const Function& f : built(part).functions) all.push_back(&f);
  }
  std::ranges::sort(all, {}, [](const Function* f) { return function_key(f->variant, f->target); });
  return all;
}

}  // namespace penumbra::shaders
