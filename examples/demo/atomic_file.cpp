#include "atomic_file.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>

namespace demo {

namespace {

std::runtime_error failure(const std::string& what, const std::string& path) {
  return std::runtime_error("cannot " + what + " " + path + ": " + std::strerror(errno));
}

}  // namespace

// The process id keeps two demos writing the same target from sharing a
// temporary; the same directory keeps the final rename on one file system.
atomic_file::atomic_file(const std::string& path)
    : path_(path), temporary_(path + ".tmp." + std::to_string(getpid())) {
  out_.open(temporary_, std::ios::out | std::ios::trunc);
  if (!out_) throw failure("create", temporary_);
}

atomic_file::~atomic_file() {
  if (committed_) return;
  out_.close();
  std::remove(temporary_.c_str());
}

void atomic_file::commit() {
  out_.close();  // flushes; a failed write or flush sets failbit
  if (!out_) throw failure("write", temporary_);
  if (std::rename(temporary_.c_str(), path_.c_str()) != 0) throw failure("replace", path_);
  committed_ = true;
}

}  // namespace demo
