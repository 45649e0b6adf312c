// The programs a run can reach: the main file and macro library folders, by O number.
#pragma once
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "nc/program.hpp"
#include "nc/program_stream.hpp"

namespace ncurve::machine {

// Whether a folder's file is read as a program (add_folder, `ncurve run FOLDER`): one of the
// extensions part programs are kept under (.nc, .cnc, .tap, .txt, .ncc, .iso, .eia, .ptp, .prg,
// .gcode, any case), or a name of O and a number (O9010).
bool program_file_name(const std::string& path);

class ProgramLibrary {
public:
  explicit ProgramLibrary(nc::ParseOptions options = {});
  ~ProgramLibrary();
  ProgramLibrary(const ProgramLibrary&) = delete;
  ProgramLibrary& operator=(const ProgramLibrary&) = delete;
  // Parses a file and registers its programs; a program without an O line takes its number from a
  // file name like O9010.nc. Returns the syntax problems of the main file; those of a library file stay
  // attached to their blocks only, to alarm when a block of it is reached.
  std::vector<nc::Diagnostic> add_text(const std::string& name, std::string text, bool is_main = false);
  std::vector<nc::Diagnostic> add_file(const std::string& path, bool is_main = false);
  // The main file read block by block as the run reaches it (nc::ProgramStream), a pipe ("-") too:
  // its programs are found as they are read, its problems are complete once read_all() has run.
  void add_streamed(const std::string& path, const std::string& name,
                    std::size_t chunk_bytes = nc::ProgramStream::kChunkBytes);
  // Reads the rest of a streamed main file; then its problems (as add_file returns them) are complete.
  void read_all() const {
    if (stream_ && !stream_counted_) read_rest();
  }
  std::vector<nc::Diagnostic> streamed_problems() const;
  bool streamed() const { return stream_ != nullptr; }
  // Problems found beyond the first nc::kMaxDiagnostics of each file, counted only.
  std::size_t problems_left_out() const { return problems_left_out_; }
  // Lines not parsed because no block on them can run (nc::ParseResult::unchecked_lines).
  std::size_t unchecked_lines() const { return unchecked_lines_; }
  // Every program file of the folder (program_file_name).
  std::vector<nc::Diagnostic> add_folder(const std::string& dir);

  // (A streamed main file is read to its end first: a program it defines later comes first.)
  const nc::Program* find(int number) const;
  // A program that is in a file only after the '%' that ends it (never read), or null.
  struct Unread {
    const nc::SourceFile* file;
    nc::UnreadProgram where;
  };
  const Unread* unread(int number) const;
  // PS0073 when two programs of one file or one folder carry this number (find() gives the first).
  // The file run and earlier folders come before later folders, as a search path.
  const nc::Diagnostic* duplicate(int number) const {
    read_all();
    if (duplicates_.empty()) return nullptr;
    auto it = duplicates_.find(number);
    return it == duplicates_.end() ? nullptr : &it->second;
  }
  const nc::Program* main() const { return main_; }
  // The main file's programs in order, as read so far (all of them once a streamed file is read).
  const std::vector<std::unique_ptr<nc::Program>>& programs() const { return programs_; }
  const std::vector<std::shared_ptr<const nc::SourceFile>>& files() const { return files_; }

private:
  struct StreamListener;
  void read_rest() const;
  void enter(nc::Program* p, const std::string& name, int from_name, bool is_main, int source,
             std::vector<nc::Diagnostic>& found);

  nc::ParseOptions options_;
  std::vector<std::shared_ptr<const nc::SourceFile>> files_;
  std::vector<std::unique_ptr<nc::Program>> programs_;
  std::map<int, const nc::Program*> by_number_;
  std::map<int, Unread> unread_;
  std::map<int, nc::Diagnostic> duplicates_;
  std::map<int, int> source_of_;  // number -> the file or folder (counted from 1) that defined it
  int source_ = 0;
  std::size_t problems_left_out_ = 0;
  std::size_t unchecked_lines_ = 0;
  bool in_folder_ = false;
  const nc::Program* main_ = nullptr;
  std::unique_ptr<StreamListener> listener_;
  std::unique_ptr<nc::ProgramStream> stream_;
  std::vector<nc::Diagnostic> stream_duplicates_;
  const nc::SourceFile* stream_file_ = nullptr;
  int stream_source_ = 0;
  mutable bool stream_counted_ = false;
};

}  // namespace ncurve::machine
