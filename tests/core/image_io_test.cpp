// Writing and reading images: round trips, and failures that leave nothing behind.
#include <OpenImageIO/imageio.h>
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>

#include "parashade/errors.hpp"
#include "parashade/image.hpp"
#include "parashade/output_file.hpp"

namespace parashade {
namespace {

namespace fs = std::filesystem;

class ImageIo : public ::testing::Test {
 protected:
  void SetUp() override {
    // A parameterized test's name holds a '/' ("Name/png"): as a path it made a folder inside a folder, and
    // TearDown removed only the inner one, leaving an empty folder in the temporary directory per run.
    std::string name = ::testing::UnitTest::GetInstance()->current_test_info()->name();
    std::replace(name.begin(), name.end(), '/', '-');
    dir_ = fs::temp_directory_path() / ("parashade-image-io-" + std::to_string(::getpid()) + "-" + name);
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

// OpenImageIO says only "Could not open file"; the message gives the system's reason (issue 17, item 16).
TEST_F(ImageIo, ReadErrorsGiveTheSystemsReason) {
  const auto message = [](const fs::path& p) {
    try {
      read_image(p);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message(dir_ / "absent.png").find("No such file or directory"), std::string::npos) << message(dir_ / "absent.png");
  fs::create_symlink(dir_ / "b.png", dir_ / "a.png");
  fs::create_symlink(dir_ / "a.png", dir_ / "b.png");
  EXPECT_NE(message(dir_ / "a.png").find("Too many levels of symbolic links"), std::string::npos) << message(dir_ / "a.png");
  fs::create_directories(dir_ / "folder.png");
  EXPECT_NE(message(dir_ / "folder.png").find("is a directory"), std::string::npos) << message(dir_ / "folder.png");
  for (const char* name : {"absent.png", "a.png", "folder.png"})
    EXPECT_EQ(message(dir_ / name).find("Could not open"), std::string::npos) << message(dir_ / name);
}

std::string file_bytes(const fs::path& p) {
  std::ostringstream s;
  s << std::ifstream(p, std::ios::binary).rdbuf();
  return s.str();
}

// The child side of write_with_file_size_limit: a fresh process (exec'd, so no thread pool of OIIO or
// OpenEXR is inherited half-alive from the parent, which made a forked child hang in its EXR write)
// whose files may not grow past PARASHADE_CHILD_LIMIT bytes (RLIMIT_FSIZE, SIGXFSZ ignored: a write past
// it fails with EFBIG, as on a full disk it fails with ENOSPC). It writes a 256x256 image of random
// pixels, or 100 000 bytes of text, to PARASHADE_CHILD_PATH and leaves the InputError's message ("ok"
// when it wrote) in PARASHADE_CHILD_MESSAGE. Run only by the tests below.
TEST(ImageIoChild, DISABLED_WriteUnderAFileSizeLimit) {
  const char* path = std::getenv("PARASHADE_CHILD_PATH");
  const char* message_file = std::getenv("PARASHADE_CHILD_MESSAGE");
  const char* limit_text = std::getenv("PARASHADE_CHILD_LIMIT");
  ASSERT_TRUE(path && message_file && limit_text);
  ::signal(SIGXFSZ, SIG_IGN);
  const rlim_t limit = rlim_t(std::stoull(limit_text));
  const rlimit rl{limit, limit};
  ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &rl), 0);
  std::string message = "ok";
  try {
    if (fs::path(path).extension() == ".json")
      stage_text(path, std::string(100000, ' ')).commit();
    else if (std::getenv("PARASHADE_CHILD_STAGE_ONLY"))
      stage_image(path, test_image(256, 256));  // the failure must show here, before any commit()
    else
      write_image(path, test_image(256, 256));  // random pixels: far more than the limit in any format
  } catch (const InputError& e) {
    message = e.what();
  } catch (const std::exception& e) {
    message = std::string("other exception: ") + e.what();
  }
  std::ofstream(message_file) << message;  // a few bytes: under the limit
}

std::string write_with_file_size_limit(rlim_t limit, const fs::path& path, bool stage_only = false) {
  const fs::path message_file = path.parent_path().parent_path() / (path.filename().string() + ".message");
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::setenv("PARASHADE_CHILD_PATH", path.c_str(), 1);
    ::setenv("PARASHADE_CHILD_MESSAGE", message_file.c_str(), 1);
    ::setenv("PARASHADE_CHILD_LIMIT", std::to_string(limit).c_str(), 1);
    if (stage_only) ::setenv("PARASHADE_CHILD_STAGE_ONLY", "1", 1);
    const int null = ::open("/dev/null", O_WRONLY);
    if (null < 0 || ::dup2(null, 1) < 0) ::_exit(126);
    ::execl("/proc/self/exe", "/proc/self/exe", "--gtest_filter=ImageIoChild.DISABLED_WriteUnderAFileSizeLimit",
            "--gtest_also_run_disabled_tests", static_cast<char*>(nullptr));
    ::_exit(127);
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  const std::string message = file_bytes(message_file);
  fs::remove(message_file);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    return "child failed (status " + std::to_string(status) + "): " + message;
  return message;
}

// Issue 17, item 1: a write that fails part-way (full disk) must not replace the good file, must leave
// no temporary file and must name the file and the system's error. PNG, BMP and TGA used to rename the
// truncated file into place and report success; JPEG left its temporary file.
class ImageIoFullDisk : public ImageIo, public ::testing::WithParamInterface<std::string> {};

TEST_P(ImageIoFullDisk, FailedWriteKeepsTheOldFileAndLeavesNoTemporary) {
  const fs::path path = dir_ / ("frame." + GetParam());
  write_image(path, test_image(4, 4));
  const std::string before = file_bytes(path);
  const std::string message = write_with_file_size_limit(8192, path);
  EXPECT_NE(message.find("cannot write " + path.string()), std::string::npos) << message;
  EXPECT_NE(message.find(std::strerror(EFBIG)), std::string::npos) << message;
  EXPECT_EQ(file_bytes(path), before);
  EXPECT_EQ(entries(), 1u);
}

INSTANTIATE_TEST_SUITE_P(Formats, ImageIoFullDisk, ::testing::Values("png", "bmp", "tga", "jpg", "tif", "exr", "ppm"));

// The write path's two checks, each with a test that fails without it (issue 46, "tests that bind"): with
// both in place, removing either one passed every test above, since the other caught the same failure.
// stage_image's: a failed write throws from stage_image itself, before anything could commit it.
TEST_F(ImageIo, StageImageThrowsOnAFailedWriteBeforeAnyCommit) {
  const fs::path path = dir_ / "frame.png";
  const std::string message = write_with_file_size_limit(8192, path, /*stage_only=*/true);
  EXPECT_NE(message.find("cannot write " + path.string()), std::string::npos) << message;
  EXPECT_NE(message.find(std::strerror(EFBIG)), std::string::npos) << message;
  EXPECT_EQ(entries(), 0u);
}

// commit()'s: a staged file whose write failed is never renamed over the destination; commit() throws, the
// previous file stays byte for byte and the temporary file goes.
TEST_F(ImageIo, CommitOfAFailedStagedFileKeepsTheOldFile) {
  const fs::path path = dir_ / "report.json";
  stage_text(path, "{}\n").commit();
  StagedFile file(path);
  file.open_fd();
  ASSERT_TRUE(file.pwrite_all("[1", 2, 0));
  file.fail("No space left on device");  // as pwrite_all records a failed write
  try {
    file.commit();
    ADD_FAILURE() << "commit() of a failed file did not throw";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("cannot write " + path.string() + ": No space left on device"),
              std::string::npos) << e.what();
  }
  EXPECT_EQ(file_bytes(path), "{}\n");
  EXPECT_EQ(entries(), 1u);
}

TEST_F(ImageIo, FailedTextWriteKeepsTheOldFileAndLeavesNoTemporary) {
  const fs::path path = dir_ / "report.json";
  stage_text(path, "{}\n").commit();
  const std::string message = write_with_file_size_limit(4096, path);
  EXPECT_NE(message.find("cannot write " + path.string()), std::string::npos) << message;
  EXPECT_NE(message.find(std::strerror(EFBIG)), std::string::npos) << message;
  EXPECT_EQ(file_bytes(path), "{}\n");
  EXPECT_EQ(entries(), 1u);
}

// Item 3: an uncommitted staged file goes with its owner, and a signal removes it (the handler runs in a
// child that is stopped with SIGTERM while the file is staged).
TEST_F(ImageIo, SigtermRemovesStagedFilesAndExitsWith143) {
  const fs::path path = dir_ / "frame.png";
  int fds[2];
  ASSERT_EQ(::pipe(fds), 0);
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::close(fds[0]);
    install_signal_cleanup();
    StagedFile image = stage_image(path, test_image(8, 8));
    StagedFile text = stage_text(dir_ / "report.json", "{}");
    if (::write(fds[1], "s", 1) != 1) ::_exit(2);
    ::pause();
    ::_exit(0);
  }
  ::close(fds[1]);
  char c = 0;
  ASSERT_EQ(::read(fds[0], &c, 1), 1);
  ::close(fds[0]);
  EXPECT_EQ(entries(), 2u);  // the two temporary files
  ::kill(pid, SIGTERM);
  int status = 0;
  ::waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFEXITED(status)) << "ended by signal " << WTERMSIG(status);
  EXPECT_EQ(WEXITSTATUS(status), 128 + SIGTERM);
  EXPECT_EQ(entries(), 0u);
}

