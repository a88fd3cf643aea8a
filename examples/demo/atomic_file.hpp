// An output file that appears whole or not at all. Everything is written to a
// temporary file in the target's directory, and commit() renames it over the
// target: rename() within one file system is atomic, so no reader (and no
// crash) ever sees a half-written target, and a failure leaves an existing
// target as it was.
#pragma once

#include <fstream>
#include <string>

namespace demo {

class atomic_file {
 public:
  // Creates the temporary; throws std::runtime_error naming the target when
  // it cannot (the target's directory does not exist) or when the target is
  // there and not a regular file (a folder, a device: a rename would put the
  // output in place of /dev/null). A file replaced keeps its permissions,
  // and a symbolic link is followed: the file it names is replaced.
  explicit atomic_file(const std::string& path);
  // Removes the temporary unless commit() succeeded.
  ~atomic_file();
  atomic_file(const atomic_file&) = delete;
  atomic_file& operator=(const atomic_file&) = delete;

  std::ostream& stream() { return out_; }

  // Throws std::runtime_error, with the system's reason, once a write to the
  // stream has failed (a full disk): a long run stops there, not at its end.
  void check();

  // Closes the temporary and renames it over the target; throws
  // std::runtime_error when either fails.
  void commit();

  // Whether two paths name the same file, however spelled ("a.json",
  // "./a.json"), whether or not it exists yet.
  static bool same_target(const std::string& a, const std::string& b);

 private:
  std::string path_;    // as given: named in messages
  std::string target_;  // the file replaced: path_, or where its link leads
  std::string temporary_;
  std::ofstream out_;
  bool committed_ = false;
};

}  // namespace demo
