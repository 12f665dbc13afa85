#pragma once
// Shot lists and frame metadata: the CSV tables that say which frames make up a footprint run
// and what each shot is (its time, beam and camera, optionally the nominal spot centre). The
// workbench's shot list and `laserwb-cli footprint` read them here, so both take the same
// files with the same messages.
//
// A shot list is a CSV (core/common/csv: RFC 4180, '#' comment lines) with a header holding a
// `file` column and optionally `time`, `beam`, `camera`, `center_x`, `center_y`; one row per
// shot (a two-beam frame is listed twice, each row with its beam and centre). A relative
// `file` is relative to the list's folder. `time` is anything the trend reads (ISO 8601 date or
// date-time, YYYY-MM, Unix seconds) and is checked here, so that a bad time is reported at its
// line before any frame is processed.
#include <map>
#include <string>
#include <vector>

namespace lwb::core::footprint {

/// One shot to process: a frame and what is known about it.
struct ShotSpec {
    std::string file;                 ///< the frame (a shot list's relative path resolved)
    std::string time, beam, camera;   ///< empty when unknown
    bool hasCenter = false;           ///< a nominal spot centre for this shot (full-image px)
    double centerX = 0, centerY = 0;
    std::string source;               ///< the shot list it came from ("" for a frame or folder given)
    long line = 0;                    ///< its line there
};

struct ShotListResult {
    bool ok = false;
    std::string error;                ///< "FILE:LINE: what is wrong"
    std::vector<ShotSpec> shots;      ///< in the list's order
};

/// True when `path` names a shot list rather than a frame: a regular file ending in .csv (any case).
bool isShotListFile(const std::string& path);

/// Reads a shot list (see above). Refuses a list without a `file` column, an empty file cell,
/// a time the trend cannot read, a centre with one coordinate or a non-number, with FILE:LINE.
ShotListResult readShotList(const std::string& path);

/// Expands frames, folders (their frames, sorted by name) and shot lists into shots, in the
/// order given. False with *error (the first problem) when a path is missing or a list is bad.
bool expandShots(const std::vector<std::string>& inputs, std::vector<ShotSpec>* out, std::string* error,
                 bool keepMissing = false);

/// Rows of a table found by the frame they name: by its path (absolute, symlink-free), else by
/// its file name when every row of that name names one path (frame metadata, verdict tables).
class FrameIndex {
public:
    /// Adds row `row` for the frame `file` (as the table resolves it).
    void add(const std::string& file, size_t row);
    /// The rows of the frame at `file`'s path alone (empty if none).
    const std::vector<size_t>& atPath(const std::string& file) const;
    /// The rows of the frame `file`: those of its path, else those of its name (above).
    const std::vector<size_t>& rowsOf(const std::string& file) const;

private:
    std::map<std::string, std::vector<size_t>> m_byPath;
    std::map<std::string, std::vector<std::string>> m_pathsByName;
};

/// Frame metadata: a table in the shot-list format (file, time, beam, camera, center_x,
/// center_y) that annotates shots chosen otherwise (folders, --files-from, shards). A shot takes
/// the time, beam, camera and centre of its frame's row where it has none of its own; its frame
/// is found by path (the table's file resolved against its folder, both made absolute) or, when
/// that finds nothing, by file name if exactly one row has that name. A frame listed twice by
/// path (two beams) is ambiguous here: list such frames as a shot list instead. *unmatched
/// counts the shots no row describes.
bool applyFrameMetadata(const ShotListResult& metadata, std::vector<ShotSpec>* shots, size_t* unmatched,
                        std::string* error);

}  // namespace lwb::core::footprint
