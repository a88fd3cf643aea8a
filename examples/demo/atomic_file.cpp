#include "atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <system_error>

namespace demo {

namespace {

std::runtime_error failure(const std::string& what, const std::string& path, int error) {
  return std::runtime_error(
      "cannot " + what + " " + path +
      (error != 0 ? std::string(": ") + std::strerror(error) : std::string()));
}

}  // namespace

// The process id and a count keep two demos, or two outputs of one, from
// sharing a temporary; the same directory keeps the final rename on one file
// system. The temporary is made anew (O_EXCL): never a file already there.
atomic_file::atomic_file(const std::string& path) : path_(path), target_(path) {
  std::error_code ignored;
  const std::filesystem::file_status status = std::filesystem::status(path, ignored);
  if (std::filesystem::exists(status) && !std::filesystem::is_regular_file(status)) {
    throw std::runtime_error("cannot write " + path + ": it exists and is not a regular file");
  }
  // A symbolic link stays a link: the file it names is replaced (renaming
  // over the link itself would put a plain file in its place).
  // (Followed link by link: a link to a file not made yet leads to it too.)
  std::filesystem::path followed = path;
  for (int links = 0;
       std::filesystem::is_symlink(std::filesystem::symlink_status(followed, ignored)); ++links) {
    std::error_code error;
    const std::filesystem::path next = std::filesystem::read_symlink(followed, error);
    if (error) throw failure("follow the link", path, error.value());
    if (links == 40) throw failure("follow the link", path, ELOOP);
    followed = next.is_absolute() ? next : followed.parent_path() / next;
  }
  target_ = followed.string();
  static std::atomic<int> count{0};
  temporary_ = target_ + ".tmp." + std::to_string(getpid()) + "." + std::to_string(count++);
  const int made = ::open(temporary_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
  if (made < 0) throw failure("create a file beside", path, errno);
  ::close(made);
  // A file replaced keeps its permissions (a private 600 stays private).
  if (std::filesystem::is_regular_file(status)) {
    std::filesystem::permissions(temporary_, status.permissions(), ignored);
  }
  out_.open(temporary_, std::ios::out | std::ios::trunc);
  if (!out_) {
    const int error = errno;
    std::remove(temporary_.c_str());
    throw failure("create a file beside", path, error);
  }
}

atomic_file::~atomic_file() {
  if (committed_) return;
  out_.close();
  std::remove(temporary_.c_str());
}

void atomic_file::check() {
  // (Right after the write that failed: errno is still its reason.)
  if (!out_) throw failure("write", path_, errno);
}

void atomic_file::commit() {
  errno = 0;     // a reason left from earlier calls is not this one's
  out_.close();  // flushes; a failed write or flush sets failbit
  if (!out_) throw failure("write", path_, errno);
  if (std::rename(temporary_.c_str(), target_.c_str()) != 0) throw failure("replace", path_, errno);
  committed_ = true;
}

bool atomic_file::same_target(const std::string& a, const std::string& b) {
  // (Made absolute first: libstdc++ leaves a relative path none of whose
  // parts exist as it is, "a.json" against "/here/a.json" for "./a.json".)
  std::error_code error_a, error_b;
  const std::filesystem::path x =
      std::filesystem::weakly_canonical(std::filesystem::absolute(a, error_a), error_a);
  const std::filesystem::path y =
      std::filesystem::weakly_canonical(std::filesystem::absolute(b, error_b), error_b);
  if (!error_a && !error_b) return x == y;
  return a == b;
}

}  // namespace demo
