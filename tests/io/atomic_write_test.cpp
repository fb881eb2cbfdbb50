// SPDX-License-Identifier: GPL-3.0-or-later
// Atomic writes: all or nothing, and no temporary file left behind.
#include <filesystem>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include "io/atomic_write.h"
#include "support/run_command.h"

namespace roomcad {
namespace {

namespace fs = std::filesystem;

std::size_t entries(const fs::path& dir) {
  std::size_t n = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++n;
  return n;
}

TEST(AtomicWrite, WritesANewFile) {
  test::TempDir dir;
  ASSERT_TRUE(write_file_atomically(dir / "a.txt", std::string_view("hello\n")).ok());
  EXPECT_EQ(test::read_bytes(dir / "a.txt"), "hello\n");
  EXPECT_EQ(entries(dir.path()), 1u);
  // Permissions as for any new file: 0666 less the umask.
  const mode_t mask = ::umask(0);
  ::umask(mask);
  struct stat info {};
  ASSERT_EQ(::stat((dir / "a.txt").c_str(), &info), 0);
  EXPECT_EQ(info.st_mode & 0777, 0666 & ~mask);
}

TEST(AtomicWrite, ReplacesAnExistingFileKeepingItsMode) {
  test::TempDir dir;
  ASSERT_TRUE(test::write_bytes(dir / "a.txt", "old contents that are longer"));
  ASSERT_EQ(::chmod((dir / "a.txt").c_str(), 0640), 0);
  ASSERT_TRUE(write_file_atomically(dir / "a.txt", std::string_view("new")).ok());
  EXPECT_EQ(test::read_bytes(dir / "a.txt"), "new");
  struct stat info {};
  ASSERT_EQ(::stat((dir / "a.txt").c_str(), &info), 0);
  EXPECT_EQ(info.st_mode & 0777, 0640u);
  EXPECT_EQ(entries(dir.path()), 1u);
}

TEST(AtomicWrite, LargeContentThroughTheStream) {
  test::TempDir dir;
  const Status s = write_file_atomically(dir / "big.bin", [](std::ostream& out) {
    for (int i = 0; i < 200000; ++i) out << i << '\n';
    return true;
  });
  ASSERT_TRUE(s.ok()) << s.message();
  const std::string bytes = test::read_bytes(dir / "big.bin");
  EXPECT_EQ(bytes.substr(0, 6), "0\n1\n2\n");
  EXPECT_EQ(bytes.substr(bytes.size() - 7), "199999\n");
}

TEST(AtomicWrite, AbandonedWriteLeavesTheOldFileAndNoTemporary) {
  test::TempDir dir;
  ASSERT_TRUE(test::write_bytes(dir / "a.txt", "precious"));
  const Status declined = write_file_atomically(dir / "a.txt", [](std::ostream& out) {
    out << std::string(100000, 'x');  // more than the buffer: partly on disk already
    return false;
  });
  EXPECT_FALSE(declined.ok());
  EXPECT_NE(declined.message().find("a.txt"), std::string::npos) << declined.message();
  EXPECT_NE(declined.message().find("abandoned"), std::string::npos) << declined.message();
  EXPECT_EQ(test::read_bytes(dir / "a.txt"), "precious");
  EXPECT_EQ(entries(dir.path()), 1u);

  const Status thrown = write_file_atomically(dir / "a.txt", [](std::ostream& out) -> bool {
    out << std::string(100000, 'y');
    throw std::runtime_error("mesh is broken");
  });
  EXPECT_FALSE(thrown.ok());
  EXPECT_NE(thrown.message().find("mesh is broken"), std::string::npos) << thrown.message();
  EXPECT_EQ(test::read_bytes(dir / "a.txt"), "precious");
  EXPECT_EQ(entries(dir.path()), 1u);
}

TEST(AtomicWrite, MissingDirectoryNamesThePathAndTheReason) {
  test::TempDir dir;
  const Status s = write_file_atomically(dir / "no" / "such" / "a.txt", std::string_view("x"));
  EXPECT_FALSE(s.ok());
  EXPECT_NE(s.message().find((dir / "no" / "such" / "a.txt").string()), std::string::npos)
      << s.message();
  EXPECT_NE(s.message().find("No such file or directory"), std::string::npos) << s.message();
  EXPECT_EQ(entries(dir.path()), 0u);
}

TEST(AtomicWrite, TargetThatIsADirectoryIsLeftAlone) {
  test::TempDir dir;
  fs::create_directory(dir / "d");
  ASSERT_TRUE(test::write_bytes(dir / "d" / "inside", "keep"));
  const Status s = write_file_atomically(dir / "d", std::string_view("x"));
  EXPECT_FALSE(s.ok());
  EXPECT_NE(s.message().find((dir / "d").string()), std::string::npos) << s.message();
  EXPECT_EQ(test::read_bytes(dir / "d" / "inside"), "keep");
  EXPECT_EQ(entries(dir.path()), 1u);
}

TEST(AtomicWrite, EmptyPathIsAnError) {
  EXPECT_FALSE(write_file_atomically("", std::string_view("x")).ok());
  EXPECT_FALSE(write_file_atomically("some/dir/", std::string_view("x")).ok());
}

}  // namespace
}  // namespace roomcad
