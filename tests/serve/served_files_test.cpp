// The files `ncurve serve FILE...` offers: a folder's part programs by name, with the setups beside
// them; what cannot be served refused at the start.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include <fmt/format.h>

#include "serve/served_files.hpp"

namespace ncurve::serve {
namespace {
namespace fs = std::filesystem;

struct Folder {
  Folder() : path(fs::temp_directory_path() / fmt::format("ncurve-served-{}-{}", ::getpid(), count++)) {
    fs::remove_all(path);
    fs::create_directories(path / "sub");
  }
  ~Folder() { fs::remove_all(path); }
  std::string file(const std::string& name, const std::string& text = "G00 X1.\nM30\n") const {
    std::ofstream(path / name) << text;
    return (path / name).string();
  }
  fs::path path;
  static inline int count = 0;
};

TEST(ServedFiles, AFolderOffersItsProgramsByNameAndTheirSetups) {
  Folder d;
  const std::string b = d.file("b.nc"), a = d.file("a.NC"), tap = d.file("c.tap"), setup = d.file("b.setup.toml", "");
  d.file("notes.md");
  d.file(".hidden.nc");
  d.file("sub/d.nc");
  d.file("a.nc~");
  const std::vector<std::string> want{a, b, tap, setup};  // the programs by name, then b.nc's setup
  EXPECT_EQ(served_files({d.path.string()}), want);
  // a file given beside the folder comes where it is given; the same name twice is refused
  Folder other;
  const std::string one = other.file("one.nc");
  EXPECT_EQ(served_files({one, d.path.string()}), (std::vector<std::string>{one, a, b, tap, setup}));
  EXPECT_THROW(served_files({d.path.string(), b}), std::runtime_error);
}

TEST(ServedFiles, AFolderWithoutAProgramIsRefused) {
  Folder d;
  d.file("notes.md");
  try {
    served_files({d.path.string()});
    FAIL() << "served";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("holds no part program"), std::string::npos) << e.what();
  }
  // `ncurve serve FOLDER` says so and exits 2
  const std::string err = (d.path / "err").string();
  const int status = std::system(fmt::format("timeout 10 {} serve --port 0 {} > /dev/null 2> {}", NCURVE_BINARY,
                                             d.path.string(), err).c_str());
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 2) << status;
  std::ifstream in(err);
  const std::string message((std::istreambuf_iterator<char>(in)), {});
  EXPECT_NE(message.find("holds no part program"), std::string::npos) << message;
}

}  // namespace
}  // namespace ncurve::serve
