// The files `ncurve serve FILE...` offers the page (GET /api/files): each FILE, a folder's part
// programs, and beside a program its setup (NAME.setup.toml), which the page's Part cuts the stock by.
#pragma once
#include <string>
#include <vector>

namespace ncurve::serve {

// The paths to serve, in order: the files given and each folder's programs (its regular files named
// as the page's Open takes them: .nc .cnc .tap .txt .ncc .iso .eia .ptp .prg .gcode, by name; not
// hidden ones nor those of its subfolders), then the setups found beside the .nc programs. Throws
// std::runtime_error for anything but a regular file or folder, a folder without a program, or two
// files of one name.
std::vector<std::string> served_files(const std::vector<std::string>& given);

}  // namespace ncurve::serve
