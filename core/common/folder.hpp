#pragma once
// Folders as inputs: a path that is a folder, and the files it holds.
#include <string>
#include <vector>

namespace lwb::core {

/// The path names a folder (following symlinks).
bool isFolder(const std::string& path);
/// Whether something (a file, a folder, a device) is at `path`.
bool pathExists(const std::string& path);
/// The folder part of a path with its '/' ("a/b.png" gives "a/"; a bare name gives "").
std::string folderWithSlash(const std::string& path);
/// The regular files of a folder (symlinks followed), hidden ones (a leading '.') left out, as
/// DIR/NAME sorted by name. False with *error ("DIR: cannot open the folder: REASON").
bool listFolder(const std::string& dir, std::vector<std::string>* files, std::string* error);

}  // namespace lwb::core
