// SPDX-License-Identifier: GPL-3.0-or-later
#include "io/atomic_write.h"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <streambuf>
#include <string>
#include <vector>

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

namespace roomcad {
namespace {

/// An output stream buffer over a file descriptor that remembers the first write error.
class FdStreamBuf : public std::streambuf {
 public:
  explicit FdStreamBuf(int fd) : fd_(fd), buffer_(1 << 16) {
    setp(buffer_.data(), buffer_.data() + buffer_.size());
  }
  int error() const { return error_; }

 protected:
  int_type overflow(int_type c) override {
    if (!flush_buffer()) return traits_type::eof();
    if (!traits_type::eq_int_type(c, traits_type::eof())) {
      *pptr() = traits_type::to_char_type(c);
      pbump(1);
    }
    return traits_type::not_eof(c);
  }
  int sync() override { return flush_buffer() ? 0 : -1; }

 private:
  bool flush_buffer() {
    const char* at = pbase();
    while (at < pptr() && error_ == 0) {
      const ssize_t n = ::write(fd_, at, static_cast<std::size_t>(pptr() - at));
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) {
        error_ = n < 0 ? errno : EIO;
        break;
      }
      at += n;
    }
    setp(buffer_.data(), buffer_.data() + buffer_.size());
    return error_ == 0;
  }

  int fd_;
  std::vector<char> buffer_;
  int error_ = 0;
};

/// The mode a new file gets (0666 less the umask), or the existing file's mode.
mode_t mode_for(const std::string& target) {
  struct stat info {};
  if (::stat(target.c_str(), &info) == 0 && S_ISREG(info.st_mode)) return info.st_mode & 07777;
  const mode_t mask = ::umask(0);
  ::umask(mask);
  return 0666 & ~mask;
}

/// The folder a target lives in.
std::filesystem::path folder_of(const std::filesystem::path& target) {
  return target.has_parent_path() ? target.parent_path() : std::filesystem::path(".");
}

/// The start of the names of the target's temporary files: `.<name>.tmp-`; the writer's
/// process id, a dash and six random characters follow.
std::string temporary_prefix(const std::filesystem::path& target) {
  std::string prefix = target.filename().string();
  prefix.insert(prefix.begin(), '.');  // appends, not operator+: GCC 12 warns falsely there
  prefix.append(".tmp-");
  return prefix;
}

/// Removes the temporary files of `target` left by writers that were killed midway (a
/// destructor cannot run after SIGKILL or a power cut): those whose process no longer exists.
/// A live writer's file is never touched, so concurrent saves stay safe. Best effort: errors
/// are ignored. O(entries of the folder).
void remove_stale_temporaries(const std::filesystem::path& target) {
  const std::string prefix = temporary_prefix(target);
  std::error_code error;
  for (auto it = std::filesystem::directory_iterator(folder_of(target), error);
       !error && it != std::filesystem::directory_iterator(); it.increment(error)) {
    const std::string leaf = it->path().filename().string();
    if (!leaf.starts_with(prefix)) continue;
    const std::string rest = leaf.substr(prefix.size());  // "<pid>-XXXXXX"
    const std::size_t dash = rest.find('-');
    if (dash == std::string::npos || dash == 0 || rest.size() - dash != 7 ||
        rest.find_first_not_of("0123456789") != dash)
      continue;
    const long pid = std::strtol(rest.c_str(), nullptr, 10);
    if (pid > 0 && ::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH)
      std::filesystem::remove(it->path(), error);
  }
}

/// A temporary file beside the target, removed unless committed.
class TemporaryFile {
 public:
  explicit TemporaryFile(const std::filesystem::path& target) {
    std::string leaf = temporary_prefix(target);
    leaf.append(std::to_string(::getpid())).append("-XXXXXX");
    name_ = (folder_of(target) / leaf).string();
    fd_ = ::mkstemp(name_.data());
    if (fd_ < 0) error_ = errno;
    created_ = fd_ >= 0;
  }
  ~TemporaryFile() {
    if (fd_ >= 0) ::close(fd_);
    if (created_ && !committed_) ::unlink(name_.c_str());
  }
  TemporaryFile(const TemporaryFile&) = delete;
  TemporaryFile& operator=(const TemporaryFile&) = delete;

  int fd() const { return fd_; }
  bool created() const { return created_; }
  int error() const { return error_; }
  const std::string& name() const { return name_; }

  /// Flushes to disk, closes and renames over `target`. @return 0 or an errno value.
  int commit(const std::string& target, mode_t mode) {
    if (::fchmod(fd_, mode) != 0) return errno;
    if (::fsync(fd_) != 0) return errno;
    const int fd = fd_;
    fd_ = -1;
    if (::close(fd) != 0) return errno;
    if (::rename(name_.c_str(), target.c_str()) != 0) return errno;
    committed_ = true;
    return 0;
  }

 private:
  std::string name_;
  int fd_ = -1;
  int error_ = 0;
  bool created_ = false;
  bool committed_ = false;
};

/// Flushes the folder's entries to disk, so that the rename survives a power cut.
/// @return 0 or an errno value. EINVAL (a file system that cannot flush a folder, such as
/// some network and FUSE ones) counts as done: there is nothing more a program can do there.
int sync_directory(const std::filesystem::path& target) {
  const int fd = ::open(folder_of(target).c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return errno;
  const int error = ::fsync(fd) == 0 || errno == EINVAL ? 0 : errno;
  ::close(fd);
  return error;
}

Status fail(const std::filesystem::path& path, std::string_view what, int error) {
  return Status::failure(
      Code::io_error, "cannot write " + path.string() + ": " + std::string(what) +
                          (error > 0 ? std::string(": ") + std::strerror(error) : std::string()));
}

}  // namespace

Status write_file_atomically(const std::filesystem::path& path,
                             const std::function<bool(std::ostream&)>& produce) {
  if (path.empty() || !path.has_filename()) return fail(path, "not a file name", 0);
  const std::string target = path.string();
  const mode_t mode = mode_for(target);
  remove_stale_temporaries(path);
  TemporaryFile temp(path);
  if (!temp.created()) return fail(path, "cannot create a temporary file beside it", temp.error());

  FdStreamBuf buffer(temp.fd());
  std::ostream stream(&buffer);
  bool produced = false;
  try {
    produced = produce(stream);
  } catch (const std::exception& e) {
    return fail(path, std::string("writing was abandoned: ") + e.what(), 0);
  } catch (...) {
    return fail(path, "writing was abandoned", 0);
  }
  if (!produced) return fail(path, "writing was abandoned", 0);
  stream.flush();
  if (buffer.error() != 0) return fail(path, "write failed", buffer.error());
  if (!stream) return fail(path, "write failed", EIO);
  if (const int e = temp.commit(target, mode); e != 0) return fail(path, "write failed", e);
  if (const int e = sync_directory(path); e != 0)
    return fail(path,
                "the new file is in place, but its folder could not be flushed to disk, so "
                "a power cut may still bring back the old one",
                e);
  return Status::success();
}

Status write_file_atomically(const std::filesystem::path& path, std::string_view bytes) {
  return write_file_atomically(path, [bytes](std::ostream& out) {
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    return true;
  });
}

}  // namespace roomcad
