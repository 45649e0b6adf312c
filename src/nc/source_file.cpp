#include "nc/source_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <fmt/format.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>

namespace ncurve::nc {

namespace {
constexpr std::size_t kMostLineBytes = std::size_t{1} << 20;  // of a streamed file's line, for quoting

std::size_t read_at(int fd, char* to, std::size_t n, std::size_t offset) {
  std::size_t got = 0;
  while (got < n) {
    const ssize_t r = ::pread(fd, to + got, n - got, static_cast<off_t>(offset + got));
    if (r < 0 && errno == EINTR) continue;
    if (r < 0) throw std::runtime_error(fmt::format("error: cannot read the file ({})", std::strerror(errno)));
    if (r == 0) break;
    got += static_cast<std::size_t>(r);
  }
  return got;
}

// A pipe's bytes into an unnamed temporary file, to be read again where a jump goes back.
int spool(int from, const std::string& name) {
  FILE* tmp = std::tmpfile();
  if (!tmp) throw std::runtime_error(fmt::format("{}: error: no temporary file to hold the program read", name));
  const int to = ::dup(::fileno(tmp));
  std::fclose(tmp);
  if (to < 0) throw std::runtime_error(fmt::format("{}: error: no temporary file to hold the program read", name));
  std::string buf(std::size_t{1} << 16, '\0');
  for (;;) {
    const ssize_t r = ::read(from, buf.data(), buf.size());
    if (r < 0 && errno == EINTR) continue;
    if (r < 0) {
      ::close(to);
      throw std::runtime_error(fmt::format("{}: error: cannot read the file ({})", name, std::strerror(errno)));
    }
    if (r == 0) break;
    for (ssize_t done = 0; done < r;) {
      const ssize_t w = ::write(to, buf.data() + done, static_cast<std::size_t>(r - done));
      if (w < 0 && errno == EINTR) continue;
      if (w <= 0) {
        ::close(to);
        throw std::runtime_error(fmt::format("{}: error: cannot hold the program read in a temporary file", name));
      }
      done += w;
    }
  }
  return to;
}
}  // namespace

SourceFile::SourceFile(std::string name, std::string text) : name_(std::move(name)), text_(std::move(text)) {
  line_starts_.push_back(0);
  const char* begin = text_.data();
  const char* end = begin + text_.size();
  for (const char* p = begin; (p = static_cast<const char*>(std::memchr(p, '\n', end - p))) != nullptr;)
    line_starts_.push_back(static_cast<std::size_t>(++p - begin));
  if (line_starts_.size() > 1 && line_starts_.back() == text_.size()) line_starts_.pop_back();
}

SourceFile::SourceFile(std::string name, int fd, std::size_t skip, std::size_t size)
    : name_(std::move(name)), fd_(fd), skip_(skip), size_(size) {}

SourceFile::~SourceFile() {
  if (fd_ >= 0) ::close(fd_);
}

std::shared_ptr<SourceFile> SourceFile::open_streamed(const std::string& path, std::string name) {
  int fd = path == "-" ? ::dup(0) : ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) throw std::runtime_error(fmt::format("{}: error: cannot open the file", name));
  struct stat st {};
  if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
    int copy = -1;
    try {
      copy = spool(fd, name);
    } catch (...) {
      ::close(fd);
      throw;
    }
    ::close(fd);
    fd = copy;
    if (::fstat(fd, &st) != 0) {
      ::close(fd);
      throw std::runtime_error(fmt::format("{}: error: cannot read the file", name));
    }
  }
  char bom[3] = {};
  const std::size_t size = static_cast<std::size_t>(st.st_size);
  std::size_t skip = 0;
  try {
    if (read_at(fd, bom, 3, 0) == 3 && std::memcmp(bom, "\xEF\xBB\xBF", 3) == 0) skip = 3;
  } catch (const std::runtime_error&) {
    ::close(fd);
    throw std::runtime_error(fmt::format("{}: error: cannot read the file", name));
  }
  return std::shared_ptr<SourceFile>(new SourceFile(std::move(name), fd, skip, size - skip));
}

std::size_t SourceFile::read(std::size_t offset, std::size_t n, std::string& out) const {
  if (whole() || offset >= size_) return 0;
  n = std::min(n, size_ - offset);
  const std::size_t at = out.size();
  out.resize(at + n + 1);  // one byte more: is a CR at the end followed by LF
  std::size_t got;
  try {
    got = read_at(fd_, out.data() + at, n + (offset + n < size_ ? 1 : 0), skip_ + offset);
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(fmt::format("{}: {}", name_, e.what()));
  }
  if (got < n)  // the file shrank after it was opened: its index no longer holds
    throw std::runtime_error(fmt::format("{}: error: the file became shorter while it was read ({} bytes, was {})",
                                         name_, skip_ + offset + got, skip_ + size_));
  const bool peeked = got > n;
  got = n;
  char* p = out.data() + at;
  if (std::memchr(p, '\r', got) == nullptr) {
    out.resize(at + got);
    return got;
  }
  for (std::size_t i = 0; i < got; ++i)
    if (p[i] == '\r' && (i + 1 < got ? p[i + 1] != '\n' : !(peeked && p[got] == '\n'))) p[i] = '\n';
  out.resize(at + got);
  return got;
}

std::string SourceFile::all_text() const {
  if (whole()) return text_;
  std::string out;
  read(0, size_, out);
  return out;
}

void SourceFile::note_line_start(std::uint32_t number, std::size_t offset) const {
  if ((number - 1) / kLineStride == sparse_starts_.size()) sparse_starts_.push_back(offset);
}

std::string SourceFile::line(std::uint32_t number) const {
  if (whole()) {
    if (number == 0 || number > line_starts_.size()) return {};
    std::size_t begin = line_starts_[number - 1];
    std::size_t end = number < line_starts_.size() ? line_starts_[number] : text_.size();
    while (end > begin && (text_[end - 1] == '\n' || text_[end - 1] == '\r')) --end;
    return text_.substr(begin, end - begin);
  }
  if (number == 0 || number > lines_read_) return {};
  const std::size_t k = (number - 1) / kLineStride;
  if (k >= sparse_starts_.size()) return {};
  std::size_t offset = sparse_starts_[k];
  std::uint32_t at = static_cast<std::uint32_t>(k * kLineStride + 1);
  std::string buf, out;
  while (at < number) {  // to the line's start
    buf.clear();
    if (read(offset, std::size_t{1} << 16, buf) == 0) return {};
    std::size_t pos = 0;
    while (at < number) {
      const std::size_t eol = buf.find('\n', pos);
      if (eol == std::string::npos) break;
      ++at;
      pos = eol + 1;
    }
    offset += at < number ? buf.size() : pos;
  }
  while (out.size() < kMostLineBytes) {
    buf.clear();
    if (read(offset, std::size_t{1} << 16, buf) == 0) break;
    const std::size_t eol = buf.find('\n');
    out.append(buf, 0, eol == std::string::npos ? buf.size() : eol);
    if (eol != std::string::npos) break;
    offset += buf.size();
  }
  if (out.size() > kMostLineBytes) out.resize(kMostLineBytes);
  while (!out.empty() && out.back() == '\r') out.pop_back();
  return out;
}

}  // namespace ncurve::nc
