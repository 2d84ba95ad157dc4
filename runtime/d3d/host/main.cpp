// penumbra_d3d_host: runs a job list of Direct3D 9, 10 or 11 draws on the
// runtime it runs on (Windows, or Wine on Linux), one process for a whole
// verify run. Linux's penumbra::d3d writes the jobs from index.json's
// reflection and reads the results back (docs/verification.md, "Direct3D
// runtimes"). The protocol, one command a line on stdin:
//
//   texture ID FORMAT WIDTH HEIGHT LEVELS target|depth|input LAYERS
//                                 LAYERS 0: a 2D texture, else a 2D array
//   upload ID LEVEL PATH          raw float32 texels (device.hpp's upload())
//   buffer ID PATH                raw float32 vertices
//   shader ID vs|ps PATH          compiled bytecode (.d3dbc, .dxbc)
//   draw                          then the draw's lines, then `end`:
//     colour ID LEVEL | depth ID | clear_colour R G B A | clear_depth D | depth_greater
//     vs ID | ps ID | input SEMANTIC FORMAT OFFSET | vertices ID STRIDE COUNT
//     constant vs|ps REG X Y Z W                     (Direct3D 9)
//     member vs|ps REG BLOCK_SIZE OFFSET X Y Z W     (Direct3D 10, 11)
//     texture REG ID [VIEW_FORMAT]
//     sampler REG FILTER MIP_FILTER ADDRESS compare|compare_greater|plain
//   copy SRC SRC_LEVEL DST DST_LEVEL
//   read ID LEVEL PATH            raw float32 texels, an array's layers one after another
//   release ID
//   sync TAG                      answers "ok TAG", or "error TAG <message>"
//                                 with the first error since the last sync
//   quit
//
// After an error the commands up to the next sync are skipped: the job
// they belong to has failed. Paths are the Linux side's: an absolute
// /path is read through Wine's Z: drive.
#include <windows.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "device.hpp"

