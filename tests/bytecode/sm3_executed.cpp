#include "sm3_executed.hpp"

#include <algorithm>
#include <string>

#include "targets/sm3_slots.hpp"

namespace penumbra::testing {
namespace {

std::string_view opcode_of(std::string_view line) {
  const std::size_t first = line.find_first_not_of(" \t");
  if (first == std::string_view::npos) return {};
  line.remove_prefix(first);
  return line.substr(0, line.find_first_of(" \t\r"));
}

// Recursive descent over the lines: a block ends at `else`, `endif` or
// `endrep`/`endloop`, which the caller consumes.
class Walker {
 public:
  Walker(std::string_view assembly, const std::vector<long long>& trips) : trips_(trips) {
    while (!assembly.empty()) {
      const std::size_t end = std::min(assembly.find('\n'), assembly.size());
      lines_.push_back(assembly.substr(0, end));
      assembly.remove_prefix(std::min(end + 1, assembly.size()));
    }
  }

  Result<long long> program() {
    long long total = 0;
    PENUMBRA_TRY_ASSIGN(total, block());
    if (next_ != lines_.size()) return fail("unmatched " + std::string(opcode_of(lines_[next_])));
    if (loop_ != trips_.size()) {
      return fail(std::to_string(loop_) + " loops, " + std::to_string(trips_.size()) +
                  " trip counts given");
    }
    return total;
  }

 private:
  Result<long long> block() {
    long long total = 0;
    while (next_ < lines_.size()) {
      const std::string_view op = opcode_of(lines_[next_]);
      if (op == "else" || op == "endif" || op == "endrep" || op == "endloop") return total;
      const int slots = sm3_line_slots(lines_[next_++]);
      if (op.starts_with("if")) {
        long long then_arm = 0;
        PENUMBRA_TRY_ASSIGN(then_arm, block());
        long long else_arm = 0;
        if (next_ < lines_.size() && opcode_of(lines_[next_]) == "else") {
          ++next_;
          PENUMBRA_TRY_ASSIGN(else_arm, block());
          else_arm += 1;
        }
        if (next_ == lines_.size() || opcode_of(lines_[next_]) != "endif") {
          return fail("if without endif");
        }
        ++next_;
        total += slots + std::max(then_arm, else_arm) + 1;
      } else if (op == "rep" || op == "loop") {
        if (loop_ == trips_.size()) return fail("more loops than trip counts given");
        const long long trips = trips_[loop_++];
        long long body = 0;
        PENUMBRA_TRY_ASSIGN(body, block());
        if (next_ == lines_.size() || !opcode_of(lines_[next_]).starts_with("end")) {
          return fail(std::string(op) + " without its end");
        }
        ++next_;
        total += slots + trips * (body + 1);
      } else {
        total += slots;
      }
    }
    return total;
  }

  Error fail(const std::string& what) const {
    return make_error(Error::Kind::bad_input, "d3d-asm line " + std::to_string(next_ + 1), what);
  }

  std::vector<std::string_view> lines_;
  const std::vector<long long>& trips_;
  std::size_t next_ = 0;
  std::size_t loop_ = 0;
};

}  // namespace

Result<long long> sm3_most_executed(std::string_view assembly,
                                    const std::vector<long long>& trips) {
  return Walker(assembly, trips).program();
}

}  // namespace penumbra::testing
