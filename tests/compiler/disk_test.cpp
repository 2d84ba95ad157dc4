// Poisson disks: determinism, range errors, geometry and the NVIDIA PCSS whitepaper set.
#include "penumbra/compiler/disk.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <nlohmann/json.hpp>
#include <numbers>

#include "penumbra/library/disk_json.hpp"

namespace penumbra {
namespace {

constexpr const char* kMethods[] = {"best_candidate", "sample_elimination"};

Disk generate(int count, std::uint64_t seed, const char* method) {
  Result<Disk> disk = generate_disk({.count = count, .seed = seed, .method = method});
  EXPECT_TRUE(disk.ok()) << disk.error().to_string();
  return disk.ok() ? *disk : Disk{};
}

std::uint32_t bits(float value) {
  std::uint32_t out = 0;
  std::memcpy(&out, &value, sizeof out);
  return out;
}

TEST(Disk, SameOptionsGiveTheSamePoints) {
  for (const char* method : kMethods) {
    const Disk a = generate(32, 7, method);
    const Disk b = generate(32, 7, method);
    EXPECT_EQ(a.points, b.points) << method;
    EXPECT_NE(a.points, generate(32, 8, method).points) << method;
  }
}

// Pinned values: a change here changes every baked disk (and so the shaders).
TEST(Disk, DefaultDiskIsPinned) {
  const Disk disk = generate(16, 1, "sample_elimination");
  EXPECT_EQ(disk.name, "sample_elimination");
  EXPECT_EQ(disk.method, "sample_elimination");
  EXPECT_EQ(disk.seed, 1u);
  ASSERT_EQ(disk.points.size(), 16u);
  EXPECT_EQ(bits(disk.points[0][0]), 0xbeb684c8u);  // -0.356481791
  EXPECT_EQ(bits(disk.points[0][1]), 0xbf460e0cu);  // -0.773651838
  EXPECT_NEAR(disk.normalized_min_distance, 0.76505482284354076, 1e-12);

  const Disk candidate = generate(16, 1, "best_candidate");
  EXPECT_EQ(bits(candidate.points[0][0]), 0xbdc7d2e2u);  // -0.0975701958
  EXPECT_EQ(bits(candidate.points[0][1]), 0xbf753c50u);  // -0.957951546
}

TEST(Disk, CountOutOfRangeIsAnError) {
  for (int count : {0, 129}) {
    Result<Disk> disk = generate_disk({.count = count, .seed = 1, .method = "sample_elimination"});
    ASSERT_FALSE(disk.ok());
    EXPECT_EQ(disk.error().kind, Error::Kind::bad_input);
    EXPECT_EQ(disk.error().to_string(),
              "sample count " + std::to_string(count) + " is out of range; allowed 1..128");
  }
}

TEST(Disk, UnknownMethodListsTheMethods) {
  Result<Disk> disk = generate_disk({.count = 16, .seed = 1, .method = "lloyd"});
  ASSERT_FALSE(disk.ok());
  EXPECT_EQ(disk.error().kind, Error::Kind::bad_input);
  EXPECT_EQ(disk.error().to_string(),
            "unknown disk method 'lloyd'; allowed methods: best_candidate, sample_elimination, "
            "square_stratified, square_r2");
}

TEST(Disk, EveryCountGivesDistinctPointsInTheUnitDisk) {
  for (const char* method : kMethods) {
    for (int count = 1; count <= kMaxSamples; ++count) {
      const Disk disk = generate(count, 1, method);
      ASSERT_EQ(disk.points.size(), static_cast<std::size_t>(count)) << method;
      for (const Point2& p : disk.points) {
        const double x = p[0];
        const double y = p[1];
        EXPECT_LE(x * x + y * y, 1.0) << method << " count " << count;
      }
      EXPECT_GT(disk.normalized_min_distance, 0.0) << method << " count " << count;
    }
  }
}

// Measured with seed 1 at 16/32/64/128 points:
//   sample_elimination 0.765, 0.741, 0.740, 0.715
//   best_candidate     0.823, 0.742, 0.775, 0.764
// and never below 0.706 over seeds 1..20 at those counts.
TEST(Disk, PointsAreWellSpread) {
  for (const char* method : kMethods) {
    for (int count : {16, 32, 64, 128}) {
      for (std::uint64_t seed = 1; seed <= 10; ++seed) {
        EXPECT_GE(generate(count, seed, method).normalized_min_distance, 0.70)
            << method << " count " << count << " seed " << seed;
      }
    }
  }
}

TEST(Disk, NormalizedMinDistanceDividesByTheHexagonalBound) {
  const Point2 one[] = {{0.5f, 0.5f}};
  EXPECT_EQ(normalized_min_distance(one), 1.0);
  const Point2 two[] = {{-1.0f, 0.0f}, {1.0f, 0.0f}};
  const double bound = std::sqrt(2.0 * std::numbers::pi / (std::sqrt(3.0) * 2.0));
  EXPECT_NEAR(normalized_min_distance(two), 2.0 / bound, 1e-12);
  EXPECT_NEAR(normalized_min_distance(two), 1.48503, 1e-5);
}

constexpr const char* kSquareMethods[] = {"square_stratified", "square_r2"};

TEST(SquareSet, EveryCountGivesDistinctPointsInTheSquare) {
  for (const char* method : kSquareMethods) {
    EXPECT_EQ(sample_shape(method), SampleShape::square);
    for (int count = 1; count <= kMaxSamples; ++count) {
      const Disk set = generate(count, 1, method);
      ASSERT_EQ(set.points.size(), static_cast<std::size_t>(count)) << method;
      for (std::size_t i = 0; i < set.points.size(); ++i) {
        EXPECT_LE(std::abs(set.points[i][0]), 1.0f) << method << " count " << count;
        EXPECT_LE(std::abs(set.points[i][1]), 1.0f) << method << " count " << count;
        for (std::size_t j = 0; j < i; ++j) EXPECT_NE(set.points[i], set.points[j]) << method;
      }
    }
  }
  EXPECT_EQ(sample_shape("sample_elimination"), SampleShape::disk);
}

// square_stratified: rows = floor(sqrt(N)) bands, the first N mod rows with
// one cell more, each band as tall as its cells' share: one point per cell.
TEST(SquareSet, StratifiedPutsOnePointInEachCellOfEqualArea) {
  for (int count : {1, 2, 7, 16, 25, 32, 64, 127}) {
    const Disk set = generate(count, 3, "square_stratified");
    const int rows = static_cast<int>(std::floor(std::sqrt(double(count))));
    std::size_t next = 0;
    double bottom = 0.0;
    for (int r = 0; r < rows; ++r) {
      const int cells = count / rows + (r < count % rows ? 1 : 0);
      const double height = double(cells) / count;
      for (int c = 0; c < cells; ++c, ++next) {
        const double x = (set.points[next][0] + 1.0) / 2, y = (set.points[next][1] + 1.0) / 2;
        // float32 rounding may put a point on its cell's edge.
        EXPECT_GE(x, double(c) / cells - 1e-7) << count;
        EXPECT_LE(x, double(c + 1) / cells + 1e-7) << count;
        EXPECT_GE(y, bottom - 1e-7) << count;
        EXPECT_LE(y, bottom + height + 1e-7) << count;
      }
      bottom += height;
    }
  }
}

// square_r2: consecutive points step by (1/g, 1/g^2) in the unit square,
// g the plastic number, wrapped.
TEST(SquareSet, R2StepsByThePlasticNumber) {
  const Disk set = generate(64, 5, "square_r2");
  constexpr double kG = 1.32471795724474602596;
  for (std::size_t i = 1; i < set.points.size(); ++i) {
    for (int axis = 0; axis < 2; ++axis) {
      const double step = axis == 0 ? 1.0 / kG : 1.0 / (kG * kG);
      const double d =
          (set.points[i][axis] - set.points[i - 1][axis]) / 2.0;  // in unit-square units
      EXPECT_NEAR(d - std::floor(d), step, 1e-6) << i << " axis " << axis;
    }
  }
}

// Pinned: the default manifest's square family; a change here changes its shaders.
TEST(SquareSet, DefaultSquareIsPinned) {
  const Disk set = generate(16, 1, "square_stratified");
  EXPECT_EQ(bits(set.points[0][0]), 0xbf6edd21u);  // -0.933061659
  EXPECT_EQ(bits(set.points[0][1]), 0xbf6e8a37u);  // -0.931796491
  EXPECT_NEAR(set.normalized_min_distance, 0.29, 0.005);
}

TEST(SquareSet, NormalizedMinDistanceUsesTheSquaresArea) {
  const Point2 two[] = {{-1.0f, 0.0f}, {1.0f, 0.0f}};
  const double bound = std::sqrt(2.0 * 4.0 / (std::sqrt(3.0) * 2.0));
  EXPECT_NEAR(normalized_min_distance(two, SampleShape::square), 2.0 / bound, 1e-12);
}

TEST(Disk, Whitepaper16IsTheWhitepapersSet) {
  const Disk disk = whitepaper16();
  EXPECT_EQ(disk.name, "whitepaper16");
  EXPECT_EQ(disk.method, "whitepaper");
  EXPECT_EQ(disk.seed, 0u);
  const std::vector<Point2> expected = {
      {-0.94201624f, -0.39906216f}, {0.94558609f, -0.76890725f},  {-0.094184101f, -0.92938870f},
      {0.34495938f, 0.29387760f},   {-0.91588581f, 0.45771432f},  {-0.81544232f, -0.87912464f},
      {-0.38277543f, 0.27676845f},  {0.97484398f, 0.75648379f},   {0.44323325f, -0.97511554f},
      {0.53742981f, -0.47373420f},  {-0.26496911f, -0.41893023f}, {0.79197514f, 0.19090188f},
      {-0.24188840f, 0.99706507f},  {-0.81409955f, 0.91437590f},  {0.19984126f, 0.78641367f},
      {0.14383161f, -0.14100790f}};
  EXPECT_EQ(disk.points, expected);
  // Kept as published, outside the unit disk.
  EXPECT_NEAR(std::hypot(disk.points[7][0], disk.points[7][1]), 1.2339, 1e-4);
  EXPECT_NEAR(disk.normalized_min_distance, 0.96339, 1e-5);
}

TEST(Disk, JsonHoldsTheBakedBits) {
  const Disk disk = generate(25, 3, "sample_elimination");
  const nlohmann::json parsed = nlohmann::json::parse(disk_to_json(disk).dump());
  EXPECT_EQ(parsed["name"], "sample_elimination");
  EXPECT_EQ(parsed["method"], "sample_elimination");
  EXPECT_EQ(parsed["seed"], 3);
  EXPECT_EQ(parsed["count"], 25);
  EXPECT_EQ(parsed["normalized_min_distance"].get<double>(), disk.normalized_min_distance);
  ASSERT_EQ(parsed["points"].size(), 25u);
  for (std::size_t i = 0; i < disk.points.size(); ++i) {
    for (std::size_t axis = 0; axis < 2; ++axis) {
      const auto value = static_cast<float>(parsed["points"][i][axis].get<double>());
      EXPECT_EQ(bits(value), bits(disk.points[i][axis])) << "point " << i;
    }
  }
}

}  // namespace
}  // namespace penumbra
