#include "machine/library.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <unordered_set>

namespace ncurve::machine {

namespace {
int number_from_file_name(const std::string& path) {
  std::string stem = std::filesystem::path(path).stem().string();
  if (stem.size() < 2 || (stem[0] != 'O' && stem[0] != 'o')) return -1;
  for (std::size_t i = 1; i < stem.size(); ++i)
    if (!std::isdigit(static_cast<unsigned char>(stem[i]))) return -1;
  if (stem.size() > 9) return -1;
  return std::stoi(stem.substr(1));
}
// Lines before a file's first O number that hold nothing but comments (a title such as "(NEW FILE)"
// after the '%'): the control runs the program the O line starts, not these.
bool header_only(const nc::Program& p) {
  return p.number < 0 && std::ranges::all_of(p.blocks, [](const nc::Block& b) {
           return b.kind == nc::Statement::empty && b.error < 0 && b.sequence < 0;
         });
}
}  // namespace

bool program_file_name(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  // the extensions part programs are kept under (a control holds them by O number whatever the name)
  static const std::array<std::string_view, 10> kProgramExtensions = {".nc", ".cnc", ".tap", ".txt", ".ncc",
                                                                       ".iso", ".eia", ".ptp", ".prg", ".gcode"};
  return std::find(kProgramExtensions.begin(), kProgramExtensions.end(), ext) != kProgramExtensions.end() ||
         number_from_file_name(path) >= 0;
}

ProgramLibrary::ProgramLibrary(nc::ParseOptions options) : options_(options) {}
ProgramLibrary::~ProgramLibrary() = default;

// A program of a file as the control holds it: by its number (or its file name's), the first the main.
// `source`: the file or folder, counted from 1 in the order given; an earlier one's program comes
// first (a streamed main file's programs are entered as they are read, after the folders').
void ProgramLibrary::enter(nc::Program* p, const std::string& name, int from_name, bool is_main, int source,
                           std::vector<nc::Diagnostic>& found) {
  if (p->number < 0 && from_name >= 0) p->number = from_name;
  if (is_main && !main_) main_ = p;
  if (p->number < 0) return;
  auto [it, added] = by_number_.try_emplace(p->number, p);
  if (added || source_of_[p->number] > source) {
    it->second = p;
    source_of_[p->number] = source;
  } else if (source_of_[p->number] == source) {  // a control holds one program a number (PS0073)
    const nc::Program& first = *it->second;
    nc::Diagnostic d{nc::Severity::error, "PS0073",
                     fmt::format("O{:04} is defined twice, at {}:{} and {}:{}: a control holds one program a "
                                 "number (program number already in use)",
                                 p->number, first.file->name(), first.line, name, p->line),
                     nc::Span{p->file.get(), p->line, 1, 1}};
    duplicates_.try_emplace(p->number, d);
    found.push_back(std::move(d));
  }
}

std::vector<nc::Diagnostic> ProgramLibrary::add_text(const std::string& name, std::string text, bool is_main) {
  // A UTF-8 byte-order mark is no part of the program; CR alone ends a line as LF and CRLF do.
  if (text.rfind("\xEF\xBB\xBF", 0) == 0) text.erase(0, 3);
  for (std::size_t i = 0; i < text.size(); ++i)
    if (text[i] == '\r' && (i + 1 == text.size() || text[i + 1] != '\n')) text[i] = '\n';
  auto file = std::make_shared<const nc::SourceFile>(name, std::move(text));
  files_.push_back(file);
  nc::ParseResult r = nc::parse(file, options_);
  problems_left_out_ += r.more_diagnostics;
  unchecked_lines_ += r.unchecked_lines;
  if (!in_folder_) ++source_;
  const int from_name = number_from_file_name(name);
  for (auto& p : r.programs) {
    nc::Program* raw = p.get();
    const bool skipped = header_only(*p) && p != r.programs.back();  // comments before the first O
    programs_.push_back(std::move(p));
    if (!skipped) enter(raw, name, from_name, is_main, source_, r.diagnostics);
  }
  if (is_main && !main_) throw std::runtime_error(fmt::format("{}: error: the file holds no program", name));
  for (const nc::UnreadProgram& u : r.after_end) unread_.try_emplace(u.number, Unread{file.get(), u});
  if (!is_main) return {};
  return std::move(r.diagnostics);
}

// The stream's programs entered as add_text enters a file's: a program of nothing but comments
// before the first O is no program to run.
struct ProgramLibrary::StreamListener : nc::ProgramStream::Listener {
  ProgramLibrary& lib;
  std::string name;
  int from_name;
  std::unordered_set<const nc::Program*> entered;
  StreamListener(ProgramLibrary& l, std::string n) : lib(l), name(std::move(n)), from_name(number_from_file_name(name)) {}
  void program_begun(std::unique_ptr<nc::Program> p) override { lib.programs_.push_back(std::move(p)); }
  void program_content(nc::Program& p) override { enter(p); }
  void program_ended(nc::Program& p, bool has_content, bool last) override {
    if (has_content || last || p.number >= 0) enter(p);
  }
  void enter(nc::Program& p) {
    if (!entered.insert(&p).second) return;
    lib.enter(&p, name, from_name, true, lib.stream_source_, lib.stream_duplicates_);
  }
};

void ProgramLibrary::add_streamed(const std::string& path, const std::string& name, std::size_t chunk_bytes) {
  auto file = nc::SourceFile::open_streamed(path, name);
  files_.push_back(file);
  stream_file_ = file.get();
  if (!in_folder_) ++source_;
  stream_source_ = source_;
  listener_ = std::make_unique<StreamListener>(*this, name);
  stream_ = std::make_unique<nc::ProgramStream>(file, options_, *listener_, chunk_bytes);
  while (!main_ && stream_->advance()) {
  }
  if (!main_) throw std::runtime_error(fmt::format("{}: error: the file holds no program", name));
}

void ProgramLibrary::read_rest() const {
  auto& self = const_cast<ProgramLibrary&>(*this);  // reading on completes what the library holds
  self.stream_->finish();
  const nc::ParseResult r = stream_->problems();
  self.problems_left_out_ += r.more_diagnostics;
  self.unchecked_lines_ += r.unchecked_lines;
  for (const nc::UnreadProgram& u : r.after_end) self.unread_.try_emplace(u.number, Unread{stream_file_, u});
  stream_counted_ = true;
}

std::vector<nc::Diagnostic> ProgramLibrary::streamed_problems() const {
  read_all();
  std::vector<nc::Diagnostic> all = stream_->problems().diagnostics;
  all.insert(all.end(), stream_duplicates_.begin(), stream_duplicates_.end());
  return all;
}

std::vector<nc::Diagnostic> ProgramLibrary::add_file(const std::string& path, bool is_main) {
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) throw std::runtime_error(fmt::format("{}: error: cannot open the file", path));
  std::string text(static_cast<std::size_t>(in.tellg()), '\0');  // one copy of the file, however large
  in.seekg(0);
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  if (!in) throw std::runtime_error(fmt::format("{}: error: cannot read the file", path));
  return add_text(path, std::move(text), is_main);
}

std::vector<nc::Diagnostic> ProgramLibrary::add_folder(const std::string& dir) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) throw std::runtime_error(fmt::format("{}: error: not a folder", dir));
  std::vector<std::string> paths;
  for (const auto& e : fs::directory_iterator(dir, ec))
    if (e.is_regular_file() && program_file_name(e.path().string())) paths.push_back(e.path().string());
  std::sort(paths.begin(), paths.end());
  std::vector<nc::Diagnostic> all;
  ++source_;
  in_folder_ = true;
  try {
    for (const auto& p : paths) {
      auto d = add_file(p);
      all.insert(all.end(), d.begin(), d.end());
    }
  } catch (...) {
    in_folder_ = false;
    throw;
  }
  in_folder_ = false;
  return all;
}

const nc::Program* ProgramLibrary::find(int number) const {
  read_all();
  auto it = by_number_.find(number);
  return it == by_number_.end() ? nullptr : it->second;
}

const ProgramLibrary::Unread* ProgramLibrary::unread(int number) const {
  read_all();
  auto it = unread_.find(number);
  return it == unread_.end() ? nullptr : &it->second;
}

}  // namespace ncurve::machine
