// Output files written whole or not at all. Each file is written to a temporary file in its
// own folder and renamed into place once complete and flushed to disk, so an interrupted run
// (an error, a full disk, Ctrl-C) leaves the earlier file or none, never a half-written one;
// on SIGINT, SIGTERM, SIGHUP and SIGPIPE the temporaries are removed before the process ends.
// An existing file is replaced only when the caller allows it (the commands' --force). A
// device or a FIFO (/dev/null, /dev/stdout, a pipe) is written in place: there is no file to
// keep whole.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace exactccd::oracle {

/// Whether an existing regular file may be replaced (--force).
enum class Overwrite { refuse, replace };

/// Throws OutputError ("PATH: what") unless `path` can be written: not a directory, not an
/// existing regular file unless `overwrite` is replace, in an existing folder. `option` (e.g.
/// "--out") is named in the message of a refusal. Writes nothing; used to refuse before work.
void check_output_path(const std::string& path, Overwrite overwrite, const std::string& option);

class OutputFile {
 public:
  /// Checks `path` as check_output_path does, then creates the temporary file (or opens the
  /// device). Throws OutputError.
  OutputFile(const std::string& path, Overwrite overwrite, const std::string& option);
  /// Without commit(): removes the temporary file; the destination is untouched.
  ~OutputFile();
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  /// Buffered; throws OutputError when a write fails (a full disk: "No space left on device").
  void write(std::string_view text);
  /// Writes what is buffered, flushes to disk, closes, and renames into place (without
  /// replacing a file that appeared meanwhile unless allowed). Throws OutputError.
  void commit();

  const std::string& path() const { return path_; }

 private:
  void flush_buffer();
  void discard();

  std::string path_;        // as given, for messages
  std::string destination_; // the file renamed onto (symbolic links resolved)
  std::string temporary_;   // empty when writing in place
  Overwrite overwrite_;
  int fd_ = -1;
  int slot_ = -1;           // in the registry of temporaries removed on a signal
  std::string buffer_;
};

/// Writes `text` to `path` through an OutputFile.
void write_file_atomically(const std::string& path, std::string_view text, Overwrite overwrite,
                           const std::string& option);

/// Warns, on one line, that `files` (under `folder`), outputs of an earlier run that this run
/// did not replace, were left in place: nothing is ever deleted. Nothing when `files` is empty.
void warn_files_left_in_place(const std::vector<std::string>& files, const std::string& folder);

}  // namespace exactccd::oracle