namespace penumbra::d3dhost {
namespace {

std::string windows_path(const std::string& path) {
  return !path.empty() && path[0] == '/' ? "Z:" + path : path;
}

bool read_file(const std::string& path, std::vector<unsigned char>& bytes, std::string& error) {
  FILE* file = std::fopen(windows_path(path).c_str(), "rb");
  if (!file) {
    error = "cannot open " + path;
    return false;
  }
  bytes.clear();
  unsigned char chunk[65536];
  std::size_t got = 0;
  while ((got = std::fread(chunk, 1, sizeof chunk, file)) > 0)
    bytes.insert(bytes.end(), chunk, chunk + got);
  const bool failed = std::ferror(file) != 0;
  std::fclose(file);
  if (failed) error = "cannot read " + path;
  return !failed;
}

bool read_floats(const std::string& path, std::vector<float>& floats, std::string& error) {
  std::vector<unsigned char> bytes;
  if (!read_file(path, bytes, error)) return false;
  if (bytes.size() % sizeof(float) != 0) {
    error = path + " is not a whole number of 32-bit floats";
    return false;
  }
  floats.resize(bytes.size() / sizeof(float));
  if (!bytes.empty()) std::memcpy(floats.data(), bytes.data(), bytes.size());
  return true;
}

std::string write_floats(const std::string& path, const std::vector<float>& floats) {
  FILE* file = std::fopen(windows_path(path).c_str(), "wb");
  if (!file) return "cannot create " + path;
  const std::size_t wrote = std::fwrite(floats.data(), sizeof(float), floats.size(), file);
  const bool closed = std::fclose(file) == 0;
  return wrote == floats.size() && closed ? std::string() : "cannot write " + path;
}

Stage parse_stage(const std::string& token, std::string& error) {
  if (token == "vs") return Stage::vertex;
  if (token != "ps") error = "stage '" + token + "' (allowed: vs, ps)";
  return Stage::pixel;
}

std::array<float, 4> read_vec4(std::istringstream& in) {
  std::array<float, 4> v{};
  for (float& f : v) in >> f;
  return v;
}

// One line of a draw block into `draw`; an error names the line.
std::string parse_draw_line(const std::string& line, Draw& draw) {
  std::istringstream in(line);
  std::string word;
  in >> word;
  std::string error;
  if (word == "colour") {
    int id = 0;
    in >> id >> draw.colour_level;
    draw.colour = id;
  } else if (word == "depth") {
    int id = 0;
    in >> id;
    draw.depth = id;
  } else if (word == "clear_colour") {
    draw.clear_colour = read_vec4(in);
  } else if (word == "clear_depth") {
    float d = 0.0f;
    in >> d;
    draw.clear_depth = d;
  } else if (word == "depth_greater") {
    draw.depth_greater = true;
  } else if (word == "vs") {
    in >> draw.vs;
  } else if (word == "ps") {
    in >> draw.ps;
  } else if (word == "input") {
    InputElement element;
    in >> element.semantic >> element.format >> element.offset;
    draw.inputs.push_back(element);
  } else if (word == "vertices") {
    in >> draw.vertices >> draw.stride >> draw.count;
  } else if (word == "constant") {
    std::string stage;
    Constant constant;
    in >> stage >> constant.reg;
    constant.stage = parse_stage(stage, error);
    constant.value = read_vec4(in);
    draw.constants.push_back(constant);
  } else if (word == "member") {
    std::string stage;
    BlockMember member;
    in >> stage >> member.reg >> member.block_size >> member.offset;
    member.stage = parse_stage(stage, error);
    member.value = read_vec4(in);
    draw.members.push_back(member);
  } else if (word == "texture") {
    TextureBind bind;
    in >> bind.reg >> bind.texture;
    if (in.fail()) return "malformed draw line '" + line + "'";
    in >> bind.view_format;  // optional: Direct3D 10 and 11 only
    draw.textures.push_back(bind);
    return {};
  } else if (word == "sampler") {
    SamplerBind bind;
    std::string compare;
    in >> bind.reg >> bind.state.filter >> bind.state.mip_filter >> bind.state.address >> compare;
    if (compare != "compare" && compare != "compare_greater" && compare != "plain") {
      return "comparison '" + compare + "' (allowed: compare, compare_greater, plain) in '" + line +
             "'";
    }
    bind.state.comparison = compare != "plain";
    bind.state.greater_equal = compare == "compare_greater";
    draw.samplers.push_back(bind);
  } else {
    return "unknown draw line '" + line + "'";
  }
  if (!error.empty()) return error + " in '" + line + "'";
  if (in.fail()) return "malformed draw line '" + line + "'";
  return {};
}

Usage parse_usage(const std::string& token, std::string& error) {
  if (token == "target") return Usage::target;
  if (token == "depth") return Usage::depth;
  if (token != "input") error = "usage '" + token + "' (allowed: target, depth, input)";
  return Usage::input;
}

// Runs one command line (a whole draw block for `draw`); returns the error.
std::string run_command(Device& device, const std::string& line, std::istream& input) {
  std::istringstream in(line);
  std::string word;
  in >> word;
  std::string error;
  if (word == "texture") {
    int id = 0;
    TextureDesc desc;
    std::string usage;
    in >> id >> desc.format >> desc.width >> desc.height >> desc.levels >> usage >> desc.layers;
    if (in.fail()) return "malformed '" + line + "'";
    desc.usage = parse_usage(usage, error);
    if (!error.empty()) return error;
    return device.create_texture(id, desc);
  }
  if (word == "upload" || word == "buffer") {
    int id = 0;
    int level = 0;
    std::string path;
    in >> id;
    if (word == "upload") in >> level;
    in >> path;
    if (in.fail()) return "malformed '" + line + "'";
    std::vector<float> floats;
    if (!read_floats(path, floats, error)) return error;
    return word == "upload" ? device.upload(id, level, floats) : device.create_buffer(id, floats);
  }
  if (word == "shader") {
    int id = 0;
    std::string stage;
    std::string path;
    in >> id >> stage >> path;
    if (in.fail()) return "malformed '" + line + "'";
    const Stage s = parse_stage(stage, error);
    if (!error.empty()) return error;
    std::vector<unsigned char> code;
    if (!read_file(path, code, error)) return error;
    return device.create_shader(id, s, code);
  }
  if (word == "draw") {
    Draw draw;
    std::string draw_line;
    while (std::getline(input, draw_line) && draw_line != "end" && draw_line != "end\r") {
      if (error.empty()) error = parse_draw_line(draw_line, draw);
    }
    if (!error.empty()) return error;
    return device.draw(draw);
  }
  if (word == "copy") {
    int src = 0, src_level = 0, dst = 0, dst_level = 0;
    in >> src >> src_level >> dst >> dst_level;
    if (in.fail()) return "malformed '" + line + "'";
    return device.copy(src, src_level, dst, dst_level);
  }
  if (word == "read") {
    int id = 0;
    int level = 0;
    std::string path;
    in >> id >> level >> path;
    if (in.fail()) return "malformed '" + line + "'";
    const std::vector<float> texels = device.read(id, level, error);
    if (!error.empty()) return error;
    return write_floats(path, texels);
  }
  if (word == "release") {
    int id = 0;
    in >> id;
    if (in.fail()) return "malformed '" + line + "'";
    device.release(id);
    return {};
  }
  return "unknown command '" + line + "'";
}

std::unique_ptr<Device> create_device(const std::string& api, std::string& error) {
  if (api == "d3d9") return create_d3d9_device(error);
  if (api == "d3d10") return create_d3d10_device(error);
  if (api == "d3d11") return create_d3d11_device(false, error);
  if (api == "d3d11_10_0") return create_d3d11_device(true, error);
  error = "unknown runtime '" + api + "' (allowed: d3d9, d3d10, d3d11, d3d11_10_0)";
  return nullptr;
}

}  // namespace
}  // namespace penumbra::d3dhost

int main(int argc, char** argv) {
  using namespace penumbra::d3dhost;
  // No dialog boxes: a crash must end the process, not wait for a click.
  SetErrorMode(SEM_FAILCRITICALERRORS | SEM_NOGPFAULTERRORBOX);
  std::string error;
  std::unique_ptr<Device> device = argc == 2 ? create_device(argv[1], error) : nullptr;
  if (argc != 2) error = "usage: penumbra_d3d_host d3d9|d3d10|d3d11|d3d11_10_0";
  if (!device) {
    std::cout << "error - " << error << std::endl;
    return 1;
  }
  std::cout << "ready " << device->description() << std::endl;
  std::string line;
  std::string first_error;
  while (std::getline(std::cin, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) continue;
    if (line == "quit") break;
    if (line.rfind("sync ", 0) == 0) {
      const std::string tag = line.substr(5);
      if (first_error.empty()) {
        std::cout << "ok " << tag << std::endl;
      } else {
        std::cout << "error " << tag << " " << first_error << std::endl;
      }
      first_error.clear();
      continue;
    }
    if (!first_error.empty()) {
      // Skip the failed job's rest (and a draw block's lines).
      if (line == "draw") {
        while (std::getline(std::cin, line) && line != "end" && line != "end\r") {
        }
      }
      continue;
    }
    first_error = run_command(*device, line, std::cin);
  }
  return 0;
}
