#include "core/footprint/shot_list.hpp"

#include <climits>
#include <cstdlib>
#include <map>
#include <sys/stat.h>
#include <unistd.h>

#include "core/common/csv.hpp"
#include "core/common/folder.hpp"
#include "core/common/text.hpp"
#include "core/footprint/image_io.hpp"
#include "core/footprint/trend.hpp"

namespace lwb::core::footprint {

namespace {
std::string nameOf(const std::string& path) {
    const size_t slash = path.find_last_of('/');
    return slash == std::string::npos ? path : path.substr(slash + 1);
}
// An absolute, symlink-free spelling when the file exists, else the path made absolute.
std::string absolute(const std::string& path) {
    if (char* r = ::realpath(path.c_str(), nullptr)) {
        std::string s(r);
        std::free(r);
        return s;
    }
    if (!path.empty() && path[0] == '/') return path;
    char cwd[PATH_MAX];
    return ::getcwd(cwd, sizeof cwd) ? std::string(cwd) + "/" + path : path;
}
}  // namespace

bool isShotListFile(const std::string& path) {
    if (path.size() < 4 || toLower(path.substr(path.size() - 4)) != ".csv") return false;
    struct stat st {};
    return ::stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode);
}

ShotListResult readShotList(const std::string& path) {
    ShotListResult res;
    const CsvReadResult csv = readCsv(path);
    if (!csv.ok) {
        res.error = csv.error;
        return res;
    }
    const CsvTable& t = csv.table;
    const int cf = t.column("file"), ct = t.column("time"), cb = t.column("beam"), cc = t.column("camera"),
              cx = t.column("center_x"), cy = t.column("center_y");
    if (cf < 0) {
        res.error = path + ":1: a shot list needs a 'file' column (optional: time, beam, camera, center_x, center_y)";
        return res;
    }
    if ((cx < 0) != (cy < 0)) {
        res.error = path + ":1: center_x and center_y go together (the list has only " +
                    std::string(cx < 0 ? "center_y" : "center_x") + ")";
        return res;
    }
    const std::string base = folderWithSlash(path);
    for (size_t r = 0; r < t.rows.size(); ++r) {
        const auto& row = t.rows[r];
        const std::string where = whereInFile(path, t.lines[r]);
        ShotSpec s;
        s.source = path;
        s.line = t.lines[r];
        const std::string f(trim(row[size_t(cf)]));
        if (f.empty()) {
            res.error = where + "empty file";
            return res;
        }
        s.file = f[0] == '/' ? f : base + f;
        if (ct >= 0) s.time = std::string(trim(row[size_t(ct)]));
        if (cb >= 0) s.beam = std::string(trim(row[size_t(cb)]));
        if (cc >= 0) s.camera = std::string(trim(row[size_t(cc)]));
        std::string month, why;
        if (!s.time.empty() && !monthOf(s.time, &month, &why)) {
            res.error = where + "time \"" + printableExcerpt(s.time) + "\": " + why;
            return res;
        }
        if (cx >= 0) {
            const std::string x(trim(row[size_t(cx)])), y(trim(row[size_t(cy)]));
            if (x.empty() != y.empty()) {
                res.error = where + "center_x and center_y go together (one of them is empty)";
                return res;
            }
            if (!x.empty()) {
                if (!parseDouble(x, &s.centerX) || !parseDouble(y, &s.centerY)) {
                    res.error = where + "center_x/center_y must be numbers, not \"" + printableExcerpt(x) + "\", \"" +
                                printableExcerpt(y) + "\"";
                    return res;
                }
                s.hasCenter = true;
            }
        }
        res.shots.push_back(std::move(s));
    }
    res.ok = true;
    return res;
}

bool expandShots(const std::vector<std::string>& inputs, std::vector<ShotSpec>* out, std::string* error, bool keepMissing) {
    for (const std::string& in : inputs) {
        if (isShotListFile(in)) {
            ShotListResult l = readShotList(in);
            if (!l.ok) {
                *error = l.error;
                return false;
            }
            for (auto& s : l.shots) out->push_back(std::move(s));
            continue;
        }
        std::vector<std::string> files;
        if (!expandInputs({in}, &files, error, keepMissing)) return false;
        for (auto& f : files) {
            ShotSpec s;
            s.file = std::move(f);
            out->push_back(std::move(s));
        }
    }
    return true;
}

void FrameIndex::add(const std::string& file, size_t row) {
    const std::string path = absolute(file);
    std::vector<size_t>& rows = m_byPath[path];
    if (rows.empty()) m_pathsByName[nameOf(file)].push_back(path);  // (the name as written, as a shot's is looked up)
    rows.push_back(row);
}

const std::vector<size_t>& FrameIndex::atPath(const std::string& file) const {
    static const std::vector<size_t> kNone;
    const auto it = m_byPath.find(absolute(file));
    return it == m_byPath.end() ? kNone : it->second;
}

const std::vector<size_t>& FrameIndex::rowsOf(const std::string& file) const {
    const std::vector<size_t>& here = atPath(file);
    if (!here.empty()) return here;
    const auto n = m_pathsByName.find(nameOf(file));
    return n != m_pathsByName.end() && n->second.size() == 1 ? m_byPath.at(n->second.front()) : here;
}

bool applyFrameMetadata(const ShotListResult& metadata, std::vector<ShotSpec>* shots, size_t* unmatched,
                        std::string* error) {
    FrameIndex index;
    for (size_t k = 0; k < metadata.shots.size(); ++k) {
        const ShotSpec& m = metadata.shots[k];
        index.add(m.file, k);
        if (const std::vector<size_t>& rows = index.atPath(m.file); rows.size() > 1) {
            *error = whereInFile(m.source, m.line) + m.file + " is described already at line " +
                     std::to_string(metadata.shots[rows.front()].line) +
                     " (frame metadata: one row per frame; a frame with two beams is two rows of a shot list)";
            return false;
        }
    }
    *unmatched = 0;
    for (ShotSpec& s : *shots) {
        const std::vector<size_t>& rows = index.rowsOf(s.file);
        if (rows.empty()) {
            ++*unmatched;
            continue;
        }
        const ShotSpec* m = &metadata.shots[rows.front()];
        if (s.time.empty()) s.time = m->time;
        if (s.beam.empty()) s.beam = m->beam;
        if (s.camera.empty()) s.camera = m->camera;
        if (!s.hasCenter && m->hasCenter) {
            s.hasCenter = true;
            s.centerX = m->centerX;
            s.centerY = m->centerY;
        }
    }
    return true;
}

}  // namespace lwb::core::footprint
