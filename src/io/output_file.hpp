// A file written whole or not at all: the text goes to a temporary beside the requested name and
// is renamed onto it only once every write and the close have succeeded. "-" is standard output;
// a device or pipe (/dev/null, /dev/stdout) is written in place, its writes checked the same.
#pragma once
#include <fstream>
#include <memory>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace ncurve::io {

// A write that failed or was refused; what() names the path and the reason.
struct OutputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class OutputFile {
public:
  // Opens the temporary. Refuses a path that names one of `inputs` (the program being read).
  explicit OutputFile(std::string path, const std::vector<std::string>& inputs = {});
  ~OutputFile();  // removes the temporary of an output never committed
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  std::ostream& stream() { return *out_; }
  bool is_stdout() const { return path_ == "-"; }
  const std::string& path() const { return path_; }
  // Flushes, checks and closes the stream and renames the temporary onto the path.
  void commit();

private:
  std::string path_;
  std::string temporary_;  // empty when writing in place
  std::unique_ptr<char[]> buffer_;  // the file stream's: large writes, few system calls
  std::ofstream file_;
  std::ostream* out_;
  bool committed_ = false;
};

// The whole of `text` to `path` through an OutputFile.
void write_file(const std::string& path, const std::string& text, const std::vector<std::string>& inputs = {});
// Flushes standard output and throws OutputError if any write to it failed.
void check_stdout();
// Whether `path` names the same file as one of `inputs` ("-" names none).
bool same_file(const std::string& path, const std::vector<std::string>& inputs);

}  // namespace ncurve::io