// Item 4: a replaced file keeps its permission bits; a new one gets the umask's.
TEST_F(ImageIo, ReplacedFilesKeepTheirPermissionBits) {
  const mode_t mask = ::umask(022);
  ::umask(mask);
  const auto mode_of = [](const fs::path& p) {
    struct stat st {};
    ::stat(p.c_str(), &st);
    return st.st_mode & 07777;
  };
  const fs::path image = dir_ / "frame.png", text = dir_ / "report.json";
  write_image(image, test_image(2, 2));
  stage_text(text, "{}").commit();
  EXPECT_EQ(mode_of(image), 0666u & ~mask);
  EXPECT_EQ(mode_of(text), 0666u & ~mask);
  for (const mode_t mode : {mode_t(0444), mode_t(0600), mode_t(0640)}) {
    ::chmod(image.c_str(), mode);
    ::chmod(text.c_str(), mode);
    write_image(image, test_image(2, 2));
    stage_text(text, "{}").commit();
    EXPECT_EQ(mode_of(image), mode) << std::oct << mode;
    EXPECT_EQ(mode_of(text), mode) << std::oct << mode;
  }
}

// Item 17: TIFF and EXR carry no time stamp (OIIO wrote DateTime / capDate), so identical runs give
// identical bytes whatever second they run in.
TEST_F(ImageIo, TiffAndExrHoldNoTimeStamp) {
  for (const std::string ext : {"tif", "exr"}) {
    const fs::path a = dir_ / ("a." + ext), b = dir_ / ("b." + ext);
    write_image(a, test_image(6, 5));
    write_image(b, test_image(6, 5));
    EXPECT_EQ(file_bytes(a), file_bytes(b)) << ext;
    auto in = OIIO::ImageInput::open(a.string());
    ASSERT_TRUE(in) << ext;
    const OIIO::ParamValue* date = in->spec().find_attribute("DateTime");
    EXPECT_TRUE(date == nullptr || date->get_string().empty())
        << ext << " holds DateTime " << (date ? date->get_string() : "");
  }
}

}  // namespace
}  // namespace parashade
