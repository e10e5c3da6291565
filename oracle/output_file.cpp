#include "oracle/output_file.hpp"

#include <fcntl.h>
#include <limits.h>
#include <signal.h>
#include <stdio.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <mutex>
#include <system_error>

#include "oracle/common.hpp"

namespace exactccd::oracle {

namespace {

namespace fs = std::filesystem;

std::string system_message(int error) {
  return std::error_code(error, std::generic_category()).message();
}

// ---- Temporaries removed on a signal ----------------------------------------------------------

// A fixed table, so that the handler reads it without locks or allocation: state 0 free, 1
// being filled, 2 holding the path of a live temporary.
struct Slot {
  std::atomic<int> state{0};
  char path[PATH_MAX];
};
constexpr int kSlots = 64;
Slot g_slots[kSlots];

extern "C" void remove_temporaries_and_reraise(int signal_number) {
  for (Slot& slot : g_slots)
    if (slot.state.load() == 2) ::unlink(slot.path);
  // SA_RESETHAND restored the default action; it ends the process once the handler returns.
  ::raise(signal_number);
}

void install_signal_handlers() {
  static std::once_flag once;
  std::call_once(once, [] {
    for (const int signal_number : {SIGINT, SIGTERM, SIGHUP, SIGPIPE}) {
      struct sigaction current {};
      if (::sigaction(signal_number, nullptr, &current) != 0 || current.sa_handler == SIG_IGN)
        continue;  // an ignored signal (nohup) stays ignored
      struct sigaction action {};
      action.sa_handler = remove_temporaries_and_reraise;
      sigemptyset(&action.sa_mask);
      action.sa_flags = SA_RESETHAND;
      ::sigaction(signal_number, &action, nullptr);
    }
  });
}

// The slot now holding `path`, or -1 when the table is full (the temporary is then still
// removed on every ordinary exit, only not on a signal).
int register_temporary(const std::string& path) {
  install_signal_handlers();
  if (path.size() >= PATH_MAX) return -1;
  for (int k = 0; k < kSlots; ++k) {
    int expected = 0;
    if (!g_slots[k].state.compare_exchange_strong(expected, 1)) continue;
    std::memcpy(g_slots[k].path, path.c_str(), path.size() + 1);
    g_slots[k].state.store(2);
    return k;
  }
  return -1;
}

void unregister_temporary(int slot) {
  if (slot >= 0) g_slots[slot].state.store(0);
}

// ---- Destinations ---------------------------------------------------------------------------

struct Destination {
  std::string path;     // the file to rename onto (symbolic links resolved)
  bool exists = false;  // a regular file is there
  bool in_place = false;  // a device or FIFO: written directly
  mode_t mode = 0;      // of the existing file
};

Destination examine(const std::string& path, Overwrite overwrite, const std::string& option) {
  if (path.empty()) throw UsageError(option + ": the file name is empty");
  if (path.find('\0') != std::string::npos)  // the C library would write to a shorter path
    throw UsageError(option + ": the file name contains a NUL byte");
  Destination d;
  d.path = path;
  struct stat status {};
  if (::stat(path.c_str(), &status) == 0) {
    if (S_ISDIR(status.st_mode))
      throw OutputError(path, "is a directory, not a file (" + option + ")");
    if (!S_ISREG(status.st_mode)) {
      d.in_place = true;
      return d;
    }
    if (overwrite == Overwrite::refuse)
      throw OutputError(path, "exists; pass --force to replace it (" + option + ")");
    d.exists = true;
    d.mode = status.st_mode & 07777;
    std::error_code error;
    d.path = fs::canonical(path, error).string();  // replace a link's target, not the link
    if (error) throw OutputError(path, error.message());
    return d;
  }
  const int error = errno;
  struct stat link {};
  if (error == ENOENT && ::lstat(path.c_str(), &link) == 0)
    throw OutputError(path, "is a symbolic link to a missing file (" + option + ")");
  if (error != ENOENT) throw OutputError(path, system_message(error));
  fs::path folder = fs::path(path).parent_path();
  if (folder.empty()) folder = ".";
  if (::stat(folder.c_str(), &status) != 0)
    throw OutputError(path, "cannot create the file: " + folder.string() + ": " +
                                system_message(errno) + " (" + option + ")");
  if (!S_ISDIR(status.st_mode))
    throw OutputError(path, "cannot create the file: " + folder.string() +
                                " is not a directory (" + option + ")");
  return d;
}

// Renames `from` onto `to`; unless `replace`, fails with EEXIST when `to` exists (atomically:
// renameat2 RENAME_NOREPLACE, or link + unlink where the file system lacks it). 0 or errno.
int rename_into_place(const std::string& from, const std::string& to, bool replace) {
  if (replace) return ::rename(from.c_str(), to.c_str()) == 0 ? 0 : errno;
  if (::renameat2(AT_FDCWD, from.c_str(), AT_FDCWD, to.c_str(), RENAME_NOREPLACE) == 0) return 0;
  if (errno != EINVAL && errno != ENOSYS) return errno;
  if (::link(from.c_str(), to.c_str()) != 0) return errno;
  ::unlink(from.c_str());
  return 0;
}

constexpr std::size_t kBufferBytes = 1 << 20;

}  // namespace

void check_output_path(const std::string& path, Overwrite overwrite, const std::string& option) {
  examine(path, overwrite, option);
}

OutputFile::OutputFile(const std::string& path, Overwrite overwrite, const std::string& option)
    : path_(path), overwrite_(overwrite) {
  const Destination d = examine(path, overwrite, option);
  destination_ = d.path;
  if (d.in_place) {
    fd_ = ::open(path.c_str(), O_WRONLY | O_CLOEXEC);
    if (fd_ < 0) throw OutputError(path, "cannot open for writing: " + system_message(errno));
    return;
  }
  const fs::path target(destination_);
  fs::path folder = target.parent_path();
  if (folder.empty()) folder = ".";
  // A hidden name in the same folder, so that the rename stays within one file system.
  const std::string stem = (folder / ("." + target.filename().string() + ".tmp-")).string() +
                           std::to_string(::getpid()) + "-";
  static std::atomic<unsigned> counter{0};
  for (int attempt = 0; attempt < 100 && fd_ < 0; ++attempt) {
    temporary_ = stem + std::to_string(counter++);
    // Registered before it exists, so that no signal can leave it behind.
    slot_ = register_temporary(temporary_);
    fd_ = ::open(temporary_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd_ >= 0) break;
    const int error = errno;
    unregister_temporary(slot_);
    slot_ = -1;
    temporary_.clear();
    if (error != EEXIST)
      throw OutputError(path, "cannot create a file in " + folder.string() + ": " +
                                  system_message(error));
  }
  if (fd_ < 0) throw OutputError(path, "cannot create a temporary file in " + folder.string());
  if (d.exists) ::fchmod(fd_, d.mode);  // the replacement keeps the replaced file's permissions
}

OutputFile::~OutputFile() { discard(); }

void OutputFile::discard() {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
  if (!temporary_.empty()) ::unlink(temporary_.c_str());
  unregister_temporary(slot_);
  slot_ = -1;
  temporary_.clear();
}

void OutputFile::write(std::string_view text) {
  if (fd_ < 0) throw OutputError(path_, "write after the file was closed");
  buffer_.append(text);
  if (buffer_.size() >= kBufferBytes) flush_buffer();
}

void OutputFile::flush_buffer() {
  std::size_t done = 0;
  while (done < buffer_.size()) {
    const ssize_t n = ::write(fd_, buffer_.data() + done, buffer_.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const int error = n < 0 ? errno : EIO;
      discard();
      throw OutputError(path_, "write failed: " + system_message(error));
    }
    done += static_cast<std::size_t>(n);
  }
  buffer_.clear();
}

void OutputFile::commit() {
  if (fd_ < 0) throw OutputError(path_, "write after the file was closed");
  flush_buffer();
  const bool in_place = temporary_.empty();
  // On disk before the rename: a crash then leaves the old file or the whole new one.
  if (!in_place && ::fsync(fd_) != 0) {
    const int error = errno;
    discard();
    throw OutputError(path_, "write failed: " + system_message(error));
  }
  const int closed = ::close(fd_);
  const int close_error = errno;
  fd_ = -1;
  if (closed != 0) {
    discard();
    throw OutputError(path_, "write failed: " + system_message(close_error));
  }
  if (in_place) return;
  const int error =
      rename_into_place(temporary_, destination_, overwrite_ == Overwrite::replace);
  if (error != 0) {
    discard();
    throw OutputError(path_, error == EEXIST
                                 ? "appeared while it was being written; pass --force to "
                                   "replace it"
                                 : "cannot rename the finished file into place: " +
                                       system_message(error));
  }
  unregister_temporary(slot_);
  slot_ = -1;
  temporary_.clear();
}

void write_file_atomically(const std::string& path, std::string_view text, Overwrite overwrite,
                           const std::string& option) {
  OutputFile file(path, overwrite, option);
  file.write(text);
  file.commit();
}

void warn_files_left_in_place(const std::vector<std::string>& files, const std::string& folder) {
  if (files.empty()) return;
  warn(std::to_string(files.size()) + " file(s) under " + folder +
       " not written by this run, left in place (an earlier run's; a check of the folder reads "
       "them too): " + files.front() + (files.size() > 1 ? ", ..." : ""));
}

}  // namespace exactccd::oracle
