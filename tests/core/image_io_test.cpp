// Writing and reading images: round trips, and failures that leave nothing behind.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <random>
#include <string>

#include "parashade/errors.hpp"
#include "parashade/image.hpp"

namespace parashade {
namespace {

namespace fs = std::filesystem;

class ImageIo : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("parashade-image-io-" + std::to_string(::getpid()) + "-" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::size_t entries() const {
    return std::size_t(std::distance(fs::directory_iterator(dir_), fs::directory_iterator()));
  }

  fs::path dir_;
};

RenderedImage test_image(int width, int height) {
  RenderedImage im;
  im.width = width;
  im.height = height;
  std::mt19937 rng(7);
  for (int i = 0; i < width * height; ++i) {
    for (int c = 0; c < 3; ++c) im.rgba.push_back(std::uint8_t(rng() & 255));
    im.rgba.push_back(255);
  }
  return im;
}

TEST_F(ImageIo, PngRoundTripIsExact) {
  const RenderedImage im = test_image(13, 7);
  const fs::path path = dir_ / "frame.png";
  write_image(path, im);
  const RenderedImage back = read_image(path);
  EXPECT_EQ(back.width, 13);
  EXPECT_EQ(back.height, 7);
  EXPECT_EQ(back.rgba, im.rgba);
  EXPECT_TRUE(back.rgb_float.empty());
  EXPECT_EQ(entries(), 1u);  // no temporary left beside it
}

TEST_F(ImageIo, RewritingReplacesTheFile) {
  const fs::path path = dir_ / "frame.ppm";
  write_image(path, test_image(4, 4));
  RenderedImage second = test_image(4, 4);
  second.rgba[0] ^= 0xff;
  write_image(path, second);
  EXPECT_EQ(read_image(path).rgba, second.rgba);
  EXPECT_EQ(entries(), 1u);
}

TEST_F(ImageIo, ExrKeepsFloatValues) {
  RenderedImage im = test_image(5, 3);
  for (int i = 0; i < 5 * 3 * 3; ++i)
    im.rgb_float.push_back(0.37f * float(i * i) - 3.0f);  // unclamped, fractional
  const fs::path path = dir_ / "frame.exr";
  write_image(path, im);
  const RenderedImage back = read_image(path);
  ASSERT_EQ(back.rgb_float.size(), im.rgb_float.size());
  for (std::size_t i = 0; i < im.rgb_float.size(); ++i)
    EXPECT_NEAR(back.rgb_float[i], im.rgb_float[i], 1e-5f * std::max(1.0f, std::abs(im.rgb_float[i])));
}

TEST_F(ImageIo, ExrFromEightBitValues) {
  const RenderedImage im = test_image(3, 2);
  const fs::path path = dir_ / "frame.exr";
  write_image(path, im);
  const RenderedImage back = read_image(path);
  ASSERT_EQ(back.rgb_float.size(), 3u * 6u);
  for (std::size_t p = 0; p < 6; ++p)
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(back.rgb_float[3 * p + c], float(im.rgba[4 * p + c]), 1e-4f);
}

TEST_F(ImageIo, UnknownExtensionIsAnInputErrorAndLeavesNothing) {
  const fs::path path = dir_ / "frame.notanimage";
  try {
    write_image(path, test_image(2, 2));
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
  }
  EXPECT_EQ(entries(), 0u);
}

TEST_F(ImageIo, MissingDirectoryIsAnInputErrorAndLeavesNothing) {
  const fs::path path = dir_ / "no-such-dir" / "frame.png";
  try {
    write_image(path, test_image(2, 2));
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
  }
  EXPECT_EQ(entries(), 0u);
}

TEST_F(ImageIo, FailedRenameRemovesTheTemporary) {
  // The image is written, but a non-empty directory holds the destination name: rename must fail.
  const fs::path path = dir_ / "frame.png";
  fs::create_directories(path / "occupied");
  EXPECT_THROW(write_image(path, test_image(2, 2)), InputError);
  EXPECT_EQ(entries(), 1u);
  EXPECT_TRUE(fs::is_directory(path));
}

TEST_F(ImageIo, ReadingAMissingFileIsAnInputError) {
  EXPECT_THROW(read_image(dir_ / "absent.png"), InputError);
}

}  // namespace
}  // namespace parashade
