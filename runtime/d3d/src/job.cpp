#include "job.hpp"

#include <algorithm>
#include <cstring>
#include <fstream>
#include <functional>

#include "host_process.hpp"
#include "penumbra/support/file.hpp"

namespace penumbra::d3d {
namespace {

void write_floats(const std::filesystem::path& path, const std::vector<float>& floats) {
  std::ofstream out(path, std::ios::binary);
  out.write(reinterpret_cast<const char*>(floats.data()),
            static_cast<std::streamsize>(floats.size() * sizeof(float)));
}

}  // namespace

Job::Job(D3dEngine& engine)
    : engine_(engine),
      number_(engine.session_->new_job_number()),
      folder_(engine.session_->scratch() / ("job-" + std::to_string(number_))) {
  std::filesystem::create_directories(folder_);
}

Job::~Job() {
  // Released with the next job's commands: no round trip of its own.
  for (int id : own_) engine_.pending_releases_ += "release " + std::to_string(id) + "\n";
  std::error_code ignored;
  std::filesystem::remove_all(folder_, ignored);
}

std::filesystem::path Job::data_file() {
  return folder_ / (std::to_string(files_++) + ".f32");
}

int Job::texture(std::string_view format, int width, int height, int levels, std::string_view usage,
                 int layers) {
  const int id = engine_.next_id();
  commands_ += "texture " + std::to_string(id) + " " + std::string(format) + " " +
               std::to_string(width) + " " + std::to_string(height) + " " + std::to_string(levels) +
               " " + std::string(usage) + " " + std::to_string(layers) + "\n";
  own_.push_back(id);
  return id;
}

void Job::keep(int id) {
  std::erase(own_, id);
}

void Job::upload(int id, int level, const std::vector<float>& texels) {
  const auto file = data_file();
  write_floats(file, texels);
  commands_ +=
      "upload " + std::to_string(id) + " " + std::to_string(level) + " " + file.string() + "\n";
}

int Job::vertices(const std::vector<float>& floats) {
  const int id = engine_.next_id();
  const auto file = data_file();
  write_floats(file, floats);
  commands_ += "buffer " + std::to_string(id) + " " + file.string() + "\n";
  own_.push_back(id);
  return id;
}

Result<int> Job::shader(const std::filesystem::path& bytecode, std::string_view stage) {
  auto code = read_file(bytecode);
  if (!code) return code.error();
  const std::string key = std::string(stage) + *code;
  if (auto known = engine_.shaders_.find(key); known != engine_.shaders_.end()) {
    return known->second;
  }
  const int id = engine_.next_id();
  commands_ +=
      "shader " + std::to_string(id) + " " + std::string(stage) + " " + bytecode.string() + "\n";
  engine_.shaders_.emplace(key, id);
  return id;
}

int Job::constant_texture(std::string_view format, const TextureContents& contents) {
  std::string key(format);
  key.append(reinterpret_cast<const char*>(contents.texels.data()),
             contents.texels.size() * sizeof(float));
  if (auto known = engine_.constant_textures_.find(key);
      known != engine_.constant_textures_.end()) {
    return known->second;
  }
  const int id = texture(format, static_cast<int>(contents.width),
                         static_cast<int>(contents.height), 1, "input");
  keep(id);
  upload(id, 0, contents.texels);
  engine_.constant_textures_.emplace(std::move(key), id);
  return id;
}

void Job::append(const std::string& lines) {
  commands_ += lines;
}

void Job::copy(int source, int source_level, int destination, int destination_level) {
  commands_ += "copy " + std::to_string(source) + " " + std::to_string(source_level) + " " +
               std::to_string(destination) + " " + std::to_string(destination_level) + "\n";
}

std::size_t Job::read(int id, int level, int width, int height, int channels, int layers) {
  const auto file = data_file();
  commands_ +=
      "read " + std::to_string(id) + " " + std::to_string(level) + " " + file.string() + "\n";
  FloatImage image(width, height * std::max(1, layers), channels);
  image.layers = layers;
  reads_.push_back({file, std::move(image)});
  return reads_.size() - 1;
}

Status Job::run() {
  PENUMBRA_TRY(engine_.run(*this));
  commands_.clear();
  for (; answered_ < reads_.size(); ++answered_) {
    Read& read = reads_[answered_];
    auto bytes = read_file(read.file);
    if (!bytes) return bytes.error();
    const std::size_t expected = read.image.data.size() * sizeof(float);
    if (bytes->size() != expected) {
      return make_error(Error::Kind::device, read.file.string(),
                        "the host read back " + std::to_string(bytes->size()) + " bytes, not " +
                            std::to_string(expected));
    }
    std::memcpy(read.image.data.data(), bytes->data(), expected);
  }
  return {};
}

FloatImage Job::take(std::size_t read) {
  return std::move(reads_.at(read).image);
}

}  // namespace penumbra::d3d
