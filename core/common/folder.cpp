#include "core/common/folder.hpp"

#include <dirent.h>
#include <sys/stat.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

namespace lwb::core {

bool isFolder(const std::string& path) {
    struct stat st {};
    return ::stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode);
}

bool listFolder(const std::string& dir, std::vector<std::string>* files, std::string* error) {
    DIR* d = ::opendir(dir.c_str());
    if (!d) {
        if (error) *error = dir + ": cannot open the folder: " + std::strerror(errno);
        return false;
    }
    while (const dirent* e = ::readdir(d)) {
        const std::string name = e->d_name;
        if (name.empty() || name[0] == '.') continue;
        const std::string full = dir + (!dir.empty() && dir.back() == '/' ? "" : "/") + name;
        struct stat st {};
        if (::stat(full.c_str(), &st) == 0 && S_ISREG(st.st_mode)) files->push_back(full);
    }
    ::closedir(d);
    std::sort(files->begin(), files->end());
    return true;
}

std::string folderWithSlash(const std::string& path) {
    const size_t slash = path.find_last_of('/');
    return slash == std::string::npos ? std::string() : path.substr(0, slash + 1);
}

bool pathExists(const std::string& path) {
    struct stat st {};
    return ::stat(path.c_str(), &st) == 0;
}

}  // namespace lwb::core
