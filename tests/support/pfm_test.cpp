#include "penumbra/support/pfm.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <string>

#include "temp_dir.hpp"

namespace penumbra {
namespace {

void write_bytes(const std::filesystem::path& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

std::string read_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The four bytes of `value` in big-endian order.
std::string big_endian(float value) {
  std::uint32_t word = 0;
  std::memcpy(&word, &value, 4);
  std::string bytes(4, '\0');
  for (int k = 0; k < 4; ++k) bytes[k] = char((word >> (24 - 8 * k)) & 0xff);
  return bytes;
}

FloatImage ramp(int width, int height, int channels) {
  FloatImage image(width, height, channels);
  for (std::size_t k = 0; k < image.data.size(); ++k) image.data[k] = 0.25f * float(k) - 3.0f;
  return image;
}

std::string read_error(const std::filesystem::path& path) {
  const auto image = read_pfm(path);
  EXPECT_FALSE(image.ok());
  return image.ok() ? "" : image.error().to_string();
}

TEST(FloatImageBytes, SameBytesComparesValuesBitForBitAndTheShape) {
  FloatImage a(2, 1, 1);
  a.data = {std::nanf(""), 1.0f};
  FloatImage b = a;
  EXPECT_TRUE(same_bytes(a, b));  // a NaN equals itself
  b.data[1] = -0.0f;
  a.data[1] = 0.0f;
  EXPECT_FALSE(same_bytes(a, b));  // -0 is not 0
  EXPECT_FALSE(same_bytes(FloatImage(2, 1, 1), FloatImage(1, 2, 1)));
  EXPECT_FALSE(same_bytes(FloatImage(2, 1, 1), FloatImage(2, 1, 2)));
}

TEST(Pfm, RoundTripsOneChannel) {
  testing::TempDir dir;
  const FloatImage image = ramp(5, 3, 1);
  ASSERT_TRUE(write_pfm(dir.path() / "a.pfm", image));
  EXPECT_EQ(read_bytes(dir.path() / "a.pfm").substr(0, 12), "Pf\n5 3\n-1.0\n");
  const auto back = read_pfm(dir.path() / "a.pfm");
  ASSERT_TRUE(back.ok()) << back.error().to_string();
  EXPECT_EQ(back->width, 5);
  EXPECT_EQ(back->height, 3);
  EXPECT_EQ(back->channels, 1);
  EXPECT_EQ(back->data, image.data);
}

TEST(Pfm, RoundTripsThreeChannels) {
  testing::TempDir dir;
  const FloatImage image = ramp(4, 7, 3);
  ASSERT_TRUE(write_pfm(dir.path() / "b.pfm", image));
  const auto back = read_pfm(dir.path() / "b.pfm");
  ASSERT_TRUE(back.ok()) << back.error().to_string();
  EXPECT_EQ(back->channels, 3);
  EXPECT_EQ(back->width, 4);
  EXPECT_EQ(back->height, 7);
  EXPECT_EQ(back->data, image.data);
}

TEST(Pfm, FirstStoredRowIsRowZero) {
  testing::TempDir dir;
  FloatImage image(2, 2, 1);
  image.at(0, 0) = 1.0f;  // row j = 0 must come first in the file, unflipped
  image.at(1, 1) = 4.0f;
  ASSERT_TRUE(write_pfm(dir.path() / "rows.pfm", image));
  const std::string bytes = read_bytes(dir.path() / "rows.pfm");
  float first = 0.0f;
  std::memcpy(&first, bytes.data() + std::string("Pf\n2 2\n-1.0\n").size(), 4);
  EXPECT_EQ(first, 1.0f);
}

TEST(Pfm, ReadsBigEndian) {
  testing::TempDir dir;
  std::string bytes = "PF\n1 2\n1.0\n";  // two rows: row j = 0 is stored first
  for (float value : {1.0f, -2.5f, 3.0f, 0.125f, 1e-3f, 7.0f}) bytes += big_endian(value);
  write_bytes(dir.path() / "be.pfm", bytes);
  const auto image = read_pfm(dir.path() / "be.pfm");
  ASSERT_TRUE(image.ok()) << image.error().to_string();
  EXPECT_EQ(image->data, (std::vector<float>{1.0f, -2.5f, 3.0f, 0.125f, 1e-3f, 7.0f}));
}

TEST(Pfm, AcceptsAnyWhitespaceInTheHeader) {
  testing::TempDir dir;
  std::string bytes = "Pf  2\t1\r\n-1\n";
  for (float value : {0.5f, 2.0f}) bytes.append(reinterpret_cast<const char*>(&value), 4);
  write_bytes(dir.path() / "ws.pfm", bytes);
  const auto image = read_pfm(dir.path() / "ws.pfm");
  ASSERT_TRUE(image.ok()) << image.error().to_string();
  EXPECT_EQ(image->data, (std::vector<float>{0.5f, 2.0f}));
}

TEST(Pfm, RejectsBadMagic) {
  testing::TempDir dir;
  write_bytes(dir.path() / "p6.pfm", "P6\n1 1\n255\nabc");
  const std::string error = read_error(dir.path() / "p6.pfm");
  EXPECT_NE(error.find("p6.pfm"), std::string::npos) << error;
  EXPECT_NE(error.find("bad magic 'P6'"), std::string::npos) << error;
}

TEST(Pfm, RejectsBadSize) {
  testing::TempDir dir;
  write_bytes(dir.path() / "size.pfm", "Pf\n0 4\n-1.0\n");
  const std::string error = read_error(dir.path() / "size.pfm");
  EXPECT_NE(error.find("size.pfm"), std::string::npos) << error;
  EXPECT_NE(error.find("bad size '0 4'"), std::string::npos) << error;

  write_bytes(dir.path() / "text.pfm", "Pf\nwide 4\n-1.0\n");
  EXPECT_NE(read_error(dir.path() / "text.pfm").find("bad size"), std::string::npos);
}

TEST(Pfm, RejectsBadScale) {
  testing::TempDir dir;
  write_bytes(dir.path() / "scale.pfm", "Pf\n1 1\n0\nabcd");
  EXPECT_NE(read_error(dir.path() / "scale.pfm").find("bad scale '0'"), std::string::npos);
}

TEST(Pfm, RejectsTruncatedData) {
  testing::TempDir dir;
  write_bytes(dir.path() / "short.pfm", "PF\n2 2\n-1.0\n" + std::string(47, 'x'));
  const std::string error = read_error(dir.path() / "short.pfm");
  EXPECT_NE(error.find("short.pfm"), std::string::npos) << error;
  EXPECT_NE(error.find("truncated data"), std::string::npos) << error;
  EXPECT_NE(error.find("need 48 bytes, found 47"), std::string::npos) << error;
}

TEST(Pfm, RejectsExtraData) {
  testing::TempDir dir;
  write_bytes(dir.path() / "long.pfm", "Pf\n1 1\n-1.0\n" + std::string(8, 'x'));
  EXPECT_NE(read_error(dir.path() / "long.pfm").find("4 bytes of extra data"), std::string::npos);
}

TEST(Pfm, MissingFileIsAnIoError) {
  testing::TempDir dir;
  const auto image = read_pfm(dir.path() / "none.pfm");
  ASSERT_FALSE(image.ok());
  EXPECT_EQ(image.error().kind, Error::Kind::io);
  EXPECT_NE(image.error().where.find("none.pfm"), std::string::npos);
}

TEST(Pfm, WriteRejectsFourChannels) {
  testing::TempDir dir;
  const auto status = write_pfm(dir.path() / "rgba.pfm", FloatImage(1, 1, 4));
  ASSERT_FALSE(status.ok());
  EXPECT_NE(status.error().message.find("1 or 3 channels"), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "rgba.pfm"));
}

}  // namespace
}  // namespace penumbra
